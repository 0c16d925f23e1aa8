//! Lesson 2: the shapes land in the stencil buffer where their geometry says, and the room is drawn
//! exactly where the stencil test passes.

use workbook::app::headless::Capture;
use workbook::room::scene::CLEAR_SRGB;
use workbook_tests::shots;

const W: u32 = 320;
const H: u32 = 180;

/// The value the shapes write at a pixel: 2 in the bullseye (radius 0.35), 1 in the porthole (0.8),
/// 0 outside. Screen units: the screen is 2 high and the x axis is scaled by the aspect ratio.
fn shape_value(x: u32, y: u32) -> u8 {
    let aspect = W as f32 / H as f32;
    let sx = ((x as f32 + 0.5) / W as f32 * 2.0 - 1.0) * aspect;
    let sy = 1.0 - (y as f32 + 0.5) / H as f32 * 2.0;
    let r = (sx * sx + sy * sy).sqrt();
    if r < 0.35 {
        2
    } else if r < 0.8 {
        1
    } else {
        0
    }
}

/// Whether a pixel lies well inside its region (a ring of 2 pixels around each circle is skipped).
fn clearly_inside(x: u32, y: u32) -> bool {
    let here = shape_value(x, y);
    (-2i32..=2).all(|dy| {
        (-2i32..=2).all(|dx| {
            let (nx, ny) = (x as i32 + dx, y as i32 + dy);
            nx < 0
                || ny < 0
                || nx >= W as i32
                || ny >= H as i32
                || shape_value(nx as u32, ny as u32) == here
        })
    })
}

fn render(settings: &[&str]) -> Capture {
    shots::render("stencil-basics", settings, |request| {
        (request.width, request.height) = (W, H);
        request.read_stencil = true;
    })
    .unwrap()
}

#[test]
fn the_shapes_write_their_references_and_keep_leaves_them() {
    let capture = render(&[]);
    let mut checked = [0; 3];
    for y in 0..H {
        for x in 0..W {
            if clearly_inside(x, y) {
                let expected = shape_value(x, y);
                assert_eq!(capture.stencil_at(x, y), Some(expected), "pixel ({x}, {y})");
                checked[expected as usize] += 1;
            }
        }
    }
    assert!(checked.iter().all(|&n| n > 2000), "{checked:?}");
}

/// With compare=equal and reference 1 the room shows in the ring only: outside and in the bullseye
/// the sky's clear colour is left.
#[test]
fn the_room_is_drawn_only_where_the_test_passes() {
    for (settings, passes) in [
        (&["compare=equal"][..], [false, true, false]),
        (&["compare=less"], [false, false, true]),
        (&["compare=not-equal"], [true, false, true]),
        (&["compare=never"], [false, false, false]),
        // (1 & 0xfe) == (stored & 0xfe): 0 == 0 outside and in the ring, 0 != 2 in the bullseye.
        (&["read-mask=0xfe"], [true, true, false]),
    ] {
        let capture = render(settings);
        let mut room_seen = [0; 3];
        for y in 0..H {
            for x in 0..W {
                if !clearly_inside(x, y) {
                    continue;
                }
                let value = shape_value(x, y) as usize;
                let sky = capture.color.get_pixel(x, y).0[..3] == CLEAR_SRGB;
                if !passes[value] {
                    assert!(
                        sky,
                        "{settings:?}: pixel ({x}, {y}) in region {value} was drawn"
                    );
                }
                room_seen[value] += usize::from(!sky);
            }
        }
        for value in 0..3 {
            if passes[value] {
                assert!(
                    room_seen[value] > 500,
                    "{settings:?}: region {value} shows no room"
                );
            }
        }
    }
}
