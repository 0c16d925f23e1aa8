//! Lesson 8's exercises. 1: a mark without the depth test marks the stone behind the crate, and the
//! stone is then blended over the crate. 2: the wire-fence crate's image shows in the stone where
//! the ray, continued below the floor, meets the fence's mirror image, and nowhere else changes.

use lessons::exercises::floor_mirror::{exercise_1, exercise_2};

use glam::Vec3;
use workbook::Lesson;
use workbook::app::headless::{self, Capture, Request};
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, FENCE_CENTRE, FENCE_SIZE, FLOOR_MIRROR_MAX, FLOOR_MIRROR_MIN,
    SKULL_CENTRE, SKULL_SIZE,
};
use workbook_tests::geometry::{View, hit_box, hit_y0_rect, passes_near};
use workbook_tests::{changed_only_inside_mark, shots};

use lessons::floor_mirror::FloorMirror;

/// Lesson 8's camera, at a size that keeps the tests quick.
const VIEW: View = View::new(FloorMirror::CAMERA, 400, 225);

fn lesson() -> Capture {
    shots::render("floor-mirror", &[], |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.read_stencil = true;
    })
    .unwrap()
}

fn exercise<L: Lesson>(stop: workbook::Stop) -> Capture {
    let mut request = Request::new::<L>(&[] as &[&str]).unwrap();
    (request.width, request.height) = (VIEW.width, VIEW.height);
    request.read_stencil = true;
    request.stop = stop;
    headless::render::<L>(&request).unwrap()
}

/// Where the ray meets the stone (the floor mirror's rectangle in y = 0), if it does.
fn hit_stone(origin: Vec3, direction: Vec3) -> Option<f32> {
    let (min, max) = (FLOOR_MIRROR_MIN, FLOOR_MIRROR_MAX);
    hit_y0_rect(origin, direction, min.x..=max.x, min.z..=max.z)
}

fn hit_cube(origin: Vec3, direction: Vec3, centre: Vec3, size: f32) -> Option<f32> {
    let half = Vec3::splat(size / 2.0);
    hit_box(origin, direction, centre - half, centre + half)
}

/// What a pixel of the stone sees, from the scene's dimensions alone.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Seen {
    /// The crate, with the stone behind it.
    CrateOverStone,
    /// The stone with nothing in front of it; and whether the ray, continued below the floor,
    /// meets the wire-fence crate's mirror image.
    Stone {
        fence_image: bool,
    },
    Other,
}

fn seen(x: u32, y: u32) -> Seen {
    let (origin, direction) = VIEW.ray(x, y);
    let Some(stone) = hit_stone(origin, direction) else {
        return Seen::Other;
    };
    let skull = passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.6);
    let crate_box = hit_cube(origin, direction, CRATE_CENTRE, CRATE_SIZE);
    let fence = hit_cube(origin, direction, FENCE_CENTRE, FENCE_SIZE);
    match (crate_box, skull, fence) {
        (Some(c), false, None) if c < stone => Seen::CrateOverStone,
        (None, false, None) => {
            let image = FENCE_CENTRE * Vec3::new(1.0, -1.0, 1.0);
            let skull_image = SKULL_CENTRE * Vec3::new(1.0, -1.0, 1.0);
            let hidden = passes_near(origin, direction, skull_image, SKULL_SIZE * 0.6);
            let fence_image = hit_cube(origin, direction, image, FENCE_SIZE).is_some();
            match (fence_image, hidden) {
                (true, true) => Seen::Other,
                _ => Seen::Stone { fence_image },
            }
        }
        _ => Seen::Other,
    }
}

/// The pixels that see `what`, away from the region's edges.
fn pixels(what: Seen) -> Vec<(u32, u32)> {
    let pixels: Vec<_> = VIEW
        .pixels()
        .filter(|&(x, y)| seen(x, y) == what && VIEW.inside_region(x, y, seen))
        .collect();
    assert!(
        pixels.len() > 100,
        "only {} pixels see {what:?}",
        pixels.len()
    );
    pixels
}

