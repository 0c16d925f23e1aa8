//! Lesson 16, against rays: after the whole frame, the stencil at every pixel holds how many
//! doorways the camera's ray passes through — each doorway reached before anything else in the room
//! it stands in, the ray going on into the next room from the doorway (the far room is cut there) —
//! counted on the CPU from the room's dimensions and the skull's mesh, never from a render. And
//! each far room's pixels are this room drawn by itself from the camera moved back through as many
//! doorways: moving the room by the portal's transform before the camera sees it is moving the
//! camera by the inverse.

use glam::{Mat4, Vec3};
use lessons::portal::{EVENING, Portal, behind_doorways, doorway, portal, room_transform};
use workbook::app::headless::{self, Request};
use workbook::gpu::states::{self, Clip};
use workbook::room::camera::Camera;
use workbook::room::scene::FrameBinding;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, wgpu};
use workbook_tests::geometry::{RoomRays, Surface, View};
use workbook_tests::shots;

/// The size the stencil is read at.
pub const SIZE: (u32, u32) = (320, 180);

/// How many of the first `depth` doorways the ray passes, through `portal`. Each room is cast in
/// its own coordinates: the ray enters room k + 1 where it met doorway k + 1 in room k, moved as
/// room k + 1 is moved from room k (by the portal's inverse).
pub fn doorways_passed(
    rays: &RoomRays,
    portal: Mat4,
    (mut origin, mut direction): (Vec3, Vec3),
    depth: u32,
) -> u32 {
    let back = portal.inverse();
    for k in 0..depth {
        match rays.see(origin, direction) {
            Some(seen) if seen.surface == Surface::Mirror => {
                origin = back.transform_point3(seen.point);
                direction = back.transform_vector3(direction);
            }
            _ => return k,
        }
    }
    depth
}

/// The stencil of `settings` after the whole frame, and at how many of the pixels judged (whose
/// four corners' rays pass as many doorways as the centre's) it is not the number of doorways
/// passed: (judged, disagreeing).
fn disagreements(rays: &RoomRays, settings: &[&str]) -> (usize, usize) {
    let capture = shots::render(Portal::NAME, settings, |request| {
        (request.width, request.height) = SIZE;
        request.read_stencil = true;
    })
    .unwrap();
    let stencil = capture.stencil.unwrap();
    let depth = (settings.iter())
        .find_map(|s| s.strip_prefix("depth="))
        .map_or(3, |d| d.parse().unwrap());
    let view = View::new(Portal::CAMERA, SIZE.0, SIZE.1);
    let passed = |x: f32, y: f32| doorways_passed(rays, portal(), view.ray_at(x, y), depth);
    let (mut judged, mut wrong) = (0, 0);
    for y in 0..SIZE.1 {
        for x in 0..SIZE.0 {
            let (fx, fy) = (x as f32, y as f32);
            let centre = passed(fx + 0.5, fy + 0.5);
            let corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
            if corners
                .iter()
                .any(|&(dx, dy)| passed(fx + dx, fy + dy) != centre)
            {
                continue;
            }
            judged += 1;
            wrong += (stencil[(y * SIZE.0 + x) as usize] as u32 != centre) as usize;
        }
    }
    eprintln!("{settings:?}: {wrong} of {judged} judged pixels disagree");
    (judged, wrong)
}

#[test]
fn the_stencil_counts_the_doorways_each_ray_passes() {
    let rays = RoomRays::new();
    for settings in [&[][..], &["depth=1"], &["depth=4"], &["clip=oblique"]] {
        let (judged, wrong) = disagreements(&rays, settings);
        assert!(judged > 40_000, "{settings:?}: only {judged} pixels judged");
        assert_eq!(
            wrong, 0,
            "{settings:?}: {wrong} of {judged} pixels disagree"
        );
    }
}

/// The scissor rectangles leave out no pixel a far room shows: wherever the ray through a pixel's
/// centre passes k doorways, the pixel lies inside room k's rectangle. The rays judge pixel
/// centres, where the GPU samples, so a rectangle one pixel short at an edge fails. And each
/// rectangle is smaller than the one before, so that the scissor spares the rasterizer something.
#[test]
fn the_scissor_keeps_every_pixel_a_far_room_shows() {
    let rays = RoomRays::new();
    let depth = 3;
    // The book's pose, from the side, from above, and close to the wall, where doorway 1's
    // corners at the right lie behind the eye and its rectangle is the whole screen.
    const POSES: [&str; 5] = ["15,10,8", "35,10,8", "-30,25,6", "55,5,2", "65,5,2"];
    for pose in POSES {
        let view = View::new(Camera::parse(pose).unwrap(), SIZE.0, SIZE.1);
        let scissors = behind_doorways(portal(), depth, view.view_projection(), SIZE);
        let (mut seen, mut outside) = ([0; 3], [0; 3]);
        for (x, y) in (0..SIZE.1).flat_map(|y| (0..SIZE.0).map(move |x| (x, y))) {
            let passed = doorways_passed(&rays, portal(), view.ray(x, y), depth as u32) as usize;
            for k in 1..=passed {
                seen[k - 1] += 1;
                outside[k - 1] += !scissors[k - 1].contains((x, y)) as usize;
            }
        }
        eprintln!("{pose}: {scissors:?}, rooms' pixels {seen:?}, outside {outside:?}");
        assert_eq!(
            outside, [0; 3],
            "{pose}: pixels of rooms 1 to 3 outside their rectangles"
        );
        assert!(
            seen.iter().all(|&n| n > 0),
            "{pose}: rooms 1 to 3 seen by {seen:?} pixels"
        );
        if pose == POSES[0] {
            let areas: Vec<u32> = scissors
                .iter()
                .map(|rect| rect.width * rect.height)
                .collect();
            assert!(
                areas[0] < SIZE.0 * SIZE.1 / 2,
                "{pose}: rectangles {areas:?}"
            );
            assert!(
                areas[1] < areas[0] && areas[2] < areas[1],
                "{pose}: {areas:?}"
            );
        }
    }
}

