//! Lesson 14, against rays cast to the light: a pixel's count (the stencil after "count the
//! volumes") is not 0 exactly where the ray from its visible point to the key light meets the skull
//! or the crate — computed on the CPU from the room's dimensions, the skull's mesh and the light,
//! never from a render. Z-fail agrees from outside the shadows and from inside one; each wrong
//! picture's count (z-pass with the eye in a shadow, no caps, clamping in one pass) disagrees; and
//! two-sided stencil counts exactly as two passes do.

use glam::Vec3;
use lessons::shadow_volume::{IN_THE_SKULLS_SHADOW, KEY, ShadowVolume};
use workbook::math::shadow::LightSource;
use workbook::room::camera::Camera;
use workbook::room::scene::{CRATE_CENTRE, CRATE_SIZE};
use workbook::{Lesson, Show, Stop};
use workbook_tests::geometry::{RoomRays, View, hit_box};
use workbook_tests::shots;

/// The size the counts are read at.
pub const SIZE: (u32, u32) = (320, 180);

/// The room as rays see it (the lesson draws floor, wall, mirror, crate and skull), lit by a key
/// light.
pub struct Room {
    rays: RoomRays,
    light: LightSource,
}

impl Room {
    pub fn new(light: LightSource) -> Self {
        Self {
            rays: RoomRays::new(),
            light,
        }
    }

    /// The way from `point` to the light, and how far the light is.
    fn to_light(&self, point: Vec3) -> (Vec3, f32) {
        match self.light {
            LightSource::Point { position } => {
                ((position - point).normalize(), point.distance(position))
            }
            LightSource::Directional { direction } => (-direction.normalize(), f32::MAX),
        }
    }

    /// Whether the key light is hidden from `point` by the skull or the crate (the solids that
    /// cast shadows).
    fn in_shadow(&self, point: Vec3, normal: Vec3) -> bool {
        let start = point + normal * 1e-3;
        let (direction, distance) = self.to_light(start);
        let half = Vec3::splat(CRATE_SIZE / 2.0);
        let crate_box = hit_box(start, direction, CRATE_CENTRE - half, CRATE_CENTRE + half);
        crate_box.is_some_and(|d| d < distance)
            || self.rays.skull.hit(start, direction, distance).is_some()
    }

    /// What the rays through pixel (x, y) say: whether its visible point is in shadow, where the
    /// pixel is judged — not the sky, not a surface turned (almost) away from the light (the
    /// volume's near cap lies on those), and not an edge: rays through the pixel's four corners
    /// meet the same surface and agree.
    pub fn judge(&self, view: &View, x: u32, y: u32) -> Option<bool> {
        let look = |dx: f32, dy: f32| {
            let (origin, direction) = view.ray_at(x as f32 + dx, y as f32 + dy);
            let seen = self.rays.see(origin, direction)?;
            (seen.normal.dot(self.to_light(seen.point).0) > 0.15)
                .then(|| (seen.surface, self.in_shadow(seen.point, seen.normal)))
        };
        let centre = look(0.5, 0.5)?;
        let corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
        corners
            .iter()
            .all(|&(dx, dy)| look(dx, dy) == Some(centre))
            .then_some(centre.1)
    }
}

/// The counts: the stencil after "count the volumes" (step 3), seen from `camera`.
pub fn counts(settings: &[&str], camera: Camera) -> Vec<u8> {
    let capture = shots::render(ShadowVolume::NAME, settings, |request| {
        (request.width, request.height) = SIZE;
        request.camera = camera;
        request.read_stencil = true;
        request.stop = Stop::After(3);
        request.show = Show::Color;
    })
    .unwrap();
    capture.stencil.unwrap()
}

/// How many pixels are judged, and at how many of them the count and the rays disagree.
fn disagreements(room: &Room, settings: &[&str], camera: Camera) -> (usize, usize) {
    let (judged, wrong) = judge_counts(room, &counts(settings, camera), camera);
    eprintln!("{settings:?} at {camera:?}: {wrong} of {judged} judged pixels disagree");
    (judged, wrong)
}