/// The largest difference of any channel between two pictures at a pixel.
fn difference(a: &Capture, b: &Capture, (x, y): (u32, u32)) -> u8 {
    let (p, q) = (a.color.get_pixel(x, y).0, b.color.get_pixel(x, y).0);
    (0..3).map(|c| p[c].abs_diff(q[c])).max().unwrap_or(0)
}

#[test]
fn exercise_1_marks_the_stone_behind_the_crate_and_veils_the_crate() {
    let solved = exercise::<exercise_1::Solution>(workbook::Stop::Last);
    let lesson = lesson();
    let behind_crate = pixels(Seen::CrateOverStone);
    let mut changed = 0;
    for &(x, y) in &behind_crate {
        // Marked without the depth test: the crate no longer keeps the mark out ...
        assert_eq!(solved.stencil_at(x, y), Some(1), "not marked at ({x}, {y})");
        // ... where the lesson's mark fails behind the crate.
        assert_eq!(
            lesson.stencil_at(x, y),
            Some(0),
            "the lesson marked ({x}, {y})"
        );
        changed += usize::from(difference(&solved, &lesson, (x, y)) > 10);
    }
    // BLEND_OVER_MARK tests no depth: the stone is blended over the crate wherever it is marked.
    assert!(
        changed * 10 > behind_crate.len() * 9,
        "only {changed} of {} crate pixels changed",
        behind_crate.len()
    );
    // The stone that nothing stands in front of is marked and drawn as before.
    for pixel in pixels(Seen::Stone { fence_image: false }) {
        assert!(
            difference(&solved, &lesson, pixel) <= 2,
            "{pixel:?} changed"
        );
    }
}

#[test]
fn exercise_2_shows_the_fence_image_in_the_stone_and_changes_nothing_else() {
    let solved = exercise::<exercise_2::Solution>(workbook::Stop::Last);
    let lesson = lesson();
    // Where the continued ray meets the fence's image: the wires show (the holes do not change).
    let image = pixels(Seen::Stone { fence_image: true });
    let changed = |picture: &Capture, from: &Capture| {
        let count = image.iter().filter(|&&p| difference(picture, from, p) > 10);
        count.count() as f32 / image.len() as f32
    };
    assert!(
        changed(&solved, &lesson) > 0.3,
        "{:.2} of the image changed",
        changed(&solved, &lesson)
    );
    // Until the fence's own steps (after step 4, "draw the reflection") the solution draws what
    // the lesson draws: by the same measure none of those pixels has changed yet, so the change
    // above is the fence's.
    let lesson_before = shots::render("floor-mirror", &[], |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.stop = workbook::Stop::After(4);
    })
    .unwrap();
    let solved_before = exercise::<exercise_2::Solution>(workbook::Stop::After(4));
    assert_eq!(changed(&solved_before, &lesson_before), 0.0);
    // Everywhere else on the stone, the picture is the lesson's.
    for pixel in pixels(Seen::Stone { fence_image: false }) {
        assert!(
            difference(&solved, &lesson, pixel) <= 2,
            "{pixel:?} changed"
        );
    }
    // The fence's image step draws only inside the mark.
    let steps = |n| exercise::<exercise_2::Solution>(workbook::Stop::After(n));
    let (before, after) = (steps(4), steps(5));
    let drawn = changed_only_inside_mark(&before, &after, 1).unwrap();
    assert!(drawn > 500, "the fence's image drew {drawn} pixels");
}

/// One frame at the book's size, 1280×720: no wgpu error.
fn renders_full_size<L: Lesson>() {
    let request = Request::new::<L>(&[] as &[&str]).unwrap();
    let capture = headless::render::<L>(&request).unwrap();
    assert_eq!(capture.color.dimensions(), (1280, 720));
}

#[test]
fn the_exercises_render_at_1280x720() {
    renders_full_size::<exercise_1::Solution>();
    renders_full_size::<exercise_2::Solution>();
}
