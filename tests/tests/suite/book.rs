//! The book's sources: every include resolves to a real anchor, every image exists and comes from the
//! catalogue, and every catalogued screenshot is shown somewhere.

#[test]
fn every_include_and_image_of_the_book_resolves() {
    let src = workbook_tests::workspace().join("book/src");
    let problems = workbook_tests::book::problems(&src);
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

#[test]
fn every_screenshot_is_shown_in_the_book() {
    let src = workbook_tests::workspace().join("book/src");
    let mut pages = String::new();
    for entry in std::fs::read_dir(&src).unwrap().flatten() {
        if entry.path().extension().is_some_and(|e| e == "md") {
            pages += &std::fs::read_to_string(entry.path()).unwrap();
        }
    }
    for shot in workbook_tests::shots::SHOTS {
        assert!(
            pages.contains(&format!("images/{}.png", shot.name)),
            "{} is in the catalogue but no page shows it",
            shot.name
        );
    }
}

fn page(name: &str) -> String {
    let path = workbook_tests::workspace().join("book/src").join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Every lesson page shows its frame step by step: the section and the strip of its own steps.
#[test]
fn every_lesson_page_shows_its_step_strip() {
    for lesson in workbook_tests::shots::LESSONS {
        let text = page(&format!("{lesson}.md"));
        assert!(
            text.contains("## The frame, step by step"),
            "{lesson}.md has no section \"The frame, step by step\""
        );
        let include = format!("{{{{#include images/steps/{lesson}/strip.html}}}}");
        assert!(
            text.contains(&include),
            "{lesson}.md does not include its strip"
        );
    }
}

/// Every lesson page can run its lesson: the web edition's block (book/web/live.js makes it a "Run"
/// bar) stands right above the page's first figure, and names the page's own lesson.
#[test]
fn every_lesson_page_runs_its_lesson_above_its_first_figure() {
    for lesson in workbook_tests::shots::LESSONS {
        let text = page(&format!("{lesson}.md"));
        let block = format!("<div class=\"live\" data-lesson=\"{lesson}\"></div>");
        let at = text
            .find(&block)
            .unwrap_or_else(|| panic!("{lesson}.md has no `{block}`"));
        let figure = text.find("![").expect("a lesson page has figures");
        assert!(
            at < figure && text[at + block.len()..figure].trim().is_empty(),
            "{lesson}.md: the live block must stand right above the first figure"
        );
    }
}

/// Wherever a wrong picture is shown — its lesson's page and the gallery — its enlarged crop and
/// the difference image are shown too.
#[test]
fn every_wrong_picture_comes_with_its_crop_and_difference() {
    let src = workbook_tests::workspace().join("book/src");
    for entry in std::fs::read_dir(&src).unwrap().flatten() {
        let path = entry.path();
        if path.extension().is_none_or(|e| e != "md") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        for pair in workbook_tests::shots::PAIRS {
            if !text.contains(&format!("images/{}.png", pair.wrong)) {
                continue;
            }
            for name in [pair.zoom_name(), pair.difference_name()] {
                assert!(
                    text.contains(&format!("images/{name}.png")),
                    "{} shows {} without {name}",
                    path.display(),
                    pair.wrong
                );
            }
        }
    }
    let gallery = page("gallery.md");
    for pair in workbook_tests::shots::PAIRS {
        assert!(
            gallery.contains(&format!("images/{}.png", pair.wrong)),
            "{}",
            pair.wrong
        );
    }
}

/// Every lesson page has, before its first `##` section, exactly one block of speaker notes whose
/// summary gives the minutes the lesson takes to teach: between 15 and 35.
#[test]
fn every_lesson_page_has_speaker_notes_with_minutes() {
    let mut problems = Vec::new();
    for lesson in workbook_tests::shots::LESSONS {
        let text = page(&format!("{lesson}.md"));
        let minutes = workbook_tests::book::speaker_minutes(&text);
        match minutes.as_slice() {
            [Ok(minutes)] if (15..=35).contains(minutes) => {}
            [Ok(minutes)] => problems.push(format!("{lesson}.md: {minutes} minutes, not 15 to 35")),
            [Err(problem)] => problems.push(format!("{lesson}.md: {problem}")),
            more => problems.push(format!(
                "{lesson}.md has {} speaker-notes summaries, not one",
                more.len()
            )),
        }
        let intro = &workbook_tests::book::sections(&text)[..2];
        let in_intro = intro
            .iter()
            .flat_map(|s| &s.lines)
            .any(|line| line.contains("<details class=\"speaker-notes\"><summary>Speaker notes"));
        if !in_intro {
            problems.push(format!(
                "{lesson}.md: the speaker notes (`<details class=\"speaker-notes\"><summary>...`) are \
                 not in the introduction, before the first `##`"
            ));
        }
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

/// Every lesson page asks at least two "Predict the picture" questions. Each answer shows a picture of
/// the screenshot catalogue, of the same lesson, and the question's command line has exactly that
/// picture's settings (the order of the options aside, `--size` and `--screenshot` left out).
#[test]
fn every_lesson_page_asks_predictions_its_pictures_answer() {
    let images = workbook_tests::images();
    let mut problems = Vec::new();
    for lesson in workbook_tests::shots::LESSONS {
        let text = page(&format!("{lesson}.md"));
        let predictions = workbook_tests::book::predictions(&text);
        if predictions.len() < 2 {
            problems.push(format!(
                "{lesson}.md: {} questions in `## Predict the picture`, fewer than 2",
                predictions.len()
            ));
        }
        for (number, prediction) in predictions.iter().enumerate() {
            let at = format!("{lesson}.md, question {}", number + 1);
            let Some(image) = &prediction.image else {
                problems.push(format!("{at}: the answer shows no picture"));
                continue;
            };
            let name = image
                .strip_prefix("images/")
                .and_then(|n| n.strip_suffix(".png"));
            let shot = name.and_then(|n| workbook_tests::shots::Shot::named(n).ok());
            let Some(shot) = shot else {
                problems.push(format!(
                    "{at}: {image} is not a screenshot of the catalogue"
                ));
                continue;
            };
            if !images.join(format!("{}.png", shot.name)).exists() {
                problems.push(format!("{at}: {image} does not exist"));
            }
            let asked = workbook_tests::book::command_options(&prediction.command);
            let shown = workbook_tests::book::shot_options(shot);
            match (asked, shown) {
                (Ok(asked), Ok(shown)) if asked == shown && asked.0 == *lesson => {}
                (Ok(asked), Ok(shown)) => problems.push(format!(
                    "{at}: `{}` asks {asked:?} but {} shows {shown:?} (run `cargo run -p ...` with \
                     the shot's settings, or pick another picture)",
                    prediction.command, shot.name
                )),
                (Err(problem), _) | (_, Err(problem)) => problems.push(format!("{at}: {problem}")),
            }
        }
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

/// Every lesson page has an `## Exercises` section with at least two `### Exercise K` headings, each
/// followed (before the next heading) by the include of its solution,
/// `.../chapters/NN-<lesson>/examples/exercise-N-K.rs:solution` (N the lesson's number: example
/// names are unique in the workspace, since cargo puts every example binary in one folder). (That the include resolves is
/// checked by `every_include_and_image_of_the_book_resolves`.)
#[test]
fn every_lesson_page_has_exercises_with_their_solutions() {
    let mut problems = Vec::new();
    for (index, lesson) in workbook_tests::shots::LESSONS.iter().enumerate() {
        let text = page(&format!("{lesson}.md"));
        let exercises = workbook_tests::book::exercises(&text);
        if exercises.len() < 2 {
            problems.push(format!(
                "{lesson}.md: {} `### Exercise` headings in `## Exercises`, fewer than 2",
                exercises.len()
            ));
        }
        let chapter = format!("chapters/{:02}-{lesson}/examples/", index + 1);
        for exercise in &exercises {
            let number = exercise
                .title
                .strip_prefix("Exercise ")
                .map(|rest| {
                    rest.split(|c: char| !c.is_ascii_digit())
                        .next()
                        .unwrap_or("")
                })
                .unwrap_or("");
            let solution = format!("{chapter}exercise-{}-{number}.rs:solution", index + 1);
            let included = exercise
                .includes
                .iter()
                .any(|include| !number.is_empty() && include.ends_with(&solution));
            if !included {
                problems.push(format!(
                    "{lesson}.md: `### {}` is not followed by `{{{{#include ../../{solution}}}}}`",
                    exercise.title
                ));
            }
        }
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

/// The teaching page is in the book's table of contents, and its plan adds up: each session's total
/// is the sum of its parts and the minutes its heading names; a part that links to a lesson page
/// takes that page's speaker-notes minutes; the five classes teach every lesson once.
#[test]
fn the_teaching_plan_adds_up() {
    assert!(
        page("SUMMARY.md").contains("[Teaching with this workbook](teaching.md)"),
        "SUMMARY.md does not list teaching.md"
    );
    let sessions = workbook_tests::book::sessions(&page("teaching.md")).unwrap();
    let classes = sessions
        .iter()
        .filter(|s| s.title.starts_with("Class"))
        .count();
    let workshops = sessions
        .iter()
        .filter(|s| s.title.contains("workshop"))
        .count();
    assert_eq!((classes, workshops), (6, 1), "{sessions:#?}");
    let mut problems = Vec::new();
    let mut taught = Vec::new();
    for session in &sessions {
        let sum: u32 = session.parts.iter().map(|(_, _, minutes)| minutes).sum();
        if session.total != Some(sum) || session.minutes != Some(sum) {
            problems.push(format!(
                "{}: the parts add up to {sum} minutes, the total row says {:?}, the heading {:?}",
                session.title, session.total, session.minutes
            ));
        }
        for (part, target, minutes) in &session.parts {
            let Some(target) = target else { continue };
            let Some(lesson) = target.strip_suffix(".md") else {
                continue;
            };
            if !workbook_tests::shots::LESSONS.contains(&lesson) {
                continue;
            }
            let notes = workbook_tests::book::speaker_minutes(&page(target));
            if notes != [Ok(*minutes)] {
                problems.push(format!(
                    "{}: `{part}` takes {minutes} minutes, the page's speaker notes {notes:?}",
                    session.title
                ));
            }
            if session.title.starts_with("Class") {
                taught.push(lesson);
            }
        }
    }
    taught.sort();
    let mut every: Vec<&str> = workbook_tests::shots::LESSONS.to_vec();
    every.sort();
    if taught != every {
        problems.push(format!(
            "the classes teach {taught:?}, not every lesson once"
        ));
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

/// The book's pictures are written small (`PngSize::Small`: 8-bit RGB, zlib's best compression),
/// since they live in git: a picture written for speed, as a learner's screenshot is (RGBA), would
/// take a quarter more. Every one is opaque, so RGB: the colour type in its header is 2.
#[test]
fn the_books_pictures_are_written_small() {
    let images = workbook_tests::images();
    let mut pngs = Vec::new();
    let mut folders = vec![images];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).unwrap().flatten() {
            let path = entry.path();
            match path.extension() {
                _ if path.is_dir() => folders.push(path),
                Some(e) if e == "png" => pngs.push(path),
                _ => {}
            }
        }
    }
    let written_for_speed: Vec<_> = (pngs.iter())
        .filter(|png| {
            let header = std::fs::read(png).unwrap();
            header.get(25) != Some(&2)
        })
        .collect();
    assert!(pngs.len() > 400, "only {} pictures found", pngs.len());
    assert!(
        written_for_speed.is_empty(),
        "not written small (run `cargo screenshots` for them): {written_for_speed:?}"
    );
}
