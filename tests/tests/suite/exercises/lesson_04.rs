//! Lesson 4's exercises: the reflected crate found in the depth buffer where rays through the mirror
//! meet the crate's mirror image (ray casting: the image is the crate's box with z negated), on its
//! far faces, since lesson 4 draws mirror images inside out; and the reflection drawn before the mark,
//! which leaves the picture the mark alone leaves.

use glam::Vec3;
use workbook::app::headless::{self, Capture, Request};
use workbook::room::camera::BOOK_POSE;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, SKULL_CENTRE, SKULL_SIZE, mirror_reflection,
};
use workbook::{Lesson, Stop};
use workbook_tests::geometry::{View, passes_near};

use lessons::exercises::reflect_skull::{exercise_1, exercise_2};
use lessons::reflect_skull;

const VIEW: View = View::new(BOOK_POSE, 320, 180);

fn render<L: Lesson>(settings: &[&str], stop: Stop) -> Capture {
    let mut request = Request::new::<L>(settings).unwrap();
    (request.width, request.height) = (VIEW.width, VIEW.height);
    (request.read_stencil, request.read_depth) = (true, true);
    request.stop = stop;
    headless::render::<L>(&request).unwrap()
}

/// Where the ray enters and leaves the crate's mirror image, if it meets it (the slab test).
fn reflected_crate_hits(x: u32, y: u32) -> Option<(Vec3, Vec3)> {
    let (origin, direction) = VIEW.ray(x, y);
    let centre = mirror_reflection().transform_point3(CRATE_CENTRE);
    let half = Vec3::splat(CRATE_SIZE / 2.0);
    let inverse = direction.recip();
    let (a, b) = (
        (centre - half - origin) * inverse,
        (centre + half - origin) * inverse,
    );
    let (near, far) = (a.min(b).max_element(), a.max(b).min_element());
    (near <= far && near > 0.0).then(|| (origin + direction * near, origin + direction * far))
}

/// Pixels in the mark whose ray meets the crate's mirror image and passes nowhere near the skull's
/// (edges skipped).
fn reflected_crate_pixels(marked: &Capture) -> Vec<(u32, u32)> {
    let skull_image = mirror_reflection().transform_point3(SKULL_CENTRE);
    let meets = |x, y| reflected_crate_hits(x, y).is_some();
    VIEW.pixels()
        .filter(|&(x, y)| meets(x, y) && VIEW.inside_region(x, y, meets))
        .filter(|&(x, y)| {
            let (origin, direction) = VIEW.ray(x, y);
            !passes_near(origin, direction, skull_image, SKULL_SIZE * 0.9)
        })
        .filter(|&(x, y)| {
            let marked_around =
                |dx: u32, dy: u32| marked.stencil_at(x + dx - 1, y + dy - 1) == Some(1);
            (0..3).all(|dy| (0..3).all(|dx| marked_around(dx, dy)))
        })
        .collect()
}

#[test]
fn the_reflected_crate_shows_its_far_faces_in_the_mirror() {
    let capture = render::<exercise_1::Solution>(&[], Stop::Last);
    let pixels = reflected_crate_pixels(&capture);
    assert!(pixels.len() > 150, "only {} pixels", pixels.len());
    for &(x, y) in &pixels {
        let (_, far) = reflected_crate_hits(x, y).unwrap();
        let (stored, expected) = (capture.depth_at(x, y).unwrap(), VIEW.depth_of(far));
        assert!(
            (stored - expected).abs() < 2e-5,
            "pixel ({x}, {y}): stored {stored}, the image's far face {expected}"
        );
    }
}

/// The counterpart: the lesson draws nothing there; the depth stays at the far plane.
#[test]
fn the_lesson_leaves_the_crates_image_empty() {
    let lesson = render::<reflect_skull::ReflectSkull>(&[], Stop::Last);
    for (x, y) in reflected_crate_pixels(&lesson) {
        assert_eq!(lesson.depth_at(x, y), Some(1.0), "pixel ({x}, {y})");
    }
}

#[test]
fn reflected_before_the_mark_nothing_is_reflected() {
    let lesson_marked = render::<reflect_skull::ReflectSkull>(&[], Stop::After(3));
    let exercise = render::<exercise_2::Solution>(&[], Stop::Last);
    assert_eq!(exercise.stencil, lesson_marked.stencil, "the mark differs");
    assert_eq!(
        exercise.depth, lesson_marked.depth,
        "the reflection wrote depth"
    );
    assert!(exercise.color == lesson_marked.color, "the reflection drew");
}

/// The counterpart: in the lesson's order the reflection changes the marked picture.
#[test]
fn in_the_lessons_order_the_reflection_draws() {
    let lesson_marked = render::<reflect_skull::ReflectSkull>(&[], Stop::After(3));
    let lesson = render::<reflect_skull::ReflectSkull>(&[], Stop::Last);
    let changed = workbook_tests::changed_only_inside_mark(&lesson_marked, &lesson, 1).unwrap();
    assert!(changed > 100, "only {changed} pixels changed");
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