/// How many pixels of `counts` (at [`SIZE`], seen from `camera`) are judged, and at how many the
/// count and the rays disagree.
pub fn judge_counts(room: &Room, counts: &[u8], camera: Camera) -> (usize, usize) {
    let view = View::new(camera, SIZE.0, SIZE.1);
    let (mut judged, mut wrong) = (0, 0);
    for y in 0..SIZE.1 {
        for x in 0..SIZE.0 {
            let Some(in_shadow) = room.judge(&view, x, y) else {
                continue;
            };
            judged += 1;
            let count = counts[(y * SIZE.0 + x) as usize];
            if (count != 0) != in_shadow {
                wrong += 1;
            }
        }
    }
    (judged, wrong)
}

#[test]
fn the_count_is_not_zero_exactly_where_a_ray_to_the_light_is_blocked() {
    let room = Room::new(KEY);
    let cases: [(&[&str], Camera); 5] = [
        (&[], ShadowVolume::CAMERA),
        (&["method=z-pass"], ShadowVolume::CAMERA),
        (
            &["faces=two-passes", "increment=clamp"],
            ShadowVolume::CAMERA,
        ),
        (&[], IN_THE_SKULLS_SHADOW),
        (&["faces=two-passes"], IN_THE_SKULLS_SHADOW),
    ];
    for (settings, camera) in cases {
        let (judged, wrong) = disagreements(&room, settings, camera);
        // Most of the picture is judged (edges, the sky and surfaces turned from the light are not).
        assert!(
            judged > 5_000,
            "{settings:?} at {camera:?}: only {judged} pixels judged"
        );
        assert_eq!(
            wrong, 0,
            "{settings:?} at {camera:?}: {wrong} of {judged} pixels disagree"
        );
    }
}

#[test]
fn each_wrong_count_disagrees_with_the_rays() {
    let room = Room::new(KEY);
    // (settings, camera, the least share of the judged pixels that must disagree)
    let cases: [(&[&str], Camera, f64); 3] = [
        // The eye in the skull's shadow: z-pass misses the faces behind the near plane, and every
        // pixel whose ray starts in the volume is off by one.
        (&["method=z-pass"], IN_THE_SKULLS_SHADOW, 0.5),
        // Without caps z-fail counts the sides behind a point, but not the far cap that closes
        // them: the crate, lit, is found in shadow.
        (&["caps=off"], ShadowVolume::CAMERA, 0.01),
        // One pass, clamping: a −1 met before its +1 is lost at 0, and the +1 leaves a shadow
        // where there is none (beside the crate's).
        (&["increment=clamp"], ShadowVolume::CAMERA, 0.01),
    ];
    for (settings, camera, share) in cases {
        let (judged, wrong) = disagreements(&room, settings, camera);
        assert!(
            wrong as f64 >= share * judged as f64,
            "{settings:?} at {camera:?}: only {wrong} of {judged} pixels disagree"
        );
    }
}

#[test]
fn the_books_pose_in_the_shadow_is_the_lessons() {
    let pose = Camera::parse(shots::IN_THE_SKULLS_SHADOW).unwrap();
    assert_eq!(pose, IN_THE_SKULLS_SHADOW);
}

#[test]
fn two_sided_stencil_counts_exactly_as_two_passes() {
    for method in ["method=z-fail", "method=z-pass"] {
        for camera in [ShadowVolume::CAMERA, IN_THE_SKULLS_SHADOW] {
            let one = counts(&[method], camera);
            let two = counts(&[method, "faces=two-passes"], camera);
            let differ = one.iter().zip(&two).filter(|(a, b)| a != b).count();
            assert_eq!(differ, 0, "{method} at {camera:?}: {differ} counts differ");
        }
    }
}
