//! Lesson 7's exercises. 1: Luna's order with transparent objects that do not write depth marks the
//! mirror behind the water (no fringe), and the reflection then covers the water there. 2: opaque
//! first, transparent last leaves the crate's pixels unmarked and gives the default order's picture.

use lessons::exercises::drawing_order::{exercise_1, exercise_2};

use glam::Vec3;
use workbook::Lesson;
use workbook::app::headless::{self, Capture, Request};
use workbook::room::camera::BOOK_POSE;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, MIRROR_MAX, MIRROR_MIN, SKULL_CENTRE, SKULL_SIZE, WATER_MAX,
    WATER_MIN,
};
use workbook_tests::flip;
use workbook_tests::geometry::{View, hit_box, hit_y0_rect, hit_z0_rect, passes_near};
use workbook_tests::shots::{self, STRICT};

/// The book's camera, at a size that keeps the tests quick.
const VIEW: View = View::new(BOOK_POSE, 400, 225);

fn lesson(settings: &[&str], stop: Option<&str>) -> Capture {
    let stop = stop.map(|step| shots::after_step("drawing-order", settings, step).unwrap());
    shots::render("drawing-order", settings, |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.read_stencil = true;
        request.stop = stop.unwrap_or_default();
    })
    .unwrap()
}

fn exercise<L: Lesson>() -> Capture {
    let mut request = Request::new::<L>(&[] as &[&str]).unwrap();
    (request.width, request.height) = (VIEW.width, VIEW.height);
    request.read_stencil = true;
    headless::render::<L>(&request).unwrap()
}

/// The pixels whose ray crosses the water's surface and then the mirror (from the scene's
/// dimensions alone), away from the region's edges and clear of the skull, which stands in front of
/// the mirror there too, and of the crate.
fn through_water_onto_mirror() -> Vec<(u32, u32)> {
    let classify = |x, y| {
        let (origin, direction) = VIEW.ray(x, y);
        let shifted = origin - Vec3::Y * WATER_MIN.y;
        let water = hit_y0_rect(
            shifted,
            direction,
            WATER_MIN.x..=WATER_MAX.x,
            WATER_MIN.z..=WATER_MAX.z,
        );
        let mirror = hit_z0_rect(origin, direction, MIRROR_MIN, MIRROR_MAX);
        let skull = passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.6);
        let crate_hit = hit_crate(origin, direction).is_some();
        !skull && !crate_hit && matches!((water, mirror), (Some(w), Some(m)) if w < m)
    };
    let pixels: Vec<_> = VIEW
        .pixels()
        .filter(|&(x, y)| classify(x, y) && VIEW.inside_region(x, y, classify))
        .collect();
    assert!(pixels.len() > 100, "only {} pixels", pixels.len());
    pixels
}

/// The pixels where the crate stands in front of the mirror: the ray enters the crate's box before
/// it meets the mirror's rectangle.
fn crate_in_front_of_mirror() -> Vec<(u32, u32)> {
    let classify = |x, y| {
        let (origin, direction) = VIEW.ray(x, y);
        let crate_hit = hit_crate(origin, direction);
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

/// Where the ray enters the crate's box, if it does.
fn hit_crate(origin: Vec3, direction: Vec3) -> Option<f32> {
    let half = Vec3::splat(CRATE_SIZE / 2.0);
    hit_box(origin, direction, CRATE_CENTRE - half, CRATE_CENTRE + half)
}

/// The largest difference of any channel between two pictures at these pixels.
fn largest_difference(a: &Capture, b: &Capture, pixels: &[(u32, u32)]) -> u8 {
    let mut largest = 0;
    for &(x, y) in pixels {
        let (p, q) = (a.color.get_pixel(x, y).0, b.color.get_pixel(x, y).0);
        for channel in 0..3 {
            largest = largest.max(p[channel].abs_diff(q[channel]));
        }
    }
    largest
}

#[test]
fn exercise_1_marks_the_mirror_behind_the_water_and_loses_the_water_there() {
    let solved = exercise::<exercise_1::Solution>();
    let luna = lesson(&["order=luna"], None);
    let fringe = through_water_onto_mirror();
    for &(x, y) in &fringe {
        // The water no longer hides the mirror from its mark ...
        assert_eq!(solved.stencil_at(x, y), Some(1), "not marked at ({x}, {y})");
        // ... where the lesson's Luna order leaves it unmarked: the fringe.
        assert_eq!(
            luna.stencil_at(x, y),
            Some(0),
            "order=luna marked ({x}, {y})"
        );
    }
    // What the fringe shows now is the mirror alone, as the default order has it before the room's
    // water is blended over it: the reflection, drawn after the water, covered it.
    let mirror_alone = lesson(&[], Some("draw the glass"));
    let finished = lesson(&[], None);
    let covered = largest_difference(&solved, &mirror_alone, &fringe);
    assert!(
        covered <= 2,
        "the fringe differs from the mirror alone by {covered}"
    );
    // The default order's finished picture has the water over the mirror there.
    let water = largest_difference(&finished, &mirror_alone, &fringe);
    assert!(water > 20, "the water changes the fringe by only {water}");
}

#[test]
fn exercise_2_leaves_the_crate_unmarked_and_gives_the_default_picture() {
    let solved = exercise::<exercise_2::Solution>();
    let default = lesson(&[], None);
    for &(x, y) in &crate_in_front_of_mirror() {
        // The crate's depth was there before the mark: it fails behind the crate ...
        assert_eq!(
            solved.stencil_at(x, y),
            Some(0),
            "marked behind the crate at ({x}, {y})"
        );
        // ... where the default order, marking first, marks the whole mirror.
        assert_eq!(
            default.stencil_at(x, y),
            Some(1),
            "the default did not mark ({x}, {y})"
        );
    }
    for &(x, y) in &through_water_onto_mirror() {
        assert_eq!(solved.stencil_at(x, y), Some(1), "not marked at ({x}, {y})");
    }
    // The two orders give one picture.
    let comparison = flip::compare(&default.color, &solved.color).unwrap();
    assert!(comparison.passes(STRICT), "{}", comparison.summary());
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
