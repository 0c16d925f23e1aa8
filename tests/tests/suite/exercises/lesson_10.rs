//! Lesson 10's exercises. 1: without the depth test the skull's shadow darkens the crate, by exactly
//! half, once. 2: the crate's own shadow halves the floor where the crate blocks the key light (a ray
//! cast from the floor towards the light), once, though the flattened cube lies there in two layers.

use lessons::exercises::planar_shadow::{exercise_1, exercise_2};

use glam::Vec3;
use workbook::Lesson;
use workbook::app::headless::{self, Capture, Request};
use workbook::gpu::{linear_to_srgb, srgb_to_linear};
use workbook::math::shadow::LightSource;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, LIGHTS, SKULL_CENTRE, SKULL_SIZE, WALL_HALF_WIDTH,
};
use workbook_tests::geometry::{View, hit_box, hit_y0_rect, passes_near};
use workbook_tests::shots;

use lessons::planar_shadow::PlanarShadow;

/// Lesson 10's camera, at a size that keeps the tests quick.
const VIEW: View = View::new(PlanarShadow::CAMERA, 400, 225);

fn lesson() -> Capture {
    shots::render("planar-shadow", &[], |request| {
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

fn hit_crate(origin: Vec3, direction: Vec3) -> Option<f32> {
    let half = Vec3::splat(CRATE_SIZE / 2.0);
    hit_box(origin, direction, CRATE_CENTRE - half, CRATE_CENTRE + half)
}

/// Whether `picture` is `reference` under one layer of the shadow, black at 50%: every channel half
/// as bright in linear light (±2 in the stored sRGB values).
fn halved(picture: &Capture, reference: &Capture, (x, y): (u32, u32)) -> bool {
    let (p, q) = (
        picture.color.get_pixel(x, y).0,
        reference.color.get_pixel(x, y).0,
    );
    (0..3).all(|c| {
        let expected = linear_to_srgb(srgb_to_linear(q[c]) * 0.5);
        p[c].abs_diff(expected) <= 2
    })
}

/// The pixels where the ray enters the crate's box before anything else (the skull aside).
fn crate_pixels() -> Vec<(u32, u32)> {
    let classify = |x, y| {
        let (origin, direction) = VIEW.ray(x, y);
        let skull = passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.6);
        !skull && hit_crate(origin, direction).is_some()
    };
    VIEW.pixels()
        .filter(|&(x, y)| classify(x, y) && VIEW.inside_region(x, y, classify))
        .collect()
}

#[test]
fn exercise_1_darkens_the_crate_once() {
    let solved = exercise::<exercise_1::Solution>();
    let lesson = lesson();
    let on_crate = crate_pixels();
    assert!(
        on_crate.len() > 1000,
        "only {} crate pixels",
        on_crate.len()
    );
    // The lesson's depth test keeps the shadow off the crate: no crate pixel's stencil was set.
    for &(x, y) in &on_crate {
        assert_eq!(
            lesson.stencil_at(x, y),
            Some(0),
            "the lesson's shadow at ({x}, {y})"
        );
    }
    // Without it, the flattened skull lies on the crate where it is behind it on screen ...
    let shadowed: Vec<_> = on_crate
        .iter()
        .filter(|&&(x, y)| solved.stencil_at(x, y) == Some(1))
        .collect();
    assert!(
        shadowed.len() > 100,
        "the shadow covers {} crate pixels",
        shadowed.len()
    );
    // ... and darkens each of those pixels by exactly one layer: NO_DOUBLE_BLEND still works.
    for &&pixel in &shadowed {
        assert!(halved(&solved, &lesson, pixel), "{pixel:?} is not halved");
    }
}

/// The floor's pixels in the crate's shadow: the ray meets the floor first, and from there a ray
/// towards the key light (Luna's directional light) enters the crate's box.
fn in_crate_shadow() -> Vec<(u32, u32)> {
    let LightSource::Directional { direction: light } = LIGHTS[0].source else {
        panic!("the default key light is directional");
    };
    let width = WALL_HALF_WIDTH;
    let classify = |x, y| {
        let (origin, direction) = VIEW.ray(x, y);
        let floor = hit_y0_rect(origin, direction, -width..=width, 0.0..=12.0);
        let blocked = hit_crate(origin, direction).is_some()
            || passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.6);
        match floor {
            Some(t) if !blocked => hit_crate(origin + direction * t, -light).is_some(),
            _ => false,
        }
    };
    VIEW.pixels()
        .filter(|&(x, y)| classify(x, y) && VIEW.inside_region(x, y, classify))
        .collect()
}

#[test]
fn exercise_2_halves_the_floor_in_the_crates_shadow_once() {
    let solved = exercise::<exercise_2::Solution>();
    let lesson = lesson();
    let shadow = in_crate_shadow();
    assert!(shadow.len() > 100, "only {} pixels", shadow.len());
    let mut fresh = 0;
    for &(x, y) in &shadow {
        match lesson.stencil_at(x, y) {
            // The lesson draws no shadow there (its stencil is 0). The crate's shadow halves the
            // floor: once, though the flattened cube lies there in two layers (the faces where the
            // light's ray enters the crate and where it leaves it, both drawn).
            Some(0) => {
                assert!(halved(&solved, &lesson, (x, y)), "({x}, {y}) is not halved");
                assert_eq!(solved.stencil_at(x, y), Some(1), "({x}, {y})");
                fresh += 1;
            }
            // The skull's shadow is there already: the crate's does not darken it again. (From
            // the lesson's camera the two overlap only under the crate, out of sight.)
            _ => assert_eq!(solved.color.get_pixel(x, y), lesson.color.get_pixel(x, y)),
        }
    }
    assert!(fresh > 100, "{fresh} pixels of the crate's shadow alone");
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
