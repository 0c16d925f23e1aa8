//! Lesson 2's exercises: the stencil buffer read back and compared with the shapes' geometry on the
//! CPU — the count of discs covering each pixel (the Venn diagram), and the porthole and bullseye
//! marked in the other order.

use workbook::Lesson;
use workbook::Stop;
use workbook::app::headless::{self, Capture, Request};
use workbook::glam::Vec2;
use workbook::room::scene::CLEAR_SRGB;

use lessons::exercises::stencil_basics::{exercise_1, exercise_2};
use lessons::stencil_basics;

const W: u32 = 320;
const H: u32 = 180;

fn render<L: Lesson>(settings: &[&str], stop: Stop) -> Capture {
    let mut request = Request::new::<L>(settings).unwrap();
    (request.width, request.height) = (W, H);
    request.read_stencil = true;
    request.stop = stop;
    headless::render::<L>(&request).unwrap()
}

/// The centre of pixel (x, y) in the shapes' screen units (the screen 2 high, x scaled by the
/// aspect ratio).
fn screen(x: u32, y: u32) -> Vec2 {
    let aspect = W as f32 / H as f32;
    Vec2::new(
        ((x as f32 + 0.5) / W as f32 * 2.0 - 1.0) * aspect,
        1.0 - (y as f32 + 0.5) / H as f32 * 2.0,
    )
}

/// How many of the exercise's discs cover the pixel.
fn discs_over(x: u32, y: u32) -> u8 {
    let p = screen(x, y);
    let inside = |centre: &Vec2| p.distance(*centre) < exercise_1::RADIUS;
    exercise_1::CENTRES.iter().filter(|c| inside(c)).count() as u8
}

/// The lesson's pattern: 2 in the bullseye (radius 0.35), 1 in the ring (to 0.8), 0 outside.
fn porthole_and_bullseye(x: u32, y: u32) -> u8 {
    match screen(x, y).length() {
        r if r < 0.35 => 2,
        r if r < 0.8 => 1,
        _ => 0,
    }
}

/// The pixels whose 5×5 neighbourhood `classify` gives one answer (edges may go either way).
fn clearly_inside(classify: fn(u32, u32) -> u8) -> impl Iterator<Item = (u32, u32, u8)> {
    (2..H - 2).flat_map(move |y| {
        (2..W - 2).filter_map(move |x| {
            let here = classify(x, y);
            let same = (0..5).all(|dy| (0..5).all(|dx| classify(x + dx - 2, y + dy - 2) == here));
            same.then_some((x, y, here))
        })
    })
}

#[test]
fn each_pixel_counts_the_discs_and_the_room_shows_where_the_count_is_the_reference() {
    for reference in [1u8, 2, 3] {
        let setting = format!("reference={reference}");
        let capture = render::<exercise_1::Solution>(&[setting.as_str()], Stop::Last);
        let mut seen = [0usize; 4];
        let mut room = 0;
        for (x, y, count) in clearly_inside(discs_over) {
            assert_eq!(capture.stencil_at(x, y), Some(count), "pixel ({x}, {y})");
            seen[count as usize] += 1;
            let sky = capture.color.get_pixel(x, y).0[..3] == CLEAR_SRGB;
            if count != reference {
                assert!(
                    sky,
                    "{setting}: pixel ({x}, {y}) covered {count} times was drawn"
                );
            }
            room += usize::from(!sky && count == reference);
        }
        assert!(seen.iter().all(|&n| n > 300), "{seen:?}");
        assert!(room > 300, "{setting}: only {room} pixels show the room");
    }
}

/// The counterpart: the lesson's marks (Replace) hold no count: where three discs overlap the
/// lesson's buffer holds 2 (the bullseye), not 3, and nowhere does it hold 3.
#[test]
fn the_lessons_marks_do_not_count() {
    let capture = render::<stencil_basics::StencilBasics>(&[], Stop::Last);
    let wrong = clearly_inside(discs_over)
        .filter(|&(x, y, count)| capture.stencil_at(x, y) != Some(count))
        .count();
    assert!(wrong > 1000, "only {wrong} pixels differ from the count");
    assert!(capture.stencil.unwrap().iter().all(|&v| v < 3));
}

#[test]
fn bullseye_first_then_porthole_where_unmarked_gives_the_lessons_buffer() {
    let capture = render::<exercise_2::Solution>(&[], Stop::Last);
    let mut seen = [0usize; 3];
    for (x, y, value) in clearly_inside(porthole_and_bullseye) {
        assert_eq!(capture.stencil_at(x, y), Some(value), "pixel ({x}, {y})");
        seen[value as usize] += 1;
    }
    assert!(seen.iter().all(|&n| n > 2000), "{seen:?}");
    // The bullseye really is marked first: after step 2, 2 inside and 0 in the ring.
    let first = render::<exercise_2::Solution>(&[], Stop::After(2));
    for (x, y, value) in clearly_inside(porthole_and_bullseye) {
        let expected = if value == 2 { 2 } else { 0 };
        assert_eq!(first.stencil_at(x, y), Some(expected), "pixel ({x}, {y})");
    }
}

/// The counterpart: in the exercise's order, the lesson's MARK_SHAPE for the porthole
/// (`porthole-compare=always`) overwrites the bullseye with 1.
#[test]
fn in_that_order_the_lessons_mark_wipes_out_the_bullseye() {
    let capture = render::<exercise_2::Solution>(&["porthole-compare=always"], Stop::Last);
    for (x, y, value) in clearly_inside(porthole_and_bullseye) {
        let expected = value.min(1);
        assert_eq!(capture.stencil_at(x, y), Some(expected), "pixel ({x}, {y})");
    }
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
