//! Lesson 14's exercises, against the lesson's own counts and the rays cast to the light: counting
//! by parity leaves the last bit of the lesson's count (0 or 255), and so calls lit the points that
//! lie in two volumes; the sun's counts are 0 exactly where a ray along its direction is free, and
//! its shadows are not the point light's.

use crate::shadow_volume::{Room, SIZE, counts, judge_counts};
use lessons::exercises::shadow_volume::{exercise_1, exercise_2};
use lessons::shadow_volume::ShadowVolume;
use workbook::app::headless::{self, Request};
use workbook::{Lesson, Stop};

/// The stencil of lesson `L` (an exercise's solution) after "count the volumes", its third step,
/// from the lesson's pose.
fn counts_of<L: Lesson>() -> Vec<u8> {
    let mut request = Request::new::<L>(&[] as &[&str]).unwrap();
    (request.width, request.height) = SIZE;
    request.camera = ShadowVolume::CAMERA;
    request.read_stencil = true;
    request.stop = Stop::After(3);
    headless::render::<L>(&request).unwrap().stencil.unwrap()
}

/// Invert flips every bit: after n faces the stencil is 255 if n is odd, 0 if even — the parity of
/// the lesson's count, since +1 and −1 both change it. Where the lesson counts 2 (the light's ray
/// crosses the skull twice, or the skull and the crate), parity says 0: lit, wrongly.
#[test]
fn parity_keeps_the_counts_last_bit_and_loses_the_twos() {
    let parity = counts_of::<exercise_1::Solution>();
    let lesson = counts(&[], ShadowVolume::CAMERA);
    let odd = |count: u8| if count % 2 == 1 { 255 } else { 0 };
    let differ = (parity.iter().zip(&lesson))
        .filter(|&(&p, &c)| p != odd(c))
        .count();
    assert_eq!(differ, 0, "{differ} pixels are not the parity of the count");
    let in_shadow = lesson.iter().filter(|&&c| c != 0).count();
    let twos = lesson.iter().filter(|&&c| c == 2).count();
    let (judged, wrong) = judge_counts(
        &Room::new(lessons::shadow_volume::KEY),
        &parity,
        ShadowVolume::CAMERA,
    );
    eprintln!(
        "parity: {in_shadow} pixels in shadow, {twos} of them counted 2 and lit by parity; \
         {wrong} of {judged} judged pixels disagree with the rays"
    );
    assert!(twos > 100, "only {twos} pixels count 2");
    assert!(
        wrong > 0,
        "parity agrees with the rays at all {judged} judged pixels"
    );
}

/// The sun's volumes, every side running to one point at infinity: the counts must be 0 exactly
/// where a ray from the visible point against the sun's direction meets neither the skull nor the
/// crate; and they are not the lesson's, whose light is a point. Fewer pixels are judged than in
/// the lesson's own test: the sun shines from behind the wall, whose face (and the mirror's) it
/// does not light.
#[test]
fn the_suns_shadows_are_where_its_rays_are_blocked() {
    let sun = counts_of::<exercise_2::Solution>();
    let room = Room::new(exercise_2::SUN);
    let (judged, wrong) = judge_counts(&room, &sun, ShadowVolume::CAMERA);
    let lesson = counts(&[], ShadowVolume::CAMERA);
    let moved = (sun.iter().zip(&lesson))
        .filter(|&(&s, &l)| (s != 0) != (l != 0))
        .count();
    eprintln!(
        "the sun: {wrong} of {judged} judged pixels disagree; {moved} pixels in shadow under one \
         light and not the other"
    );
    assert!(judged > 3_000, "only {judged} pixels judged");
    assert_eq!(wrong, 0, "{wrong} of {judged} pixels disagree");
    assert!(
        moved > 2_000,
        "only {moved} pixels differ from the point light's"
    );
}
