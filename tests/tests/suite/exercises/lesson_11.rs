//! Lesson 11's exercises. 1: marks without the depth test mark the first mirror behind the crate,
//! and the reset and the level drawn after them paint the corridor over the crate. 2: mirrors that
//! reflect 80% leave each pixel 0.8^k as bright as the lesson's, k its level in the lesson's stencil.

use lessons::exercises::two_mirrors::{exercise_1, exercise_2};

use glam::Vec3;
use workbook::Lesson;
use workbook::app::headless::{self, Capture, Request};
use workbook::gpu::{linear_to_srgb, srgb_to_linear};
use workbook::room::scene::{CRATE_CENTRE, CRATE_SIZE, MIRROR_MAX, MIRROR_MIN};
use workbook_tests::geometry::{View, hit_box, hit_z0_rect};
use workbook_tests::shots;

use lessons::two_mirrors::TwoMirrors;

/// Lesson 11's camera, at a size that keeps the tests quick.
const VIEW: View = View::new(TwoMirrors::CAMERA, 400, 225);

fn lesson() -> Capture {
    shots::render("two-mirrors", &[], |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.read_stencil = true;
    })
    .unwrap()
}

fn exercise<L: Lesson>() -> Capture {
    let mut request = Request::new::<L>(&[] as &[&str]).unwrap();
    (request.width, request.height) = (VIEW.width, VIEW.height);
    request.read_stencil = true;
    headless::render::<L>(&request).unwrap()
}

/// The pixels where the crate stands in front of the first mirror: the ray enters the crate's box
/// before it meets the mirror's rectangle.
fn crate_in_front_of_mirror() -> Vec<(u32, u32)> {
    let half = Vec3::splat(CRATE_SIZE / 2.0);
    let classify = |x, y| {
        let (origin, direction) = VIEW.ray(x, y);
        let crate_hit = hit_box(origin, direction, CRATE_CENTRE - half, CRATE_CENTRE + half);
        let mirror = hit_z0_rect(origin, direction, MIRROR_MIN, MIRROR_MAX);
        matches!((crate_hit, mirror), (Some(c), Some(m)) if c < m)
    };
    let pixels: Vec<_> = VIEW
        .pixels()
        .filter(|&(x, y)| classify(x, y) && VIEW.inside_region(x, y, classify))
        .collect();
    assert!(pixels.len() > 100, "only {} pixels", pixels.len());
    pixels
}

fn difference(a: &Capture, b: &Capture, (x, y): (u32, u32)) -> u8 {
    let (p, q) = (a.color.get_pixel(x, y).0, b.color.get_pixel(x, y).0);
    (0..3).map(|c| p[c].abs_diff(q[c])).max().unwrap_or(0)
}

#[test]
fn exercise_1_marks_behind_the_crate_and_paints_over_it() {
    let solved = exercise::<exercise_1::Solution>();
    let lesson = lesson();
    let behind_crate = crate_in_front_of_mirror();
    let mut changed = 0;
    for &(x, y) in &behind_crate {
        // The lesson's mark fails behind the crate: the crate stays level 0 ...
        assert_eq!(
            lesson.stencil_at(x, y),
            Some(0),
            "the lesson marked ({x}, {y})"
        );
        // ... without the depth test the crate's pixels belong to the corridor.
        let level = solved.stencil_at(x, y).unwrap();
        assert!(level >= 1, "({x}, {y}) is still level 0");
        changed += usize::from(difference(&solved, &lesson, (x, y)) > 10);
    }
    // The reset put their depth back to the far plane, so level 1 was drawn over the crate.
    assert!(
        changed * 10 > behind_crate.len() * 9,
        "only {changed} of {} crate pixels changed",
        behind_crate.len()
    );
}

#[test]
fn exercise_2_darkens_level_k_to_0_8_to_the_k() {
    let solved = exercise::<exercise_2::Solution>();
    let lesson = lesson();
    let mut per_level = [0; 4];
    for (x, y) in VIEW.pixels() {
        let level = lesson.stencil_at(x, y).unwrap();
        per_level[usize::from(level)] += 1;
        let factor = exercise_2::REFLECTS.powi(i32::from(level));
        let (p, q) = (
            solved.color.get_pixel(x, y).0,
            lesson.color.get_pixel(x, y).0,
        );
        for c in 0..3 {
            let expected = linear_to_srgb(srgb_to_linear(q[c]) * factor);
            // One rounding to 8 bits per darkening pass, at most three passes.
            assert!(
                p[c].abs_diff(expected) <= 3,
                "({x}, {y}), level {level}: {} where {expected} was expected ({} in the lesson)",
                p[c],
                q[c]
            );
        }
        // The stencil is the lesson's: the darkening only reads it.
        assert_eq!(solved.stencil_at(x, y), Some(level));
    }
    // Every level of the corridor is on screen, so each factor was checked; and the lesson's
    // own picture is not darkened (level 1 and beyond differ from it).
    assert!(
        per_level.iter().all(|&n| n > 200),
        "pixels per level: {per_level:?}"
    );
    let darker = VIEW
        .pixels()
        .filter(|&(x, y)| lesson.stencil_at(x, y) != Some(0))
        .filter(|&pixel| difference(&solved, &lesson, pixel) > 3)
        .count();
    let deeper = per_level[1..].iter().sum::<usize>();
    assert!(darker * 2 > deeper, "{darker} of {deeper} pixels darker");
}

/// One frame at the book's size, 1280×720: no wgpu error.
fn renders_full_size<L: Lesson>() {
    let request = Request::new::<L>(&[] as &[&str]).unwrap();
    let capture = headless::render::<L>(&request).unwrap();
    assert_eq!(capture.color.dimensions(), (1280, 720));
}

#[test]
fn the_exercises_render_at_1280x720() {
    renders_full_size::<exercise_1::Solution>();
    renders_full_size::<exercise_2::Solution>();
}
