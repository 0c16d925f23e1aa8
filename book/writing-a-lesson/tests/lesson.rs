//! The lesson of the page "Writing a lesson", checked two ways: it draws the right picture, and its
//! knob the wrong one, by what the pictures must show; and the page's listings are the crate, line
//! for line, so that a reader who types them in has this lesson.

use std::path::{Path, PathBuf};

use my_lesson::MyLesson;
use workbook::app::headless::{self, Capture, Request};
use workbook::app::testing::run;
use workbook::glam::Vec3;
use workbook::room::scene::{SKULL_CENTRE, SKULL_SIZE};
use workbook::{Lesson, Show};

const EXE: &str = env!("CARGO_BIN_EXE_my-lesson");

/// The size the tests render at: a quarter of the pixels of a screenshot, the same picture.
const SIZE: (u32, u32) = (640, 360);

/// The lesson's frame at `SIZE` with these knob settings: its colours, and its stencil buffer read
/// back.
fn render(settings: &[&str]) -> Capture {
    let request = Request {
        width: SIZE.0,
        height: SIZE.1,
        show: Show::Color,
        read_stencil: true,
        ..Request::new::<MyLesson>(settings).unwrap()
    };
    headless::render::<MyLesson>(&request).unwrap()
}

/// Where a point of the room lands on the picture, in pixels from the top left, seen by the
/// lesson's camera.
fn pixel_of(point: Vec3) -> (f32, f32) {
    let (width, height) = (SIZE.0 as f32, SIZE.1 as f32);
    let ndc = MyLesson::CAMERA
        .view_projection(width / height)
        .project_point3(point);
    ((ndc.x + 1.0) / 2.0 * width, (1.0 - ndc.y) / 2.0 * height)
}

