//! Lesson 9's exercises, against the stencil mirror (lesson 8's frame, the lesson's
//! `technique=stencil`), which at full resolution gives the texture mirror's picture. 1: without the
//! winding fix the stone shows the crate's far, inner faces: the picture leaves the stencil mirror's
//! where the crate's image is. 2: the wall mirror made a texture mirror shows what the lesson's
//! `plane=wall` shows, except where it sees the stone.

use lessons::exercises::render_to_texture::{exercise_1, exercise_2};

use glam::Vec3;
use image::RgbaImage;
use workbook::Lesson;
use workbook::app::headless::{self, Request};
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, FLOOR_MIRROR_MAX, FLOOR_MIRROR_MIN, MIRROR_MAX, MIRROR_MIN,
    SKULL_CENTRE, SKULL_SIZE,
};
use workbook_tests::flip;
use workbook_tests::geometry::{View, hit_box, hit_y0_rect, hit_z0_rect, passes_near};
use workbook_tests::shots::{self, STRICT};

use lessons::render_to_texture::RenderToTexture;

/// Lesson 9's camera, at a size that keeps the tests quick.
const VIEW: View = View::new(RenderToTexture::CAMERA, 400, 225);

fn lesson(settings: &[&str]) -> RgbaImage {
    shots::render("render-to-texture", settings, |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
    })
    .unwrap()
    .color
}

fn exercise<L: Lesson>() -> RgbaImage {
    let mut request = Request::new::<L>(&[] as &[&str]).unwrap();
    (request.width, request.height) = (VIEW.width, VIEW.height);
    headless::render::<L>(&request).unwrap().color
}

fn hit_cube(origin: Vec3, direction: Vec3, centre: Vec3, size: f32) -> Option<f32> {
    let half = Vec3::splat(size / 2.0);
    hit_box(origin, direction, centre - half, centre + half)
}

/// The pixels that pass `classify`, away from the region's edges.
fn pixels(classify: impl Fn(u32, u32) -> bool) -> Vec<(u32, u32)> {
    let pixels: Vec<_> = VIEW
        .pixels()
        .filter(|&(x, y)| classify(x, y) && VIEW.inside_region(x, y, &classify))
        .collect();
    assert!(pixels.len() > 100, "only {} pixels", pixels.len());
    pixels
}

/// The largest difference of any channel between two pictures at a pixel.
fn difference(a: &RgbaImage, b: &RgbaImage, (x, y): (u32, u32)) -> u8 {
    let (p, q) = (a.get_pixel(x, y).0, b.get_pixel(x, y).0);
    (0..3).map(|c| p[c].abs_diff(q[c])).max().unwrap_or(0)
}

/// The share of `pixels` where the two pictures differ by more than `by`.
fn share_differing(a: &RgbaImage, b: &RgbaImage, pixels: &[(u32, u32)], by: u8) -> f32 {
    let count = pixels.iter().filter(|&&p| difference(a, b, p) > by);
    count.count() as f32 / pixels.len() as f32
}

/// The stone's pixels where the crate's mirror image is seen: the ray meets the stone with nothing
/// in front of it, and, continued below the floor, enters the crate's image (y negated).
fn crate_image_in_stone(x: u32, y: u32) -> bool {
    let (origin, direction) = VIEW.ray(x, y);
    let (min, max) = (FLOOR_MIRROR_MIN, FLOOR_MIRROR_MAX);
    let stone = hit_y0_rect(origin, direction, min.x..=max.x, min.z..=max.z).is_some();
    let in_front = hit_cube(origin, direction, CRATE_CENTRE, CRATE_SIZE).is_some()
        || passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.6);
    let image = CRATE_CENTRE * Vec3::new(1.0, -1.0, 1.0);
    stone && !in_front && hit_cube(origin, direction, image, CRATE_SIZE).is_some()
}

#[test]
fn exercise_1_shows_the_crates_inner_faces_in_the_stone() {
    let stencil = lesson(&["technique=stencil"]);
    let right = lesson(&[]);
    let solved = exercise::<exercise_1::Solution>();
    let image = pixels(crate_image_in_stone);
    // The lesson's texture mirror shows the crate's image as the stencil mirror does ...
    let lesson_share = share_differing(&right, &stencil, &image, 8);
    assert!(
        lesson_share < 0.05,
        "the lesson differs at {lesson_share:.2}"
    );
    // ... without the winding fix most of it is another picture: the faces turned away.
    let solved_share = share_differing(&solved, &stencil, &image, 8);
    assert!(
        solved_share > 0.5,
        "the exercise differs at {solved_share:.2}"
    );
    let comparison = flip::compare(&stencil, &solved).unwrap();
    assert!(!comparison.passes(STRICT), "{}", comparison.summary());
}

/// What a pixel of the wall mirror sees: the ray meets the mirror with nothing in front of it; then,
/// continued behind the wall (z negated), the stone's image or something else.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum WallMirror {
    Stone,
    Else,
    /// The crate or (roughly) the skull stands in front of it.
    Hidden,
    No,
}

fn wall_mirror(x: u32, y: u32) -> WallMirror {
    let (origin, direction) = VIEW.ray(x, y);
    let Some(mirror) = hit_z0_rect(origin, direction, MIRROR_MIN, MIRROR_MAX) else {
        return WallMirror::No;
    };
    let crate_hit = hit_cube(origin, direction, CRATE_CENTRE, CRATE_SIZE);
    let skull = passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.6);
    if skull || crate_hit.is_some_and(|t| t < mirror) {
        return WallMirror::Hidden;
    }
    let (min, max) = (FLOOR_MIRROR_MIN, FLOOR_MIRROR_MAX);
    let stone_image = hit_y0_rect(origin, direction, min.x..=max.x, -max.z..=-min.z);
    match stone_image {
        Some(t) if t > mirror => WallMirror::Stone,
        _ => WallMirror::Else,
    }
}

#[test]
fn exercise_2_the_wall_mirror_shows_the_room_and_the_stone() {
    let wall = lesson(&["plane=wall"]);
    let floor = lesson(&[]);
    let solved = exercise::<exercise_2::Solution>();
    let elsewhere = pixels(|x, y| wall_mirror(x, y) == WallMirror::Else);
    // Where the wall mirror sees anything but the stone, it shows what the lesson's own wall texture
    // mirror shows ...
    let solved_share = share_differing(&solved, &wall, &elsewhere, 8);
    assert!(
        solved_share < 0.05,
        "the exercise differs at {solved_share:.2}"
    );
    // ... where the lesson (plane=floor) draws the wall mirror as plain glass.
    let lesson_share = share_differing(&floor, &wall, &elsewhere, 8);
    assert!(
        lesson_share > 0.5,
        "the lesson differs at {lesson_share:.2}"
    );
    // Where it sees the stone it shows the stone, not plane=wall's checkered floor.
    let stone = pixels(|x, y| wall_mirror(x, y) == WallMirror::Stone);
    let stone_share = share_differing(&solved, &wall, &stone, 8);
    assert!(
        stone_share > 0.5,
        "the stone's image differs at {stone_share:.2}"
    );
    // Off the wall mirror, the picture is the lesson's.
    for pixel in pixels(|x, y| wall_mirror(x, y) == WallMirror::No) {
        assert!(difference(&solved, &floor, pixel) == 0, "{pixel:?} changed");
    }
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
