//! Lesson 13, by the counts read back: each pixel's count is the number of the room's surfaces its
//! ray enters (every fragment), or of those nearer than all drawn before them (the depth test, in
//! the drawing order), computed on the CPU from the room's dimensions; the paint gives each level
//! one colour of its own; the additive way is as bright as the count; and 64 rooms stacked count
//! 64 times as much, clamped at 255 or gone round past it.

use glam::Vec3;
use workbook::app::headless::{self, Capture, Request};
use workbook::gpu::linear_to_srgb;
use workbook::room::camera::BOOK_POSE;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, FENCE_CENTRE, FENCE_SIZE, FLOOR_DEPTH, MIRROR_MAX, MIRROR_MIN,
    SKULL_CENTRE, SKULL_SIZE, WALL_HALF_WIDTH, WALL_HEIGHT, WALL_THICKNESS, WATER_MAX, WATER_MIN,
};
use workbook::{Lesson, Show, Stop};
use workbook_tests::geometry::{View, hit_box, hit_y0_rect, hit_z0_rect, passes_near};
use workbook_tests::shots;

pub const VIEW: View = View::new(BOOK_POSE, 320, 180);

fn render(settings: &[&str], stop: Stop) -> Capture {
    shots::render("depth-complexity", settings, |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.read_stencil = true;
        request.stop = stop;
        request.show = Show::Color;
    })
    .unwrap()
}

/// The counts: the stencil after "count the fragments".
pub fn counts(settings: &[&str]) -> Vec<u8> {
    render(settings, Stop::After(2)).stencil.unwrap()
}

/// The counts of lesson `L` (an exercise's solution), after its second step.
pub fn counts_of<L: Lesson>() -> Vec<u8> {
    let mut request = Request::new::<L>(&[] as &[&str]).unwrap();
    (request.width, request.height) = (VIEW.width, VIEW.height);
    request.read_stencil = true;
    request.stop = Stop::After(2);
    headless::render::<L>(&request).unwrap().stencil.unwrap()
}

/// Where the ray enters each surface of the room, in the order the lesson draws them (floor, wall,
/// mirror, crate; the water last), as distances along it; `None` for a pixel not judged (its ray
/// passes near the skull, or through the wire fence, whose two sides' order in its mesh decides the
/// depth test).
fn hits(x: u32, y: u32) -> Option<[Option<f32>; 7]> {
    let (origin, direction) = VIEW.ray(x, y);
    let fence = Vec3::splat(FENCE_SIZE / 2.0);
    let near_skull = passes_near(origin, direction, SKULL_CENTRE, SKULL_SIZE * 0.9);
    if near_skull
        || hit_box(
            origin,
            direction,
            FENCE_CENTRE - fence,
            FENCE_CENTRE + fence,
        )
        .is_some()
    {
        return None;
    }
    let (w, h, t) = (WALL_HALF_WIDTH, WALL_HEIGHT, WALL_THICKNESS);
    let (a, b) = (MIRROR_MIN, MIRROR_MAX);
    // The floor and the mirror face the room: seen from behind, they are culled.
    let floor =
        hit_y0_rect(origin, direction, -w..=w, 0.0..=FLOOR_DEPTH).filter(|_| direction.y < 0.0);
    let blocks = [
        (Vec3::new(-w, 0.0, -t), Vec3::new(a.x, b.y, 0.0)),
        (Vec3::new(b.x, 0.0, -t), Vec3::new(w, b.y, 0.0)),
        (Vec3::new(-w, b.y, -t), Vec3::new(w, h, 0.0)),
    ]
    .map(|(min, max)| hit_box(origin, direction, min, max));
    let mirror = hit_z0_rect(origin, direction, a, b).filter(|_| direction.z < 0.0);
    let half = Vec3::splat(CRATE_SIZE / 2.0);
    let crate_box = hit_box(origin, direction, CRATE_CENTRE - half, CRATE_CENTRE + half);
    // The water: a quad at y = 0.25, drawn from both sides.
    let lifted = origin - Vec3::Y * WATER_MIN.y;
    let water = hit_y0_rect(
        lifted,
        direction,
        WATER_MIN.x..=WATER_MAX.x,
        WATER_MIN.z..=WATER_MAX.z,
    );
    Some([
        floor, blocks[0], blocks[1], blocks[2], mirror, crate_box, water,
    ])
}

/// The distances along the ray of the surfaces it enters, in the order the lesson draws them.
pub fn surfaces(x: u32, y: u32) -> Option<Vec<f32>> {
    Some(hits(x, y)?.into_iter().flatten().collect())
}

/// The same surfaces in the reverse order of the objects: the water, the crate, the mirror, the
/// wall (its three blocks in the order its mesh holds them), the floor.
pub fn surfaces_objects_reversed(x: u32, y: u32) -> Option<Vec<f32>> {
    let hits = hits(x, y)?;
    Some(
        [6, 5, 4, 1, 2, 3, 0]
            .iter()
            .filter_map(|&i| hits[i])
            .collect(),
    )
}