/// The wrong pictures' stencils: a doorway marked before the room it stands in (what stands in
/// front of it no longer hides it), a far room left uncut (what of it stands on this side of its
/// doorway hides the next doorway), and the depth not reset behind a doorway (the doorway's own
/// surface hides the room behind it, and that room's doorway). Not with clip=oblique: the far
/// room's depths then come from another projection, which puts the doorway at depth 0, and here
/// they happen to pass.
#[test]
fn each_wrong_frame_disagrees_with_the_rays() {
    let rays = RoomRays::new();
    for settings in [
        &["order=doorway-first"][..],
        &["clip=off"],
        &["clear-behind=off"],
    ] {
        let (judged, wrong) = disagreements(&rays, settings);
        assert!(
            wrong > 100,
            "{settings:?}: only {wrong} of {judged} pixels disagree"
        );
    }
}

/// Room `K` by itself, lit by the evening light and cut at doorway `K`, seen from the lesson's
/// camera moved back through `K` doorways — computed without the portal's frame, its stencil or its
/// placed rooms.
pub struct MovedCamera<P, const K: usize> {
    through: std::marker::PhantomData<P>,
    frame: FrameBinding,
    draw: wgpu::RenderPipeline,
}

/// A portal's transform, as a type (the lesson's, or an exercise's).
pub trait Through: 'static {
    fn portal() -> Mat4;
}

/// The lesson's portal.
pub struct Lesson16;

impl Through for Lesson16 {
    fn portal() -> Mat4 {
        portal()
    }
}

impl<P: Through, const K: usize> Lesson for MovedCamera<P, K> {
    const NAME: &'static str = "portal-moved-camera";
    const TITLE: &'static str = "Lesson 16's far room, from a moved camera";
    const KNOBS: &'static [Knob] = &[];
    const CAMERA: Camera = Portal::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let recipe = Recipe {
            clip: Clip::Discard,
            ..states::OPAQUE
        };
        Ok(Self {
            through: std::marker::PhantomData,
            frame: scene.frame_binding(&gpu.device, "the moved camera"),
            draw: scene.pipeline(&gpu.device, &recipe),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let back = room_transform(P::portal(), K).inverse();
        let view = workbook::room::camera::View {
            eye: back.transform_point3(frame.view.eye),
            view: frame.view.view * room_transform(P::portal(), K),
            projection: frame.view.projection,
        };
        // Doorway K where room K has it in its own coordinates; what lies behind it is kept.
        let kept = doorway(P::portal(), K).transformed(back).flipped();
        (self.frame).write(&frame.gpu.queue, &view, &EVENING, kept.as_vec4());
        frame.clear();
        frame.step("draw the room from the moved camera", |pass| {
            pass.set_pipeline(&self.draw);
            self.frame.bind(pass);
            for object in scene.whole_room() {
                object.draw(pass);
            }
        });
    }
}

/// How far room `K`'s pixels in the portal's frame are from the moved camera's picture: the pixels
/// compared (judged by the rays to lie in room `K`, their eight neighbours too) and how many differ
/// by more than 8 in a channel (an edge rasterized a pixel over: the two pictures place the same
/// triangles by different products of the same matrices).
pub fn compare_room<P: Through, const K: usize>(
    rays: &RoomRays,
    portal_colour: &image::RgbaImage,
) -> (usize, usize) {
    let mut request = Request::new::<MovedCamera<P, K>>(&[] as &[&str]).unwrap();
    (request.width, request.height) = SIZE;
    let moved = headless::render::<MovedCamera<P, K>>(&request)
        .unwrap()
        .color;
    let view = View::new(Portal::CAMERA, SIZE.0, SIZE.1);
    let level = |x: i64, y: i64| {
        let ray = view.ray_at(x as f32 + 0.5, y as f32 + 0.5);
        doorways_passed(rays, P::portal(), ray, 3)
    };
    let (mut compared, mut differ) = (0, 0);
    for y in 1..SIZE.1 as i64 - 1 {
        for x in 1..SIZE.0 as i64 - 1 {
            let around = (-1..=1).flat_map(|dy| (-1..=1).map(move |dx| (dx, dy)));
            if !around
                .into_iter()
                .all(|(dx, dy)| level(x + dx, y + dy) == K as u32)
            {
                continue;
            }
            compared += 1;
            let (a, b) = (
                portal_colour.get_pixel(x as u32, y as u32),
                moved.get_pixel(x as u32, y as u32),
            );
            differ += (a.0.iter().zip(b.0).any(|(p, q)| p.abs_diff(q) > 8)) as usize;
        }
    }
    eprintln!("room {K}: {differ} of {compared} pixels differ from the moved camera's");
    (compared, differ)
}

#[test]
fn each_far_room_is_the_room_seen_from_the_moved_camera() {
    let rays = RoomRays::new();
    let capture = shots::render(Portal::NAME, &[], |request| {
        (request.width, request.height) = SIZE;
    })
    .unwrap();
    for (compared, differ) in [
        compare_room::<Lesson16, 1>(&rays, &capture.color),
        compare_room::<Lesson16, 2>(&rays, &capture.color),
        compare_room::<Lesson16, 3>(&rays, &capture.color),
    ] {
        assert!(compared > 300, "only {compared} pixels compared");
        assert!(
            differ * 100 <= compared,
            "{differ} of {compared} pixels differ"
        );
    }
}
