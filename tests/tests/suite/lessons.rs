//! The one list of the lessons, chapters/lessons/Cargo.toml's `[dependencies]` (`lessons::LESSONS`,
//! which everything else reads), is the lessons there are: every folder chapters/NN-NAME is lesson
//! NN of the list, the book's table of contents has their pages in the list's order, each name runs
//! the lesson of that name, and the scripts read the same list (scripts/lessons.sh).

use workbook::Lesson;
use workbook_tests::shots::{ForLesson, LESSONS, for_lesson};

const LIST: &str = "chapters/lessons/Cargo.toml's [dependencies]";

#[test]
fn every_lesson_folder_is_in_the_list_in_its_place() {
    let chapters = workbook_tests::workspace().join("chapters");
    let mut folders: Vec<String> = std::fs::read_dir(&chapters)
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name.starts_with(|c: char| c.is_ascii_digit()))
        .collect();
    folders.sort();
    let mut problems = Vec::new();
    for folder in &folders {
        let name = folder.split_once('-').map_or("", |(_, name)| name);
        if !LESSONS.contains(&name) {
            problems.push(format!(
                "chapters/{folder} is not in the list of lessons: add \
                 `{name} = {{ path = \"../{folder}\" }}` to {LIST}, in the book's order"
            ));
        }
    }
    for (index, name) in LESSONS.iter().enumerate() {
        let folder = format!("{:02}-{name}", index + 1);
        if !folders.contains(&folder) {
            let found = folders
                .iter()
                .find(|f| f.split_once('-').is_some_and(|(_, n)| n == *name));
            problems.push(match found {
                Some(found) => format!(
                    "`{name}` is lesson {} of {LIST}, but its folder is chapters/{found}",
                    index + 1
                ),
                None => format!("{LIST} lists `{name}`, which has no folder chapters/{folder}"),
            });
        }
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

/// The table of contents lists the lesson pages as `[Lesson N: title](NAME.md)`.
#[test]
fn the_book_has_the_lessons_in_the_lists_order() {
    let path = workbook_tests::workspace().join("book/src/SUMMARY.md");
    let summary = std::fs::read_to_string(&path).unwrap();
    let pages: Vec<String> = summary
        .lines()
        .filter_map(|line| {
            let (number, rest) = line.split_once("[Lesson ")?.1.split_once(':')?;
            let page = rest.split_once("](")?.1.split_once(".md)")?.0;
            Some(format!("{number} {page}"))
        })
        .collect();
    let listed: Vec<String> = LESSONS
        .iter()
        .enumerate()
        .map(|(index, name)| format!("{} {name}", index + 1))
        .collect();
    assert_eq!(
        pages, listed,
        "book/src/SUMMARY.md's lesson pages (left, `N NAME` for `[Lesson N: ...](NAME.md)`) are \
         not the lessons of {LIST} in order (right)"
    );
}

#[test]
fn each_name_runs_the_lesson_of_that_name() {
    struct Name;
    impl ForLesson for Name {
        type Output = &'static str;
        fn run<L: Lesson>(self) -> &'static str {
            L::NAME
        }
    }
    for name in LESSONS {
        assert_eq!(for_lesson(name, Name).unwrap(), *name);
    }
    assert!(for_lesson("no-such-lesson", Name).is_err());
}

/// The scripts' list (.ci/run's wasm32 lints, scripts/window-shots.sh) is the crate's.
#[test]
fn the_scripts_read_the_same_list() {
    workbook::skip_unless_linux!("the scripts are Linux's (sh, sed)");
    let script = workbook_tests::workspace().join("scripts/lessons.sh");
    let output = match std::process::Command::new("sh").arg(&script).output() {
        Ok(output) => output,
        Err(error) if std::env::var_os("CI").is_none() => {
            eprintln!("skipped: no `sh` to run scripts/lessons.sh: {error}");
            return;
        }
        Err(error) => panic!("sh scripts/lessons.sh: {error}"),
    };
    assert!(output.status.success(), "scripts/lessons.sh: {output:?}");
    let printed = String::from_utf8(output.stdout).unwrap();
    assert_eq!(printed.lines().collect::<Vec<_>>(), LESSONS);
}
