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
