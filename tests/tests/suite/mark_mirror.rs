//! Lesson 3's stencil buffer read back and checked against the mirror and the crate projected by the
//! camera: 1 where the mirror is seen, 0 on the wall and floor, 0 where the crate hides the mirror.

use glam::Vec3;
use workbook::Stop;
use workbook::app::headless::Capture;
use workbook::gpu::views::stencil_colour;
use workbook::room::camera::BOOK_POSE;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, MIRROR_MAX, MIRROR_MIN, SKULL_CENTRE, SKULL_SIZE,
};
use workbook_tests::geometry::{View, hit_box, hit_z0_rect, passes_near};
use workbook_tests::shots;

/// The book's camera, at a size that keeps the test quick.
const VIEW: View = View::new(BOOK_POSE, 320, 180);

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

fn render(settings: &[&str]) -> Capture {
    render_until(settings, Stop::Last)
}

fn render_until(settings: &[&str], stop: Stop) -> Capture {
    shots::render("mark-mirror", settings, |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.read_stencil = true;
        request.stop = stop;
    })
    .unwrap()
}

/// Checks the mark against the projection; returns how many pixels of each kind were checked.
fn check(capture: &Capture, expect_under_crate: u8) -> [usize; 3] {
    let mut counts = [0; 3];
    for (x, y) in VIEW.pixels() {
        let kind = seen(x, y);
        if kind == Seen::NearSkull || !VIEW.inside_region(x, y, seen) {
            continue;
        }
        let (expected, slot) = match kind {
            Seen::Mirror => (1, 0),
            Seen::Elsewhere => (0, 1),
            Seen::CrateOverMirror => (expect_under_crate, 2),
            Seen::NearSkull => unreachable!(),
        };
        let stored = capture.stencil_at(x, y).unwrap();
        assert_eq!(stored, expected, "pixel ({x}, {y}) sees {kind:?}");
        counts[slot] += 1;
    }
    counts
}

#[test]
fn the_mark_is_the_visible_mirror_with_a_hole_for_the_crate() {
    let [mirror, elsewhere, under_crate] = check(&render(&[]), 0);
    assert!(mirror > 3000, "only {mirror} mirror pixels");
    assert!(elsewhere > 20000, "only {elsewhere} pixels elsewhere");
    assert!(
        under_crate > 300,
        "only {under_crate} pixels where the crate hides the mirror"
    );
}

/// Step by step: after "draw the room" (step 2) the stencil buffer is still all 0; after "mark the
/// mirror" (step 3) it holds the mark.
#[test]
fn the_mark_is_made_by_the_step_that_marks_the_mirror() {
    let step = |name| shots::after_step("mark-mirror", &[], name).unwrap();
    let room = render_until(&[], step("draw the room"));
    assert!(room.stencil.as_ref().unwrap().iter().all(|&v| v == 0));
    let [mirror, _, _] = check(&render_until(&[], step("mark the mirror")), 0);
    assert!(mirror > 3000, "only {mirror} mirror pixels");
}

#[test]
fn without_the_depth_test_the_mark_runs_under_the_crate() {
    let [_, _, under_crate] = check(&render(&["mark-depth-test=off"]), 1);
    assert!(under_crate > 300);
}

/// `view=stencil` (rebuilt bit by bit with the stencil test, no copy) paints each pixel with the
/// colour of the value the readback (a copy) finds there: two independent paths agree.
#[test]
fn the_stencil_view_shows_the_values_the_readback_finds() {
    let capture = render(&[]);
    for (x, y) in VIEW.pixels() {
        let value = capture.stencil_at(x, y).unwrap();
        let shown = capture.color.get_pixel(x, y).0;
        let expected = stencil_colour(value);
        for c in 0..3 {
            assert!(
                shown[c].abs_diff(expected[c]) <= 1,
                "pixel ({x}, {y}) holds {value} but shows {shown:?}, not {expected:?}"
            );
        }
    }
}