/// The pixels where the stencil buffer holds `value`.
fn pixels_holding(capture: &Capture, value: u8) -> Vec<(u32, u32)> {
    let (width, height) = SIZE;
    (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .filter(|&(x, y)| capture.stencil_at(x, y) == Some(value))
        .collect()
}

// ANCHOR: mark
/// The right picture marks the skull: 1 at the pixel of its centre, and only inside the rectangle
/// its bounding box covers on the picture (the mesh fits a cube of side SKULL_SIZE around
/// SKULL_CENTRE, turned: a cube of side SKULL_SIZE·√3 holds it however it is turned). The wrong
/// one, `mark-depth=less`, marks nothing: every fragment meets its own depth. The mark writes no
/// colour, so both have the same colours.
#[test]
fn the_mark_is_the_skull_and_less_leaves_it_empty() {
    let right = render(&[]);
    let (x, y) = pixel_of(SKULL_CENTRE);
    assert_eq!(
        right.stencil_at(x as u32, y as u32),
        Some(1),
        "at ({x}, {y})"
    );

    let half = SKULL_SIZE * 3f32.sqrt() / 2.0;
    let corners = (0..8).map(|i| {
        let sign = |bit: i32| if i & bit == 0 { -1.0 } else { 1.0 };
        pixel_of(SKULL_CENTRE + half * Vec3::new(sign(1), sign(2), sign(4)))
    });
    let (mut low, mut high) = ((f32::MAX, f32::MAX), (f32::MIN, f32::MIN));
    for (x, y) in corners {
        (low, high) = ((low.0.min(x), low.1.min(y)), (high.0.max(x), high.1.max(y)));
    }
    let marked = pixels_holding(&right, 1);
    let outside = marked.iter().find(|&&(x, y)| {
        let (x, y) = (x as f32 + 0.5, y as f32 + 0.5);
        x < low.0 || x > high.0 || y < low.1 || y > high.1
    });
    assert_eq!(
        outside, None,
        "marked outside the skull's box {low:?}..{high:?}"
    );
    let all = (SIZE.0 * SIZE.1) as usize;
    assert!(
        marked.len() > all / 50,
        "{} of {all} pixels marked",
        marked.len()
    );
    assert_eq!(pixels_holding(&right, 0).len() + marked.len(), all);

    let wrong = render(&["mark-depth=less"]);
    assert_eq!(
        pixels_holding(&wrong, 0).len(),
        all,
        "less marked something"
    );
    assert!(right.color == wrong.color, "the mark changed the colours");
}
// ANCHOR_END: mark

/// The program as the page runs it: its knob, its three steps, and a screenshot of the stencil
/// buffer that is white (1) at the skull's centre with the right value and dark (0) with the wrong.
#[test]
fn the_binary_lists_its_knob_and_steps_and_shows_the_mark() {
    let listed = run(Path::new(EXE), &["--list-knobs"]);
    listed.assert_clean_success();
    assert!(
        listed.stdout.starts_with("[1] mark-depth: "),
        "{}",
        listed.stdout
    );
    assert!(
        listed
            .stdout
            .contains("values: less-equal, less (default less-equal)")
    );

    let steps = run(Path::new(EXE), &["--list-steps"]);
    steps.assert_clean_success();
    assert_eq!(
        steps.stdout,
        "1. clear\n2. draw the room\n3. mark the skull\n"
    );
    // The page shows both as the program prints them.
    let (_, page) = page();
    for printed in [&listed.stdout, &steps.stdout] {
        let block = format!("```text\n{printed}```");
        assert!(page.contains(&block), "the page does not show\n{printed}");
    }

    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("my-lesson");
    std::fs::create_dir_all(&dir).unwrap();
    let (x, y) = pixel_of(SKULL_CENTRE);
    for (settings, expected) in [("mark-depth=less-equal", 255), ("mark-depth=less", 0)] {
        let shot = dir.join(format!("{settings}.png"));
        let _ = std::fs::remove_file(&shot);
        let shot_arg = shot.to_str().unwrap();
        let arguments = [
            "--size",
            "640x360",
            "--set",
            settings,
            "--screenshot",
            shot_arg,
        ];
        run(Path::new(EXE), &arguments).assert_clean_success();
        let image = image::open(&shot).unwrap().to_rgba8();
        assert_eq!(image.dimensions(), SIZE);
        let red = image.get_pixel(x as u32, y as u32).0[0];
        assert!(
            red.abs_diff(expected) < 64,
            "{settings}: red {red} at ({x}, {y})"
        );
    }
}

/// `--pixel` at the skull's centre (the page's pixel): the second drawing's fragment has exactly the
/// depth the first stored, and `LessEqual` passes it where `Less` fails it.
#[test]
fn a_pixel_of_the_skull_meets_its_own_depth() {
    let (x, y) = pixel_of(SKULL_CENTRE);
    let pixel = format!("{},{}", x as u32, y as u32);
    let (_, page) = page();
    assert!(
        page.contains(&format!("--pixel {pixel}\n")),
        "the page's --pixel is not {pixel}"
    );
    for (settings, compare, verdict) in [
        ("mark-depth=less-equal", "LessEqual", "pass"),
        ("mark-depth=less", "Less", "fail"),
    ] {
        let told = run(
            Path::new(EXE),
            &["--size", "640x360", "--set", settings, "--pixel", &pixel],
        );
        told.assert_clean_success();
        let mark = told
            .stdout
            .split(" mark the skull ")
            .nth(1)
            .expect("the step");
        let test = mark
            .lines()
            .map(str::trim)
            .find(|line| line.starts_with("depth test "))
            .unwrap_or_else(|| panic!("{settings}: no depth test in\n{}", told.stdout));
        let words: Vec<&str> = test.split_whitespace().collect();
        assert!(
            matches!(words[..], ["depth", "test", a, c, b, "→", v] if a == b && c == compare && v == verdict),
            "{settings}: `{test}`"
        );
    }
}

/// The crate's folder, and the page beside it in the book.
fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn page() -> (PathBuf, String) {
    let path = crate_dir().join("../src/writing-a-lesson.md");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (path, text)
}

/// The anchor a line opens or closes (`// ANCHOR: name`, `# ANCHOR_END: name`), as mdBook reads it.
fn marker<'a>(line: &'a str, kind: &str) -> Option<&'a str> {
    let (_, rest) = line.split_once(kind)?;
    let name = rest.trim_start();
    let end = name
        .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == '-'))
        .unwrap_or(name.len());
    Some(&name[..end]).filter(|name| !name.is_empty())
}

fn is_marker(line: &str) -> bool {
    marker(line, "ANCHOR:").is_some() || marker(line, "ANCHOR_END:").is_some()
}

/// What `{{#include file:anchor}}` shows: the lines between the anchor's markers, other markers left
/// out; the whole file without an anchor.
fn listing(text: &str, anchor: Option<&str>) -> Result<Vec<String>, String> {
    let Some(anchor) = anchor else {
        return Ok(text.lines().map(String::from).collect());
    };
    let lines: Vec<&str> = text.lines().collect();
    let start = lines
        .iter()
        .position(|line| marker(line, "ANCHOR:") == Some(anchor))
        .ok_or_else(|| format!("anchor `{anchor}` is missing"))?;
    let end = lines[start..]
        .iter()
        .position(|line| marker(line, "ANCHOR_END:") == Some(anchor))
        .ok_or_else(|| format!("ANCHOR_END: {anchor} is missing"))?;
    Ok(lines[start + 1..start + end]
        .iter()
        .filter(|line| !is_marker(line))
        .map(|line| line.to_string())
        .collect())
}

