//! Lesson 7: with order=luna the water, drawn before the mirror, writes its depth over the mirror's
//! lowest strip; the mark fails there, the mirror's world is never drawn there, and a dark fringe of
//! water-over-nothing runs along the waterline. The default order has no fringe.

use glam::Vec3;
use workbook::app::headless::Capture;
use workbook::room::camera::BOOK_POSE;
use workbook::room::scene::{MIRROR_MAX, MIRROR_MIN, WATER_MAX, WATER_MIN};
use workbook_tests::flip;
use workbook_tests::geometry::{View, hit_y0_rect, hit_z0_rect};
use workbook_tests::shots::{self, STRICT};

/// The book's camera, at a size that keeps the test quick.
const VIEW: View = View::new(BOOK_POSE, 400, 225);

fn render(settings: &[&str]) -> Capture {
    shots::render("drawing-order", settings, |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.read_stencil = true;
    })
    .unwrap()
}

/// Whether the pixel sees the mirror through the water: its ray crosses the water's surface first,
/// then the mirror (computed from the scene's dimensions, not from a render).
fn through_water_onto_mirror(x: u32, y: u32) -> bool {
    let (origin, direction) = VIEW.ray(x, y);
    // The water's surface is the plane y = WATER_MIN.y: shift the ray so that plane is y = 0.
    let shifted = origin - Vec3::Y * WATER_MIN.y;
    let water = hit_y0_rect(
        shifted,
        direction,
        WATER_MIN.x..=WATER_MAX.x,
        WATER_MIN.z..=WATER_MAX.z,
    );
    let mirror = hit_z0_rect(origin, direction, MIRROR_MIN, MIRROR_MAX);
    matches!((water, mirror), (Some(w), Some(m)) if w < m)
}

fn luminance(capture: &Capture, x: u32, y: u32) -> f32 {
    let [r, g, b, _] = capture.color.get_pixel(x, y).0;
    0.2126 * r as f32 + 0.7152 * g as f32 + 0.0722 * b as f32
}

#[test]
fn order_luna_leaves_a_dark_fringe_along_the_waterline() {
    let right = render(&[]);
    let luna = render(&["order=luna"]);
    let fringe: Vec<(u32, u32)> = VIEW
        .pixels()
        .filter(|&(x, y)| {
            through_water_onto_mirror(x, y) && VIEW.inside_region(x, y, through_water_onto_mirror)
        })
        .collect();
    assert!(fringe.len() > 100, "only {} fringe pixels", fringe.len());

    let (mut right_light, mut luna_light) = (0.0, 0.0);
    for &(x, y) in &fringe {
        // The mechanism: the water's depth made the mark fail there ...
        assert_eq!(
            luna.stencil_at(x, y),
            Some(0),
            "order=luna marked ({x}, {y})"
        );
        // ... while the right order marks the whole mirror first.
        assert_eq!(
            right.stencil_at(x, y),
            Some(1),
            "the default did not mark ({x}, {y})"
        );
        right_light += luminance(&right, x, y);
        luna_light += luminance(&luna, x, y);
    }
    let n = fringe.len() as f32;
    let (right_light, luna_light) = (right_light / n, luna_light / n);
    assert!(
        luna_light < right_light - 15.0,
        "the fringe is not dark: luminance {luna_light:.0} with order=luna, {right_light:.0} by default"
    );
}

#[test]
fn the_two_orders_give_visibly_different_pictures() {
    let right = render(&[]).color;
    let luna = render(&["order=luna"]).color;
    let comparison = flip::compare(&right, &luna).unwrap();
    assert!(!comparison.passes(STRICT), "{}", comparison.summary());
}