/// How many boxes (the wall's three blocks, the crate) the ray enters: each also has a face where
/// it leaves, a back face.
pub fn boxes_entered(x: u32, y: u32) -> Option<u8> {
    let hits = hits(x, y)?;
    Some([1, 2, 3, 5].iter().filter(|&&i| hits[i].is_some()).count() as u8)
}

/// The count `surfaces` predicts: all of them, or those nearer than every one drawn before.
fn predicted(x: u32, y: u32, every: bool) -> Option<u8> {
    let hits = surfaces(x, y)?;
    if every {
        return Some(hits.len() as u8);
    }
    Some(passing(hits))
}

/// How many of the surfaces met in this order pass the depth test `Less`: those nearer than every
/// one before them.
pub fn passing(hits: impl IntoIterator<Item = f32>) -> u8 {
    let mut nearest = f32::INFINITY;
    hits.into_iter()
        .filter(|&t| {
            let passes = t < nearest;
            nearest = nearest.min(t);
            passes
        })
        .count() as u8
}

fn check_counts(settings: &[&str], every: bool) -> usize {
    let counts = counts(settings);
    let predict = |x, y| predicted(x, y, every);
    let mut judged = 0;
    for (x, y) in VIEW.pixels() {
        let Some(expected) = predict(x, y) else {
            continue;
        };
        if !VIEW.inside_region(x, y, predict) {
            continue;
        }
        let got = counts[(y * VIEW.width + x) as usize];
        assert_eq!(got, expected, "{settings:?}: pixel ({x}, {y})");
        judged += 1;
    }
    judged
}

#[test]
fn every_fragment_counts_once_for_each_surface_its_ray_enters() {
    let judged = check_counts(&[], true);
    assert!(judged > 30_000, "only {judged} pixels judged");
}

#[test]
fn with_the_depth_test_only_the_nearer_surfaces_count() {
    let judged = check_counts(&["count=passed-depth"], false);
    assert!(judged > 30_000, "only {judged} pixels judged");
    // The counterpart: the two questions differ (behind the crate, the wall counts only first).
    let (every, passed) = (counts(&[]), counts(&["count=passed-depth"]));
    let differ = every.iter().zip(&passed).filter(|(a, b)| a != b).count();
    assert!(differ > 1_000, "only {differ} pixels differ");
}

/// Each level painted one colour, a colour no other level has: level 0 black, 8 and more white.
#[test]
fn each_level_is_painted_its_own_colour() {
    let capture = render(&["stack=1"], Stop::Last);
    let stencil = capture.stencil.as_ref().unwrap();
    let mut colours: Vec<Option<[u8; 4]>> = vec![None; 9];
    for (i, &value) in stencil.iter().enumerate() {
        let level = value.min(8) as usize;
        let colour = capture.color.as_raw()[i * 4..i * 4 + 4].try_into().unwrap();
        match colours[level] {
            None => colours[level] = Some(colour),
            Some(seen) => assert_eq!(seen, colour, "level {level} at pixel {i}"),
        }
    }
    assert_eq!(colours[0], Some([0, 0, 0, 255]));
    let painted: Vec<[u8; 4]> = colours.iter().flatten().copied().collect();
    assert!(painted.len() >= 5, "only levels {colours:?}");
    for (i, a) in painted.iter().enumerate() {
        assert!(!painted[i + 1..].contains(a), "two levels share {a:?}");
    }
}

/// The additive way: an eighth of white per fragment, in linear light: the count again, up to 8.
#[test]
fn the_blended_count_is_the_stencil_count() {
    let counts = counts(&[]);
    let blended = render(&["way=blend"], Stop::Last);
    for (i, &count) in counts.iter().enumerate() {
        let expected = linear_to_srgb(count.min(8) as f32 / 8.0);
        let got = blended.color.as_raw()[i * 4];
        assert!(
            got.abs_diff(expected) <= 1,
            "pixel {i}: count {count}, grey {got}, not {expected}"
        );
    }
}

/// 64 rooms: each count 64 times the room's, clamped at 255, or taken modulo 256.
#[test]
fn past_255_the_count_clamps_or_wraps() {
    let once = counts(&[]);
    for (increment, expected) in [
        (
            "increment=clamp",
            (|c: u32| (64 * c).min(255)) as fn(u32) -> u32,
        ),
        ("increment=wrap", |c: u32| (64 * c) % 256),
    ] {
        let stacked = counts(&["stack=64", increment]);
        for (i, (&c, &got)) in once.iter().zip(&stacked).enumerate() {
            assert_eq!(
                got as u32,
                expected(c as u32),
                "{increment}: pixel {i}, once {c}"
            );
        }
    }
}
