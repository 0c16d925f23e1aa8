//! Lesson 3's exercises: the stencil buffer read back and checked against the mirror and the crate
//! projected by the camera (ray casting), as lesson 3's own test does — the mark made before the room
//! runs under the crate; the mark of what hides the mirror holds 2 there.

use glam::Vec3;
use workbook::Lesson;
use workbook::app::headless::{self, Capture, Request};
use workbook::room::camera::BOOK_POSE;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, MIRROR_MAX, MIRROR_MIN, SKULL_CENTRE, SKULL_SIZE,
};
use workbook_tests::geometry::{View, hit_box, hit_z0_rect, passes_near};

use lessons::exercises::mark_mirror::{exercise_1, exercise_2};
use lessons::mark_mirror;

const VIEW: View = View::new(BOOK_POSE, 320, 180);

fn render<L: Lesson>(settings: &[&str]) -> Capture {
    let mut request = Request::new::<L>(settings).unwrap();
    (request.width, request.height) = (VIEW.width, VIEW.height);
    request.read_stencil = true;
    headless::render::<L>(&request).unwrap()
}

/// What a pixel's ray meets first, as far as the mark is concerned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Seen {
    Mirror,
    /// The mirror, behind the crate.
    CrateOverMirror,
    /// Wall, floor, crate elsewhere, sky.
    Elsewhere,
    /// Near the skull, which also hides the mirror: not judged.
    NearSkull,
}

fn seen(x: u32, y: u32) -> Seen {
    let (origin, direction) = VIEW.ray(x, y);
    if passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.9) {
        return Seen::NearSkull;
    }
    let half = Vec3::splat(CRATE_SIZE / 2.0);
    let crate_hit = hit_box(origin, direction, CRATE_CENTRE - half, CRATE_CENTRE + half);
    match hit_z0_rect(origin, direction, MIRROR_MIN, MIRROR_MAX) {
        Some(mirror) if crate_hit.is_some_and(|c| c < mirror) => Seen::CrateOverMirror,
        Some(_) => Seen::Mirror,
        None => Seen::Elsewhere,
    }
}

/// Checks the stencil against the projection: 1 on the mirror, 0 elsewhere, `under_crate` where the
/// crate hides the mirror. Returns how many pixels were checked under the crate.
fn check(capture: &Capture, under_crate: u8) -> usize {
    let mut counts = [0; 3];
    for (x, y) in VIEW.pixels() {
        let kind = seen(x, y);
        if kind == Seen::NearSkull || !VIEW.inside_region(x, y, seen) {
            continue;
        }
        let (expected, slot) = match kind {
            Seen::Mirror => (1, 0),
            Seen::Elsewhere => (0, 1),
            Seen::CrateOverMirror => (under_crate, 2),
            Seen::NearSkull => unreachable!(),
        };
        let stored = capture.stencil_at(x, y).unwrap();
        assert_eq!(stored, expected, "pixel ({x}, {y}) sees {kind:?}");
        counts[slot] += 1;
    }
    assert!(counts[0] > 3000, "only {} mirror pixels", counts[0]);
    assert!(counts[1] > 20000, "only {} pixels elsewhere", counts[1]);
    counts[2]
}

/// How many pixels where the crate hides the mirror hold `value`.
fn under_crate_holding(capture: &Capture, value: u8) -> usize {
    VIEW.pixels()
        .filter(|&(x, y)| seen(x, y) == Seen::CrateOverMirror && VIEW.inside_region(x, y, seen))
        .filter(|&(x, y)| capture.stencil_at(x, y) == Some(value))
        .count()
}

#[test]
fn marked_before_the_room_the_mark_runs_under_the_crate() {
    let under_crate = check(&render::<exercise_1::Solution>(&[]), 1);
    assert!(
        under_crate > 300,
        "only {under_crate} pixels under the crate"
    );
}

/// The counterpart: the lesson (room first) leaves 0 under the crate.
#[test]
fn the_lessons_order_leaves_the_crate_a_hole() {
    let lesson = render::<mark_mirror::MarkMirror>(&[]);
    assert_eq!(under_crate_holding(&lesson, 1), 0);
    assert!(check(&lesson, 0) > 300);
}

#[test]
fn the_mark_holds_1_where_the_mirror_is_seen_and_2_where_the_crate_hides_it() {
    let capture = render::<exercise_2::Solution>(&[]);
    let under_crate = check(&capture, 2);
    assert!(
        under_crate > 300,
        "only {under_crate} pixels under the crate"
    );
    // The skull hides the mirror too: its pixel at the skull's centre holds 2.
    let (x, y) = VIEW.pixel_of(SKULL_CENTRE);
    assert_eq!(
        capture.stencil_at(x, y),
        Some(2),
        "the skull hides the mirror"
    );
}

/// The counterpart: the lesson's mark has no 2 anywhere, and 0 under the crate.
#[test]
fn the_lessons_mark_knows_nothing_of_what_hides_the_mirror() {
    let lesson = render::<mark_mirror::MarkMirror>(&[]);
    assert!(lesson.stencil.as_ref().unwrap().iter().all(|&v| v < 2));
    assert_eq!(under_crate_holding(&lesson, 2), 0);
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
