//! Every screenshot of the book, rendered again and compared with the committed file by FLIP.

use lessons::mark_mirror;
use workbook_tests::flip::{self, Threshold};
use workbook_tests::shots::{self, PAIRS, SHOTS, STRICT};

#[test]
fn every_screenshot_matches_its_reference() {
    let failures: Vec<String> = SHOTS
        .iter()
        .filter_map(|shot| shot.check().err().map(|e| format!("{e:#}")))
        .collect();
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

/// Every wrong picture of the book must be told apart from its right one by the limit the tests and
/// `--check` use ([`STRICT`]), rendered on this machine: otherwise a lesson that broke that way
/// would still "match the book". Prints each pair's figures.
#[test]
fn every_wrong_picture_fails_against_its_right_one() {
    let mut passing = Vec::new();
    println!("wrong picture                        against                FLIP figures");
    for pair in PAIRS {
        let comparison = pair.here().unwrap();
        println!(
            "{:36} {:22} {}",
            pair.wrong,
            pair.right,
            comparison.summary()
        );
        if comparison.passes(STRICT) {
            passing.push(format!("{}: {}", pair.wrong, comparison.summary()));
        }
    }
    assert!(
        passing.is_empty(),
        "wrong pictures that pass as their right ones:\n{}",
        passing.join("\n")
    );
}

/// A reference that was changed in one small region fails, and the failure leaves the actual and
/// difference images behind.
#[test]
fn a_changed_region_fails_and_writes_the_difference() {
    let shot = &SHOTS[0];
    let mut tampered = flip::load(&shot.path()).unwrap();
    for y in 200..230 {
        for x in 380..410 {
            tampered.put_pixel(x, y, image::Rgba([255, 0, 255, 255]));
        }
    }
    let name = "tampered-test-only";
    let dir = workbook_tests::images();
    let reference = dir.join(format!("{name}.png"));
    tampered.save(&reference).unwrap();
    let result = shots::check_image(name, &shot.render().unwrap(), STRICT);
    let actual = dir.join(format!("{name}-actual.png"));
    let difference = dir.join(format!("{name}-difference.png"));
    let written = actual.exists() && difference.exists();
    for path in [&reference, &actual, &difference] {
        let _ = std::fs::remove_file(path);
    }
    let error = result.expect_err("a 30x30 magenta patch went unnoticed");
    assert!(error.to_string().contains("difference"), "{error}");
    assert!(
        written,
        "the failure did not write -actual and -difference images"
    );
}

#[test]
fn a_missing_reference_fails_and_is_not_written() {
    let image = image::RgbaImage::new(8, 8);
    let threshold = Threshold {
        mean: 1.0,
        visible_share: 1.0,
        largest_patch: u32::MAX,
    };
    let error = shots::check_image("no-such-reference", &image, threshold).unwrap_err();
    assert!(error.to_string().contains("missing"), "{error}");
    assert!(
        !workbook_tests::images()
            .join("no-such-reference.png")
            .exists()
    );
}

/// The list the window's panel and `--check` read (`book/src/images/shots.txt`) is the catalogue's:
/// a shot added or changed without `cargo screenshots` fails here.
#[test]
fn the_books_list_of_screenshots_is_the_catalogue() {
    let path = workbook::book::shots::images().join(workbook::book::shots::LIST);
    let written = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        written == shots::list_text().unwrap(),
        "{} is out of date: run `cargo screenshots` (it rewrites the list)",
        path.display()
    );
    // And every line means what the lesson's command line means.
    for shot in workbook::book::shots::read(&workbook::book::shots::images()).unwrap() {
        shot.args().unwrap();
    }
}

/// `--check` on an unmodified lesson: every picture matches the book; with a knob that breaks it,
/// the pictures that change are named.
#[test]
fn check_says_every_picture_matches_and_names_the_one_that_differs() {
    let scene = workbook::room::scene::SceneOptions::default();
    let out = std::env::temp_dir().join(format!("workbook-check-{}", std::process::id()));
    let check = |overrides: &[&str]| {
        let overrides: Vec<String> = overrides.iter().map(|s| s.to_string()).collect();
        workbook::book::check::check::<mark_mirror::MarkMirror>(&overrides, &scene, None, &out)
    };
    check(&[]).unwrap();
    assert!(!out.exists(), "nothing differs, so nothing is written");
    let error = format!("{:#}", check(&["mark-depth-test=off"]).unwrap_err());
    // Only the default picture (the stencil buffer) and the mark's test map (no longer failing the
    // depth test behind the crate) change: the mark writes no colour, the wrong picture has the
    // knob set already, and seen from behind the wall there is no mark to change.
    assert!(
        error.ends_with(" pictures differ from the book: mark-mirror, mark-mirror-tests"),
        "{error}"
    );
    assert!(out.join("mark-mirror-difference.png").exists());
    std::fs::remove_dir_all(&out).unwrap();
}
