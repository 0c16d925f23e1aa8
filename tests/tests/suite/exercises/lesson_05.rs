//! Lesson 5's exercises, judged in the depth buffer by ray casting: the room drawn with clockwise as
//! the front face shows the crate's far faces (where the ray leaves the box); the reflected floor
//! leaves, in the mark, the depth of the plane y = 0 behind the mirror.

use glam::Vec3;
use workbook::app::headless::{self, Capture, Request};
use workbook::room::camera::BOOK_POSE;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, FLOOR_DEPTH, SKULL_CENTRE, SKULL_SIZE, WALL_HALF_WIDTH,
    mirror_reflection,
};
use workbook::{Lesson, Stop};
use workbook_tests::geometry::{View, hit_y0_rect, passes_near};

use lessons::exercises::winding_fix::{exercise_1, exercise_2};
use lessons::winding_fix;

const VIEW: View = View::new(BOOK_POSE, 320, 180);

fn render<L: Lesson>(settings: &[&str]) -> Capture {
    let mut request = Request::new::<L>(settings).unwrap();
    (request.width, request.height) = (VIEW.width, VIEW.height);
    (request.read_stencil, request.read_depth) = (true, true);
    request.stop = Stop::Last;
    headless::render::<L>(&request).unwrap()
}

/// Where the ray enters and leaves the crate, if it meets it (the slab test).
fn crate_hits(x: u32, y: u32) -> Option<(Vec3, Vec3)> {
    let (origin, direction) = VIEW.ray(x, y);
    let half = Vec3::splat(CRATE_SIZE / 2.0);
    let inverse = direction.recip();
    let (a, b) = (
        (CRATE_CENTRE - half - origin) * inverse,
        (CRATE_CENTRE + half - origin) * inverse,
    );
    let (near, far) = (a.min(b).max_element(), a.max(b).min_element());
    (near <= far && near > 0.0).then(|| (origin + direction * near, origin + direction * far))
}

/// Pixels well inside the crate, away from the skull.
fn crate_pixels() -> Vec<(u32, u32)> {
    let meets = |x, y| crate_hits(x, y).is_some();
    VIEW.pixels()
        .filter(|&(x, y)| meets(x, y) && VIEW.inside_region(x, y, meets))
        .filter(|&(x, y)| {
            let (origin, direction) = VIEW.ray(x, y);
            !passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.9)
        })
        .collect()
}

/// Whether the stored depth at each pixel is the depth of `point(x, y)`; returns the misses.
fn misses(capture: &Capture, pixels: &[(u32, u32)], point: impl Fn(u32, u32) -> Vec3) -> usize {
    let off = |&(x, y): &(u32, u32)| {
        let stored = capture.depth_at(x, y).unwrap();
        (stored - VIEW.depth_of(point(x, y))).abs() >= 2e-5
    };
    pixels.iter().filter(|p| off(p)).count()
}

#[test]
fn clockwise_as_the_front_the_real_crate_shows_its_far_faces() {
    let pixels = crate_pixels();
    assert!(pixels.len() > 1000, "only {} crate pixels", pixels.len());
    let capture = render::<exercise_1::Solution>(&[]);
    let far_face = |x, y| crate_hits(x, y).unwrap().1;
    assert_eq!(misses(&capture, &pixels, far_face), 0, "not the far faces");
}

/// The counterpart: the lesson draws the room with OPAQUE, and the crate shows its near faces.
#[test]
fn the_lessons_crate_shows_its_near_faces() {
    let pixels = crate_pixels();
    let lesson = render::<winding_fix::WindingFix>(&[]);
    let near_face = |x, y| crate_hits(x, y).unwrap().0;
    let far_face = |x, y| crate_hits(x, y).unwrap().1;
    assert_eq!(misses(&lesson, &pixels, near_face), 0, "not the near faces");
    assert_eq!(misses(&lesson, &pixels, far_face), pixels.len());
}

/// Where the ray meets the floor's mirror image: y = 0, x in -6..6, z in -12..0.
fn floor_image_hit(x: u32, y: u32) -> Option<Vec3> {
    let (origin, direction) = VIEW.ray(x, y);
    let w = WALL_HALF_WIDTH;
    let t = hit_y0_rect(origin, direction, -w..=w, -FLOOR_DEPTH..=0.0)?;
    Some(origin + direction * t)
}

/// Pixels well inside the mark whose ray meets the floor's image, away from the skull's image.
fn floor_image_pixels(marked: &Capture) -> Vec<(u32, u32)> {
    let skull_image = mirror_reflection().transform_point3(SKULL_CENTRE);
    let meets = |x, y| floor_image_hit(x, y).is_some();
    VIEW.pixels()
        .filter(|&(x, y)| meets(x, y) && VIEW.inside_region(x, y, meets))
        .filter(|&(x, y)| {
            let (origin, direction) = VIEW.ray(x, y);
            !passes_near(origin, direction, skull_image, SKULL_SIZE * 0.9)
        })
        .filter(|&(x, y)| {
            let marked_at = |dx: u32, dy: u32| marked.stencil_at(x + dx - 1, y + dy - 1) == Some(1);
            (0..3).all(|dy| (0..3).all(|dx| marked_at(dx, dy)))
        })
        .collect()
}

#[test]
fn the_reflected_floor_lies_in_y_0_behind_the_mirror() {
    let capture = render::<exercise_2::Solution>(&[]);
    let pixels = floor_image_pixels(&capture);
    assert!(pixels.len() > 1000, "only {} pixels", pixels.len());
    let plane = |x, y| floor_image_hit(x, y).unwrap();
    assert_eq!(misses(&capture, &pixels, plane), 0);

    // Without the fix the floor's image, one quad seen from its back, is culled: nothing is left.
    let broken = render::<exercise_2::Solution>(&["winding-fix=off"]);
    for &(x, y) in &pixels {
        assert_eq!(broken.depth_at(x, y), Some(1.0), "pixel ({x}, {y})");
    }
}

/// The counterpart: the lesson reflects only the skull; behind the glass the depth stays at 1.0.
#[test]
fn the_lesson_reflects_no_floor() {
    let lesson = render::<winding_fix::WindingFix>(&[]);
    let pixels = floor_image_pixels(&lesson);
    assert!(pixels.len() > 1000, "only {} pixels", pixels.len());
    for (x, y) in pixels {
        assert_eq!(lesson.depth_at(x, y), Some(1.0), "pixel ({x}, {y})");
    }
}

/// The book's size, 1280×720: no wgpu error.
fn renders_full_size<L: Lesson>() {
    headless::render::<L>(&Request::new::<L>(&[] as &[&str]).unwrap()).unwrap();
}

#[test]
fn the_exercises_render_at_1280x720() {
    renders_full_size::<exercise_1::Solution>();
    renders_full_size::<exercise_2::Solution>();
}
