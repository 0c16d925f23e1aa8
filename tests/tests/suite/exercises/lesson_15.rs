//! Lesson 15's exercises, against the same oracle as the lesson's own count (where the camera's ray
//! meets the plane, inside which solids): the two counts apart hold the skull's answer in the low
//! seven bits and the crate's in the top bit; the hollow ball's count is 0 in its hollow, and the
//! cap a ring.

use crate::capping::{SIZE, Solids, judge_on_plane};
use glam::Vec3;
use lessons::capping::Capping;
use lessons::exercises::capping::{exercise_1, exercise_2};
use std::cell::Cell;
use workbook::app::headless::{self, Request};
use workbook::room::scene::{SKULL_CENTRE, SKULL_SIZE};
use workbook::{Lesson, Stop};

/// Lesson `L` (an exercise's solution) stopped after step `stop`, from the lesson's pose, its
/// stencil and depth read back.
fn capture_of<L: Lesson>(stop: usize) -> headless::Capture {
    let mut request = Request::new::<L>(&[] as &[&str]).unwrap();
    (request.width, request.height) = SIZE;
    request.camera = Capping::CAMERA;
    request.read_stencil = true;
    request.read_depth = true;
    request.stop = Stop::After(stop);
    headless::render::<L>(&request).unwrap()
}

/// The stencil after "count the inside", the fourth step.
fn counts_of<L: Lesson>() -> Vec<u8> {
    capture_of::<L>(4).stencil.unwrap()
}

/// Each count writes its own bits: where the plane lies in the skull the low seven bits are not 0,
/// where it lies in the crate the top bit is set — each exactly, and both where both overlap.
#[test]
fn each_solid_has_its_own_bits() {
    let counts = counts_of::<exercise_1::Solution>();
    let solids = Solids::new(&["crate=through"]);
    let oracle = |p: Vec3| (solids.in_skull(p), solids.in_crate(p));
    let bits = |count: u8, (skull, krate): (bool, bool)| {
        (count as u32 & exercise_1::SKULL_BITS != 0) == skull
            && (count as u32 & exercise_1::CRATE_BIT != 0) == krate
    };
    let (judged, wrong) = judge_on_plane(&counts, oracle, bits);
    let both = (counts.iter())
        .filter(|&&c| c as u32 & exercise_1::SKULL_BITS != 0 && c >= 0x80)
        .count();
    eprintln!("two counts apart: {wrong} of {judged} judged pixels disagree; {both} in both");
    assert!(judged > 30_000, "only {judged} pixels judged");
    assert_eq!(wrong, 0, "{wrong} of {judged} pixels disagree");
    assert!(both > 200, "only {both} pixels in both solids");

    // The cap drew (changed the depth) exactly where the plane lies in the crate.
    let before = capture_of::<exercise_1::Solution>(4).depth.unwrap();
    let after = capture_of::<exercise_1::Solution>(5).depth.unwrap();
    let drawn: Vec<u8> = (before.iter().zip(&after))
        .map(|(a, b)| (a != b) as u8)
        .collect();
    let capped = |drawn: u8, (_, krate): (bool, bool)| (drawn == 1) == krate;
    let (judged, wrong) = judge_on_plane(&drawn, oracle, capped);
    eprintln!("the crate's cap: {wrong} of {judged} judged pixels disagree");
    assert_eq!(wrong, 0, "the cap: {wrong} of {judged} pixels disagree");
}

/// The hollow ball: the count is not 0 exactly where the plane lies in its wall, and 0 in its
/// hollow, which a cut through its centre shows as a disc (the cap, a ring).
#[test]
fn the_hollow_balls_count_leaves_its_hollow_open() {
    let counts = counts_of::<exercise_2::Solution>();
    let solids = Solids::with_skull(&exercise_2::hollow_ball(), &[]);
    // The hollow: the plane within the inner radius (a little less: the ball's facets).
    let hollow = |p: Vec3| p.distance(SKULL_CENTRE) < 0.95 * exercise_2::INNER * SKULL_SIZE;
    let open = Cell::new(0);
    let inside = |count: u8, (solids, hollow): (u32, bool)| {
        open.set(open.get() + (hollow && count == 0) as usize);
        (count != 0) == (solids > 0)
    };
    let oracle = |p: Vec3| (solids.containing(p), hollow(p));
    let (judged, wrong) = judge_on_plane(&counts, oracle, inside);
    let open = open.get();
    eprintln!(
        "the hollow ball: {wrong} of {judged} judged pixels disagree; {open} open in the hollow"
    );
    assert!(judged > 30_000, "only {judged} pixels judged");
    assert_eq!(wrong, 0, "{wrong} of {judged} pixels disagree");
    assert!(open > 500, "only {open} pixels open in the hollow");
}
