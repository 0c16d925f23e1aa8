//! Lesson 11, by the stencil buffer read back: the levels are nested (each depth adds pixels only
//! inside the deepest level of the one before, and holds its levels 0 to depth), the corridor grows
//! level by level, and the two ways to break it break it; the first level is the room seen from the
//! mirrored camera (lesson 5's oracle).

use glam::Vec4;
use image::imageops;
use lessons::two_mirrors;
use workbook::app::headless::{self, Capture, Request};
use workbook::gpu::states::{self, Clip};
use workbook::room::camera::Camera;
use workbook::room::mirror_world::MirrorWorld;
use workbook::room::scene::{FrameBinding, LIGHTS};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, Stop, wgpu};
use workbook_tests::flip::{self, Threshold};
use workbook_tests::shots::{self, STRICT};

const SIZE: (u32, u32) = (320, 180);

fn render(settings: &[&str]) -> Capture {
    shots::render("two-mirrors", settings, |request| {
        (request.width, request.height) = SIZE;
        request.read_stencil = true;
        request.stop = Stop::Last;
    })
    .unwrap()
}

#[test]
fn each_level_lies_inside_the_one_before() {
    let mut shallower = render(&["depth=0"]);
    for depth in 1..=two_mirrors::MAX_DEPTH {
        let deeper = render(&[&format!("depth={depth}")]);
        let (before, after) = (
            shallower.stencil.as_ref().unwrap(),
            deeper.stencil.as_ref().unwrap(),
        );
        let previous = depth as u8 - 1;
        assert!(
            after.iter().all(|&v| v as usize <= depth),
            "depth={depth}: a value above it"
        );
        let mut added = 0;
        for (i, (&b, &a)) in before.iter().zip(after).enumerate() {
            let (x, y) = (i as u32 % SIZE.0, i as u32 / SIZE.0);
            if a != b {
                assert!(
                    b == previous && a == previous + 1,
                    "depth={depth}: ({x}, {y}) went from {b} to {a}"
                );
                added += 1;
            }
            if deeper.color.get_pixel(x, y) != shallower.color.get_pixel(x, y) {
                assert_eq!(
                    b, previous,
                    "depth={depth}: ({x}, {y}) changed outside level {previous}"
                );
            }
        }
        // The corridor narrows, but the first levels are large: every level adds pixels up to 4.
        if depth <= 4 {
            assert!(added > 50, "depth={depth} added only {added} pixels");
        }
        shallower = deeper;
    }
    let levels = shallower.stencil.unwrap();
    for level in 0..=4u8 {
        assert!(levels.contains(&level), "no pixel holds level {level}");
    }
}

#[test]
fn replacing_instead_of_incrementing_lets_the_levels_bleed() {
    let increment = render(&[]);
    let replace = render(&["mark=replace"]);
    let comparison = flip::compare(&increment.color, &replace.color).unwrap();
    assert!(
        !comparison.passes(STRICT),
        "mark=replace: {}",
        comparison.summary()
    );
    // Replace writes level k + 1 wherever the mirror passes the depth test, inside level k or not.
    let (a, b) = (increment.stencil.unwrap(), replace.stencil.unwrap());
    assert_ne!(a, b);
}

#[test]
fn flipping_the_winding_at_every_level_turns_the_even_levels_inside_out() {
    let per_level = render(&["depth=2"]);
    let flipped = render(&["depth=2", "winding=always-flipped"]);
    let comparison = flip::compare(&per_level.color, &flipped.color).unwrap();
    assert!(
        comparison.mean > 0.0,
        "winding=always-flipped: {}",
        comparison.summary()
    );
    // Level 1 (odd) is the same either way: only level 2's pixels differ.
    let levels = per_level.stencil.unwrap();
    for (x, y, pixel) in flipped.color.enumerate_pixels() {
        if pixel != per_level.color.get_pixel(x, y) {
            assert_eq!(
                levels[(y * SIZE.0 + x) as usize],
                2,
                "({x}, {y}) outside level 2"
            );
        }
    }
}

