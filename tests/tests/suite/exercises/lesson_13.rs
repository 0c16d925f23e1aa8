//! Lesson 13's exercises, judged by the room's surfaces along each pixel's ray (the lesson's test's
//! CPU count): drawn nearest first, only the surfaces nearer than everything drawn before them pass
//! the depth test, in the reversed order; with no face culled, every box the ray enters counts its
//! way out too. Each against the lesson's own count, which is not already the answer.

use crate::depth_complexity::{
    VIEW, boxes_entered, counts, counts_of, passing, surfaces, surfaces_objects_reversed,
};
use lessons::exercises::depth_complexity::{exercise_1, exercise_2};

/// Compares `got` with `expected(x, y)` at the pixels whose prediction is the same as their four
/// neighbours'; returns how many were judged.
fn judge(got: &[u8], expected: impl Fn(u32, u32) -> Option<u8>) -> usize {
    let mut judged = 0;
    for (x, y) in VIEW.pixels() {
        let Some(want) = expected(x, y) else { continue };
        if !VIEW.inside_region(x, y, &expected) {
            continue;
        }
        assert_eq!(got[(y * VIEW.width + x) as usize], want, "pixel ({x}, {y})");
        judged += 1;
    }
    judged
}

#[test]
fn nearest_first_lets_only_the_nearest_surfaces_pass() {
    let exercise = counts_of::<exercise_1::Solution>();
    // The lesson's objects in reverse: the water first, the floor last.
    let reversed = |x, y| surfaces_objects_reversed(x, y).map(passing);
    assert!(judge(&exercise, reversed) > 30_000);
    // Fewer pass in all than in the lesson's order (the floor under the water, the wall behind
    // the crate), though not at every pixel: where the lesson already drew the nearer first, the
    // reversed order lets both pass.
    let lesson = counts(&["count=passed-depth"]);
    let total = |counts: &[u8]| counts.iter().map(|&c| c as u32).sum::<u32>();
    let (nearest_first, lesson_order) = (total(&exercise), total(&lesson));
    eprintln!("fragments passed: nearest first {nearest_first}, the lesson's order {lesson_order}");
    assert!(nearest_first < lesson_order);
}

/// The boxes a ray enters (the three wall blocks and the crate) are the surfaces it also leaves.
#[test]
fn without_culling_every_box_counts_its_way_out_too() {
    let exercise = counts_of::<exercise_2::Solution>();
    let lesson = counts(&[]);
    let both_sides = |x, y| {
        let boxes = boxes_entered(x, y)?;
        surfaces(x, y).map(|hits| hits.len() as u8 + boxes)
    };
    assert!(judge(&exercise, both_sides) > 30_000);
    let more = exercise.iter().zip(&lesson).filter(|(e, l)| e > l).count();
    assert!(
        more > 10_000,
        "only {more} pixels count more than the culled room"
    );
}