/// The lines of `file` that the page's listings must show, in order: every line but the anchor
/// markers, and but the blank lines between two anchors (the page's prose stands there). A line
/// outside every anchor that is not blank is a problem: no listing can show it.
fn lines_to_show(text: &str, problems: &mut Vec<String>, file: &str) -> Vec<(usize, String)> {
    let mut open: Vec<&str> = Vec::new();
    let mut shown = Vec::new();
    for (number, line) in text.lines().enumerate().map(|(n, l)| (n + 1, l)) {
        if let Some(name) = marker(line, "ANCHOR:") {
            open.push(name);
        } else if let Some(name) = marker(line, "ANCHOR_END:") {
            open.retain(|open| *open != name);
        } else if !open.is_empty() {
            shown.push((number, line.to_string()));
        } else if !line.trim().is_empty() {
            problems.push(format!(
                "{file}:{number} is in no anchor, so in no listing: `{line}`"
            ));
        }
    }
    shown
}

/// "The page is the crate": the page's `{{#include}}`s of this crate's files, in the page's order,
/// give every line of `src/lib.rs` once and in order (its anchor markers aside), and `src/main.rs`
/// and `Cargo.toml` whole.
#[test]
fn the_page_is_the_crate() {
    let (page_path, page) = page();
    let book_src = page_path.parent().unwrap().to_path_buf();
    let files = ["Cargo.toml", "src/main.rs", "src/lib.rs"];
    let mut listed: Vec<Vec<String>> = vec![Vec::new(); files.len()];
    let mut problems = Vec::new();
    for (number, line) in page.lines().enumerate().map(|(n, l)| (n + 1, l)) {
        let Some(directive) = line
            .trim()
            .strip_prefix("{{#include ")
            .and_then(|rest| rest.strip_suffix("}}"))
        else {
            continue;
        };
        let (path, anchor) = match directive.trim().split_once(':') {
            Some((path, anchor)) => (path, Some(anchor)),
            None => (directive.trim(), None),
        };
        let Ok(target) = book_src.join(path).canonicalize() else {
            continue;
        };
        let Some(index) = files
            .iter()
            .position(|file| crate_dir().join(file).canonicalize().ok() == Some(target.clone()))
        else {
            continue;
        };
        let text = std::fs::read_to_string(&target).unwrap();
        match listing(&text, anchor) {
            Ok(lines) => listed[index].extend(lines),
            Err(problem) => problems.push(format!(
                "writing-a-lesson.md:{number}: {}: {problem}",
                files[index]
            )),
        }
    }
    for (file, listed) in files.iter().zip(&listed) {
        let text = std::fs::read_to_string(crate_dir().join(file)).unwrap();
        let expected: Vec<(usize, String)> = match *file {
            "src/lib.rs" => lines_to_show(&text, &mut problems, file),
            _ => (1..).zip(text.lines().map(String::from)).collect(),
        };
        let first_difference = expected
            .iter()
            .zip(listed)
            .position(|((_, wanted), got)| wanted != got);
        match first_difference {
            Some(at) => problems.push(format!(
                "{file}:{}: `{}` is not where the page's listings have it; they have `{}` there \
                 (a listing left out, or out of order)",
                expected[at].0, expected[at].1, listed[at]
            )),
            None if listed.len() < expected.len() => {
                let (number, line) = &expected[listed.len()];
                problems.push(format!(
                    "{file}:{number}: `{line}` and the {} lines after it are in none of the \
                     page's listings",
                    expected.len() - listed.len() - 1
                ));
            }
            None if listed.len() > expected.len() => problems.push(format!(
                "{file}: the page's listings show {} lines more than the file has (a listing \
                 shown twice?)",
                listed.len() - expected.len()
            )),
            None => {}
        }
    }
    assert!(problems.is_empty(), "\n{}", problems.join("\n"));
}

/// The page is in the book's table of contents.
#[test]
fn the_page_is_in_the_book() {
    let summary = std::fs::read_to_string(crate_dir().join("../src/SUMMARY.md")).unwrap();
    assert!(
        summary.contains("(writing-a-lesson.md)"),
        "SUMMARY.md does not list the page"
    );
}