/// Level 1 alone, as lesson 11 draws it — the room under R₁, clipped behind the first mirror — with
/// no stencil and nothing else.
struct LevelOne(wgpu::RenderPipeline, MirrorWorld);

impl Lesson for LevelOne {
    const NAME: &'static str = "level-one";
    const TITLE: &'static str = "lesson 11's first level alone";
    const KNOBS: &'static [Knob] = &[];
    const CAMERA: Camera = two_mirrors::TwoMirrors::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let recipe = Recipe {
            stencil: states::NO_STENCIL,
            clip: Clip::Discard,
            ..states::FRONT_CLOCKWISE
        };
        let objects = [&scene.floor, &scene.wall, &scene.crate_box, &scene.skull];
        let placing = (
            two_mirrors::level_reflection(1),
            two_mirrors::first_mirror(),
        );
        let world = MirrorWorld::seen_through(gpu, scene, placing, &objects);
        Ok(Self(scene.pipeline(&gpu.device, &recipe), world))
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        self.1.update(frame, false);
        frame.clear();
        frame.step("draw level 1", |pass| {
            pass.set_pipeline(&self.0);
            self.1.bind(pass);
            for object in [&scene.floor, &scene.wall, &scene.crate_box, &scene.skull] {
                self.1.draw(pass, object);
            }
        });
    }
}

/// The room itself from the camera mirrored in the first mirror (the orbit target lies on its plane,
/// so the mirrored camera is yaw → 180° − yaw), clipped to the room's side of the mirror.
struct RoomFromBehind(wgpu::RenderPipeline, FrameBinding);

impl Lesson for RoomFromBehind {
    const NAME: &'static str = "room-from-behind";
    const TITLE: &'static str = "the room seen from the mirrored camera";
    const KNOBS: &'static [Knob] = &[];

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let recipe = Recipe {
            clip: Clip::Discard,
            ..states::OPAQUE
        };
        let binding = scene.frame_binding(&gpu.device, "mirrored camera");
        Ok(Self(scene.pipeline(&gpu.device, &recipe), binding))
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let room_side = Vec4::new(0.0, 0.0, 1.0, 0.0);
        self.1
            .write(&frame.gpu.queue, &frame.view, &LIGHTS, room_side);
        frame.clear();
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.0);
            self.1.bind(pass);
            for object in [&scene.floor, &scene.wall, &scene.crate_box, &scene.skull] {
                object.draw(pass);
            }
        });
    }
}

/// Measured on lavapipe: identical. The limit is the winding test's (edge pixels elsewhere).
const SAME_PICTURE: Threshold = Threshold {
    mean: 0.002,
    visible_share: 0.001,
    largest_patch: STRICT.largest_patch,
};

/// Lesson 5's oracle for the first level: what the first mirror shows from camera C is the room seen
/// from C mirrored, turned left to right.
#[test]
fn level_one_is_the_room_from_the_mirrored_camera() {
    let camera = two_mirrors::TwoMirrors::CAMERA;
    let mut request = Request::new::<LevelOne>(&[] as &[&str]).unwrap();
    (request.width, request.height, request.camera) = (SIZE.0, SIZE.1, camera);
    let level = headless::render::<LevelOne>(&request).unwrap().color;
    let mirrored = Camera {
        yaw: 180.0 - camera.yaw,
        ..camera
    };
    let mut request = Request::new::<RoomFromBehind>(&[] as &[&str]).unwrap();
    (request.width, request.height, request.camera) = (SIZE.0, SIZE.1, mirrored);
    let room = headless::render::<RoomFromBehind>(&request).unwrap().color;
    let comparison = flip::compare(&imageops::flip_horizontal(&room), &level).unwrap();
    assert!(comparison.passes(SAME_PICTURE), "{}", comparison.summary());
}
