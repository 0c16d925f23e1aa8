//! Lesson 4: the reflection is drawn only through the mirror. From the front the depth test alone
//! hides it behind the wall; from behind the wall only the stencil test keeps it away (Luna's
//! figure 10.1).

use workbook::Stop;
use workbook::app::headless::Capture;
use workbook::room::camera::Camera;
use workbook::room::scene::{CLEAR_SRGB, SKULL_CENTRE, SKULL_SIZE, mirror_reflection};
use workbook_tests::geometry::{View, passes_near};
use workbook_tests::shots::{self, BEHIND_THE_WALL};

const W: u32 = 320;
const H: u32 = 180;

fn render(settings: &[&str], camera: Camera) -> Capture {
    render_until(settings, camera, Stop::Last)
}

fn render_until(settings: &[&str], camera: Camera, stop: Stop) -> Capture {
    shots::render("reflect-skull", settings, |request| {
        (request.width, request.height) = (W, H);
        request.camera = camera;
        request.read_stencil = true;
        request.stop = stop;
    })
    .unwrap()
}

/// Luna's figure 10.4, step by step: drawing the reflected skull (step 4) leaves the stencil buffer
/// as the mark made it (step 3), and changes colours only where the mark holds 1.
#[test]
fn the_reflection_step_reads_the_mark_and_changes_only_the_marked_pixels() {
    let camera = Camera::default();
    let step = |name| shots::after_step("reflect-skull", &[], name).unwrap();
    let marked = render_until(&[], camera, step("mark the mirror"));
    let reflected = render_until(&[], camera, step("draw the reflected skull"));
    assert_eq!(
        marked.stencil, reflected.stencil,
        "the reflection changed the stencil"
    );
    let changed = workbook_tests::changed_only_inside_mark(&marked, &reflected, 1).unwrap();
    assert!(
        changed > 100,
        "the reflection changed only {changed} pixels"
    );
}

#[test]
fn the_reflection_appears_in_the_mirror() {
    let view = View::new(Camera::default(), W, H);
    let centre = mirror_reflection().transform_point3(SKULL_CENTRE);
    let (x, y) = view.pixel_of(centre);
    let capture = render(&[], view.camera);
    assert_eq!(
        capture.stencil_at(x, y),
        Some(1),
        "the reflected skull's centre is in the mirror"
    );
    assert_ne!(
        capture.color.get_pixel(x, y).0[..3],
        CLEAR_SRGB,
        "the mirror shows the reflected skull, not the sky"
    );
}

#[test]
fn from_the_front_the_depth_test_alone_hides_the_spill() {
    let with = render(&[], Camera::default());
    let without = render(&["stencil=off"], Camera::default());
    assert!(
        with.color == without.color,
        "from the front, stencil=off must change nothing"
    );
}

#[test]
fn from_behind_the_wall_only_the_stencil_hides_the_reflection() {
    let view = View::new(Camera::parse(BEHIND_THE_WALL).unwrap(), W, H);
    let with = render(&[], view.camera);
    let without = render(&["stencil=off"], view.camera);
    let reflected_centre = mirror_reflection().transform_point3(SKULL_CENTRE);
    let mut differing = 0;
    for (x, y) in view.pixels() {
        if with.color.get_pixel(x, y) == without.color.get_pixel(x, y) {
            continue;
        }
        differing += 1;
        let (origin, direction) = view.ray(x, y);
        assert!(
            passes_near(origin, direction, reflected_centre, SKULL_SIZE * 0.9),
            "pixel ({x}, {y}) changed but is nowhere near the reflected skull"
        );
        assert_eq!(
            with.stencil_at(x, y),
            Some(0),
            "pixel ({x}, {y}) is outside the mirror"
        );
    }
    assert!(
        differing > 1000,
        "only {differing} pixels show the spilled reflection"
    );
}
