//! Lesson 1's exercises: the depth pre-pass (the lesson's picture, shaded by `Equal`) and the skull
//! that forgets its depth (the room's depth where the skull is, from the planes by ray casting).

use glam::Vec3;
use workbook::Lesson;
use workbook::Stop;
use workbook::app::headless::{self, Capture, Request};
use workbook::room::camera::BOOK_POSE;
use workbook::room::scene::{CLEAR_SRGB, FLOOR_DEPTH, SKULL_CENTRE, WALL_HALF_WIDTH, WALL_HEIGHT};
use workbook_tests::geometry::{View, hit_y0_rect, hit_z0_rect};

use lessons::depth_test;
use lessons::exercises::depth_test::{exercise_1, exercise_2};

const VIEW: View = View::new(BOOK_POSE, 320, 180);

fn render<L: Lesson>(settings: &[&str], stop: Stop) -> Capture {
    let mut request = Request::new::<L>(settings).unwrap();
    (request.width, request.height) = (VIEW.width, VIEW.height);
    request.read_depth = true;
    request.stop = stop;
    headless::render::<L>(&request).unwrap()
}

/// Every pixel is the sky's clear colour.
fn all_sky(capture: &Capture) -> bool {
    capture.color.pixels().all(|p| p.0[..3] == CLEAR_SRGB)
}

#[test]
fn the_pre_pass_paints_nothing_and_the_equal_pass_paints_the_lessons_picture() {
    let lesson = render::<depth_test::DepthTest>(&[], Stop::Last);
    let pre_pass = render::<exercise_1::Solution>(&[], Stop::After(2));
    let finished = render::<exercise_1::Solution>(&[], Stop::Last);
    assert!(all_sky(&pre_pass), "the pre-pass wrote colour");
    assert_eq!(
        pre_pass.depth, lesson.depth,
        "the pre-pass leaves the lesson's depth buffer"
    );
    assert_eq!(finished.depth, lesson.depth, "the shading pass wrote depth");
    assert!(
        finished.color == lesson.color,
        "the pre-pass picture differs from the lesson's"
    );
}

/// The counterpart: the lesson's `Equal` alone (no pre-pass) draws nothing, since every fragment
/// meets the cleared 1.0 and none lies on the far plane.
#[test]
fn equal_without_a_pre_pass_draws_nothing() {
    assert!(all_sky(&render::<depth_test::DepthTest>(
        &["depth=equal"],
        Stop::Last
    )));
}

/// The depth of the floor or the wall-and-mirror plane that the pixel's ray meets first.
fn room_depth(x: u32, y: u32) -> f32 {
    let (origin, direction) = VIEW.ray(x, y);
    let w = WALL_HALF_WIDTH;
    let floor = hit_y0_rect(origin, direction, -w..=w, 0.0..=FLOOR_DEPTH);
    let wall = hit_z0_rect(
        origin,
        direction,
        Vec3::new(-w, 0.0, 0.0),
        Vec3::new(w, WALL_HEIGHT, 0.0),
    );
    let t = [floor, wall]
        .into_iter()
        .flatten()
        .min_by(f32::total_cmp)
        .unwrap();
    VIEW.depth_of(origin + direction * t)
}

/// The 5×5 pixels around the skull's centre on screen: all skull in the lesson's picture.
fn around_the_skull() -> impl Iterator<Item = (u32, u32)> {
    let (cx, cy) = VIEW.pixel_of(SKULL_CENTRE);
    (cy - 2..=cy + 2).flat_map(move |y| (cx - 2..=cx + 2).map(move |x| (x, y)))
}

#[test]
fn the_skull_without_depth_writes_leaves_the_rooms_depth() {
    for order in ["order=near-first", "order=far-first"] {
        let capture = render::<exercise_2::Solution>(&[order], Stop::Last);
        let lesson = render::<depth_test::DepthTest>(&[order], Stop::Last);
        for (x, y) in around_the_skull() {
            let (stored, room) = (capture.depth_at(x, y).unwrap(), room_depth(x, y));
            assert!(
                (stored - room).abs() < 2e-5,
                "{order}: pixel ({x}, {y}) holds {stored}, the room behind {room}"
            );
            // The counterpart: the lesson's skull writes its nearer depth there.
            let lesson_stored = lesson.depth_at(x, y).unwrap();
            assert!(
                lesson_stored < room - 1e-4,
                "{order}: the lesson's skull at ({x}, {y})"
            );
        }
        // Near first, the mirror drawn after the skull covers it; far first, the skull drawn last
        // shows as in the lesson.
        let (x, y) = VIEW.pixel_of(SKULL_CENTRE);
        let shows_skull = capture.color.get_pixel(x, y) == lesson.color.get_pixel(x, y);
        assert_eq!(shows_skull, order == "order=far-first", "{order}");
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
