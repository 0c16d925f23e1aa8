//! Lesson 16's exercises, against the lesson's own oracles: the turned room's stencil is the
//! number of doorways the rays pass (never 2: doorway 2 faces away), and its room 1 is the room
//! seen from the camera turned back; through the far portal, clip=off changes nothing.

use crate::portal::{SIZE, Through, compare_room, doorways_passed};
use glam::Mat4;
use lessons::exercises::portal::{exercise_1, exercise_2};
use lessons::portal::Portal;
use workbook::app::headless::{self, Capture, Request};
use workbook::{Lesson, Show};
use workbook_tests::geometry::{RoomRays, View};

/// Exercise 1's portal, as a type.
struct Turned;

impl Through for Turned {
    fn portal() -> Mat4 {
        exercise_1::turned()
    }
}

/// Lesson `L` (an exercise's solution) with `settings`, its whole frame from the lesson's pose,
/// the stencil read back.
fn capture<L: Lesson>(settings: &[&str]) -> Capture {
    let mut request = Request::new::<L>(settings).unwrap();
    (request.width, request.height) = SIZE;
    request.camera = Portal::CAMERA;
    request.read_stencil = true;
    request.show = Show::Color;
    headless::render::<L>(&request).unwrap()
}

#[test]
fn the_turned_room_is_the_room_turned_and_has_no_room_2() {
    let turned = capture::<exercise_1::Solution>(&[]);
    let stencil = turned.stencil.as_ref().unwrap();
    let deepest = stencil.iter().max().copied().unwrap_or(0);
    assert_eq!(deepest, 1, "the deepest room marked is {deepest}");
    let rays = RoomRays::new();
    let view = View::new(Portal::CAMERA, SIZE.0, SIZE.1);
    let wrong = (0..SIZE.0 * SIZE.1)
        .filter(|&i| {
            let (x, y) = ((i % SIZE.0) as f32 + 0.5, (i / SIZE.0) as f32 + 0.5);
            let passed = doorways_passed(&rays, Turned::portal(), view.ray_at(x, y), 3);
            let corners = [(-0.5, -0.5), (0.5, -0.5), (-0.5, 0.5), (0.5, 0.5)];
            let agree = corners.iter().all(|&(dx, dy)| {
                doorways_passed(&rays, Turned::portal(), view.ray_at(x + dx, y + dy), 3) == passed
            });
            agree && stencil[i as usize] as u32 != passed
        })
        .count();
    assert_eq!(wrong, 0, "{wrong} pixels disagree with the rays");
    let (compared, differ) = compare_room::<Turned, 1>(&rays, &turned.color);
    assert!(compared > 3_000, "only {compared} pixels compared");
    assert!(
        differ * 100 <= compared,
        "{differ} of {compared} pixels differ"
    );
}

/// Room 1 begins where this room's wall ends: nothing of it stands on this side of the doorway,
/// and cutting it there changes no pixel by more than 8.
#[test]
fn through_the_far_portal_the_cut_changes_nothing() {
    let cut = capture::<exercise_2::Solution>(&[]).color;
    let uncut = capture::<exercise_2::Solution>(&["clip=off"]).color;
    let differ = (cut.pixels().zip(uncut.pixels()))
        .filter(|(a, b)| a.0.iter().zip(b.0).any(|(p, q)| p.abs_diff(q) > 8))
        .count();
    assert_eq!(differ, 0, "{differ} pixels differ with clip=off");
}
