//! Lesson 12's exercises, judged against the lesson's own pictures: the dimmed band is 35 % amber
//! over what `outline-depth=less` shows, exactly where `outline-depth=always` draws the band and
//! `less` does not, and the picture is `less`'s everywhere else; the crate's band is blue all round
//! the pixels that hold the crate's bit, while grown along its normals it has gaps at the corners.

use workbook_tests::shots::BEHIND_THE_CRATE;

use super::blend;
use crate::outline::{Mask, SIZE, is_amber, render, render_as, rgb};
use lessons::exercises::outline::{exercise_1, exercise_2};

fn close(a: [u8; 3], b: [u8; 3]) -> bool {
    a.iter().zip(b).all(|(&a, b)| a.abs_diff(b) <= 1)
}

#[test]
fn the_hidden_band_is_dimmed_and_the_rest_is_as_less_draws_it() {
    let camera = Some(BEHIND_THE_CRATE);
    let less = render(&["outline-depth=less"], camera);
    let always = render(&[], camera);
    let exercise = render_as::<exercise_1::Solution>(&[], camera);
    let (mut hidden, mut faults) = (0, Vec::new());
    for i in 0..(SIZE.0 * SIZE.1) as usize {
        let band_hidden = is_amber(rgb(&always, i)) && !is_amber(rgb(&less, i));
        let expected = match band_hidden {
            true => blend(
                crate::outline::AMBER,
                rgb(&less, i),
                [exercise_1::DIMMED as f32; 3],
            ),
            false => rgb(&less, i),
        };
        hidden += band_hidden as usize;
        if !close(rgb(&exercise, i), expected) {
            let (x, y) = (i as u32 % SIZE.0, i as u32 / SIZE.0);
            faults.push(format!(
                "({x}, {y}): {:?}, not {expected:?}",
                rgb(&exercise, i)
            ));
        }
    }
    // The crate hides the jaw's right side: 535 pixels of the band on lavapipe.
    assert!(hidden > 300, "only {hidden} pixels of the band are hidden");
    assert!(
        faults.is_empty(),
        "{} pixels: {:?}",
        faults.len(),
        &faults[..faults.len().min(8)]
    );
}

/// The counterpart: the lesson with `less` leaves the hidden part out, with `always` draws it at
/// full strength; neither is the exercise.
#[test]
fn the_lesson_draws_the_hidden_band_fully_or_not_at_all() {
    let camera = Some(BEHIND_THE_CRATE);
    let exercise = render_as::<exercise_1::Solution>(&[], camera);
    for settings in [&["outline-depth=less"][..], &[]] {
        let lesson = render(settings, camera);
        let differ = (0..(SIZE.0 * SIZE.1) as usize)
            .filter(|&i| rgb(&lesson, i) != rgb(&exercise, i))
            .count();
        assert!(
            differ > 300,
            "{settings:?}: only {differ} pixels differ from the exercise"
        );
    }
}

/// The crate's blue, `fs_crate_outline`'s (0, 0.3, 1) in sRGB.
const BLUE: [u8; 3] = [0, 149, 255];

/// The exterior pixels within 1.5 pixels of the crate (the pixels that hold its bit) that are not
/// blue, and the blue pixels on the crate.
fn crate_band_gaps(settings: &[&str]) -> (usize, usize) {
    let exercise = render_as::<exercise_2::Solution>(settings, None);
    let crate_bits = Mask::of(&exercise, |v| v as u32 & exercise_2::CRATE_BIT != 0);
    assert!(
        crate_bits.count() > 10_000,
        "the crate's bit at {} pixels",
        crate_bits.count()
    );
    let (exterior, distance) = (crate_bits.exterior(), crate_bits.distances(3));
    let blue = |i| close(rgb(&exercise, i), BLUE);
    let gaps = (0..distance.len())
        .filter(|&i| exterior.0[i] && distance[i] <= 1.5 && !blue(i))
        .count();
    let on_crate = (0..distance.len())
        .filter(|&i| crate_bits.0[i] && blue(i))
        .count();
    (gaps, on_crate)
}

#[test]
fn the_crate_scaled_about_its_centre_is_outlined_all_round() {
    assert_eq!(crate_band_gaps(&[]), (0, 0));
}

/// The counterpart, and the exercise's question: grown along its normals, the crate's faces part at
/// the corners.
#[test]
fn the_crate_grown_along_its_normals_tears_at_the_corners() {
    let (gaps, on_crate) = crate_band_gaps(&["crate-grow=normals"]);
    assert_eq!(on_crate, 0);
    assert!(gaps > 20, "only {gaps} pixels of gaps");
}

/// The skull's band is the lesson's: outside the crate's band, the picture is the lesson's.
#[test]
fn selecting_the_crate_leaves_the_skulls_band_alone() {
    let lesson = render(&[], None);
    let exercise = render_as::<exercise_2::Solution>(&[], None);
    let changed = (0..(SIZE.0 * SIZE.1) as usize)
        .filter(|&i| rgb(&lesson, i) != rgb(&exercise, i) && !close(rgb(&exercise, i), BLUE))
        .count();
    assert_eq!(changed, 0, "pixels changed that are not the crate's band");
}
