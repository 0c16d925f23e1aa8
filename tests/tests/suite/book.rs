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
