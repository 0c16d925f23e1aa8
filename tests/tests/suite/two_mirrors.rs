//! Lesson 11, by the stencil buffer read back: the levels are nested (each depth adds pixels only
//! inside the deepest level of the one before, and holds its levels 0 to depth), the corridor grows
//! level by level, and the two ways to break it break it.

use workbook::Stop;
use workbook::app::headless::Capture;
use workbook_tests::flip;
use workbook_tests::shots::{self, STRICT};

const SIZE: (u32, u32) = (320, 180);

fn render(settings: &[&str]) -> Capture {
    shots::render("two-mirrors", settings, |request| {
        (request.width, request.height) = SIZE;
        request.read_stencil = true;
        request.stop = Stop::Last;
    })
    .unwrap()
}

#[test]
fn each_level_lies_inside_the_one_before() {
    let mut shallower = render(&["depth=0"]);
    for depth in 1..=two_mirrors::MAX_DEPTH {
        let deeper = render(&[&format!("depth={depth}")]);
        let (before, after) = (
            shallower.stencil.as_ref().unwrap(),
            deeper.stencil.as_ref().unwrap(),
        );
        let previous = depth as u8 - 1;
        assert!(
            after.iter().all(|&v| v as usize <= depth),
            "depth={depth}: a value above it"
        );
        let mut added = 0;
        for (i, (&b, &a)) in before.iter().zip(after).enumerate() {
            let (x, y) = (i as u32 % SIZE.0, i as u32 / SIZE.0);
            if a != b {
                assert!(
                    b == previous && a == previous + 1,
                    "depth={depth}: ({x}, {y}) went from {b} to {a}"
                );
                added += 1;
            }
            if deeper.color.get_pixel(x, y) != shallower.color.get_pixel(x, y) {
                assert_eq!(
                    b, previous,
                    "depth={depth}: ({x}, {y}) changed outside level {previous}"
                );
            }
        }
        // The corridor narrows, but the first levels are large: every level adds pixels up to 4.
        if depth <= 4 {
            assert!(added > 50, "depth={depth} added only {added} pixels");
        }
        shallower = deeper;
    }
    let levels = shallower.stencil.unwrap();
    for level in 0..=4u8 {
        assert!(levels.contains(&level), "no pixel holds level {level}");
    }
}

#[test]
fn replacing_instead_of_incrementing_lets_the_levels_bleed() {
    let increment = render(&[]);
    let replace = render(&["mark=replace"]);
    let comparison = flip::compare(&increment.color, &replace.color).unwrap();
    assert!(
        !comparison.passes(STRICT),
        "mark=replace: {}",
        comparison.summary()
    );
    // Replace writes level k + 1 wherever the mirror passes the depth test, inside level k or not.
    let (a, b) = (increment.stencil.unwrap(), replace.stencil.unwrap());
    assert_ne!(a, b);
}

#[test]
fn flipping_the_winding_at_every_level_turns_the_even_levels_inside_out() {
    let per_level = render(&["depth=2"]);
    let flipped = render(&["depth=2", "winding=always-flipped"]);
    let comparison = flip::compare(&per_level.color, &flipped.color).unwrap();
    assert!(
        comparison.mean > 0.0,
        "winding=always-flipped: {}",
        comparison.summary()
    );
    // Level 1 (odd) is the same either way: only level 2's pixels differ.
    let levels = per_level.stencil.unwrap();
    for (x, y, pixel) in flipped.color.enumerate_pixels() {
        if pixel != per_level.color.get_pixel(x, y) {
            assert_eq!(
                levels[(y * SIZE.0 + x) as usize],
                2,
                "({x}, {y}) outside level 2"
            );
        }
    }
}
