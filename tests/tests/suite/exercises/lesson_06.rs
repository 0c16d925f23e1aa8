//! Lesson 6's exercises, judged by blend values computed from separate renders of the layers (the
//! reflection without glass: lesson 5's picture; the glass alone: `blend=off`), in linear light as
//! the GPU blends into an sRGB target: the glass drawn first is blended over the room as the mark left it
//! (the sky, mostly), not over the reflection; the tinted glass mixes each channel by its own constant.

use workbook::app::headless::{self, Capture, Request};
use workbook::{Lesson, Stop};

use lessons::exercises::transparent_mirror::{exercise_1, exercise_2};
use lessons::transparent_mirror;
use lessons::winding_fix;

use super::blend;

const W: u32 = 320;
const H: u32 = 180;

fn render<L: Lesson>(settings: &[&str]) -> Capture {
    render_until::<L>(settings, Stop::Last)
}

fn render_until<L: Lesson>(settings: &[&str], stop: Stop) -> Capture {
    let mut request = Request::new::<L>(settings).unwrap();
    (request.width, request.height) = (W, H);
    request.read_stencil = true;
    request.stop = stop;
    headless::render::<L>(&request).unwrap()
}

/// What the glass lies over when nothing is reflected: the lesson's picture after its mark (the
/// sky, and the sides of the wall's opening seen through the glass).
fn unreflected() -> Capture {
    render_until::<transparent_mirror::TransparentMirror>(&[], Stop::After(3))
}

/// Pixels well inside the mark (the pixel and its 8 neighbours hold 1).
fn mirror_pixels(capture: &Capture) -> Vec<(u32, u32)> {
    let marked = |x: u32, y: u32| capture.stencil_at(x, y) == Some(1);
    (1..H - 1)
        .flat_map(|y| (1..W - 1).map(move |x| (x, y)))
        .filter(|&(x, y)| (0..3).all(|dy| (0..3).all(|dx| marked(x + dx - 1, y + dy - 1))))
        .collect()
}

/// How many channels of `pixels` are more than one step from `expected(x, y)`.
fn misses(
    capture: &Capture,
    pixels: &[(u32, u32)],
    expected: impl Fn(u32, u32) -> [u8; 3],
) -> usize {
    let mut misses = 0;
    for &(x, y) in pixels {
        let got = capture.color.get_pixel(x, y).0;
        let want = expected(x, y);
        misses += (0..3).filter(|&c| got[c].abs_diff(want[c]) > 1).count();
    }
    misses
}

fn rgb(capture: &Capture, x: u32, y: u32) -> [u8; 3] {
    let [r, g, b, _] = capture.color.get_pixel(x, y).0;
    [r, g, b]
}

#[test]
fn glass_first_is_blended_over_the_unreflected_room() {
    let glass = render::<transparent_mirror::TransparentMirror>(&["blend=off"]);
    let under = unreflected();
    let exercise = render::<exercise_1::Solution>(&[]);
    let pixels = mirror_pixels(&exercise);
    assert!(pixels.len() > 3000, "only {} mirror pixels", pixels.len());
    let over_room = |x, y| blend(rgb(&glass, x, y), rgb(&under, x, y), [0.5; 3]);
    assert_eq!(misses(&exercise, &pixels, over_room), 0);
}

/// The counterpart: the lesson's glass, drawn last, lies over the reflected skull wherever the
/// skull's image is.
#[test]
fn the_lessons_glass_is_blended_over_the_reflection() {
    let glass = render::<transparent_mirror::TransparentMirror>(&["blend=off"]);
    let under = unreflected();
    let lesson = render::<transparent_mirror::TransparentMirror>(&[]);
    let pixels = mirror_pixels(&lesson);
    let over_room = |x, y| blend(rgb(&glass, x, y), rgb(&under, x, y), [0.5; 3]);
    let missed = misses(&lesson, &pixels, over_room);
    assert!(
        missed > 500,
        "only {missed} channels differ from glass over sky"
    );
}

fn tint() -> [f32; 3] {
    let t = exercise_2::TINT;
    [t.r as f32, t.g as f32, t.b as f32]
}

#[test]
fn the_tinted_glass_mixes_each_channel_by_its_constant() {
    let reflection = render::<winding_fix::WindingFix>(&[]);
    let glass = render::<transparent_mirror::TransparentMirror>(&["blend=off"]);
    let exercise = render::<exercise_2::Solution>(&[]);
    let pixels = mirror_pixels(&reflection);
    assert!(pixels.len() > 3000, "only {} mirror pixels", pixels.len());
    let tinted = |x, y| blend(rgb(&glass, x, y), rgb(&reflection, x, y), tint());
    assert_eq!(misses(&exercise, &pixels, tinted), 0);
}

/// The counterpart: the lesson mixes every channel by the one alpha, 0.5.
#[test]
fn the_lessons_glass_is_not_tinted() {
    let reflection = render::<winding_fix::WindingFix>(&[]);
    let glass = render::<transparent_mirror::TransparentMirror>(&["blend=off"]);
    let lesson = render::<transparent_mirror::TransparentMirror>(&[]);
    let pixels = mirror_pixels(&reflection);
    let tinted = |x, y| blend(rgb(&glass, x, y), rgb(&reflection, x, y), tint());
    let missed = misses(&lesson, &pixels, tinted);
    assert!(
        missed > pixels.len(),
        "only {missed} channels differ from the tint"
    );
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
