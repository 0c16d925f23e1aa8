//! The depth buffer read back and checked against an independent expectation: the room's floor and
//! wall are planes, so the depth they leave at a pixel follows from the camera alone — cast the ray
//! through the pixel, intersect the plane, project the point.

use glam::Vec3;
use workbook::app::headless::Capture;
use workbook::room::camera::BOOK_POSE;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, FLOOR_DEPTH, SKULL_CENTRE, SKULL_SIZE, WALL_HALF_WIDTH, WALL_HEIGHT,
};
use workbook_tests::geometry::{View, hit_y0_rect, hit_z0_rect, passes_near};
use workbook_tests::shots;

/// The book's camera, at a size that keeps the test quick.
const VIEW: View = View::new(BOOK_POSE, 320, 180);

fn render(settings: &[&str]) -> Capture {
    shots::render("depth-test", settings, |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.read_depth = true;
    })
    .unwrap()
}

/// The nearest point where the ray meets the floor (y = 0) or the wall-and-mirror (z = 0), if any.
fn room_hit(x: u32, y: u32) -> Option<Vec3> {
    let (origin, direction) = VIEW.ray(x, y);
    let w = WALL_HALF_WIDTH;
    let floor = hit_y0_rect(origin, direction, -w..=w, 0.0..=FLOOR_DEPTH);
    let wall = hit_z0_rect(
        origin,
        direction,
        Vec3::new(-w, 0.0, 0.0),
        Vec3::new(w, WALL_HEIGHT, 0.0),
    );
    let t = [floor, wall].into_iter().flatten().min_by(f32::total_cmp)?;
    Some(origin + direction * t)
}

/// Whether the ray passes near the skull or the crate (generously: their bounding spheres).
fn near_an_object(x: u32, y: u32) -> bool {
    let (origin, direction) = VIEW.ray(x, y);
    passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.9)
        || passes_near(origin, direction, CRATE_CENTRE, CRATE_SIZE * 0.9)
}

#[test]
fn the_room_leaves_the_depth_its_planes_predict() {
    let capture = render(&[]);
    let (mut checked, mut sky) = (0, 0);
    for (x, y) in VIEW.pixels().filter(|(x, y)| x % 3 == 0 && y % 3 == 0) {
        if near_an_object(x, y) || !VIEW.inside_region(x, y, |x, y| room_hit(x, y).is_some()) {
            continue;
        }
        let stored = capture.depth_at(x, y).unwrap();
        match room_hit(x, y) {
            Some(point) => {
                let expected = VIEW.depth_of(point);
                assert!(
                    (stored - expected).abs() < 2e-5,
                    "pixel ({x}, {y}) sees {point:?}: expected depth {expected}, stored {stored}"
                );
                checked += 1;
            }
            None => {
                assert_eq!(
                    stored, 1.0,
                    "pixel ({x}, {y}) sees the sky: depth stays cleared"
                );
                sky += 1;
            }
        }
    }
    assert!(checked > 3000, "only {checked} room pixels checked");
    assert!(sky > 100, "only {sky} sky pixels checked");
}

#[test]
fn the_skull_is_nearer_than_the_wall_behind_it() {
    let (x, y) = VIEW.pixel_of(SKULL_CENTRE);
    let behind = VIEW.depth_of(room_hit(x, y).unwrap());
    let stored = render(&[]).depth_at(x, y).unwrap();
    assert!(
        stored < behind - 1e-4,
        "skull {stored}, room behind it {behind}"
    );
}

/// The classic wrong picture: with depth=always the last object drawn wins, so where the skull was
/// drawn first, the room drawn after it holds the pixel — at exactly the room's depth.
#[test]
fn with_depth_always_the_room_is_drawn_over_the_skull() {
    let (x, y) = VIEW.pixel_of(SKULL_CENTRE);
    let behind = VIEW.depth_of(room_hit(x, y).unwrap());
    let stored = render(&["depth=always"]).depth_at(x, y).unwrap();
    assert!(
        (stored - behind).abs() < 2e-5,
        "stored {stored}, room {behind}"
    );
    let painter = render(&["depth=always", "order=far-first"])
        .depth_at(x, y)
        .unwrap();
    assert!(
        painter < behind - 1e-4,
        "the painter's order draws the skull last"
    );
}
