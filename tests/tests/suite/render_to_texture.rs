//! Lesson 9, by oracles: the texture mirror at full resolution is the stencil mirror; smaller textures
//! differ more and more; the texture is what a camera at the reflected position sees; Rastertek's
//! camera is right for the floor and wrong for the wall; the clip plane keeps what is under the floor
//! out of the texture.

use glam::{Vec3, Vec4};
use workbook::app::headless::{self, Request};
use workbook::gpu::states::{self, Clip};
use workbook::room::camera::{TARGET, View};
use workbook::room::scene::{FrameBinding, LIGHTS};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, wgpu};
use workbook_tests::flip::{self, Threshold};
use workbook_tests::shots::{self, STRICT};

use lessons::render_to_texture::{RenderToTexture, reflected};

const SIZE: (u32, u32) = (400, 225);

fn picture(settings: &[&str]) -> image::RgbaImage {
    let render = shots::render("render-to-texture", settings, |r| {
        (r.width, r.height) = SIZE
    });
    render.unwrap().color
}

fn mean(a: &image::RgbaImage, b: &image::RgbaImage) -> f32 {
    flip::compare(a, b).unwrap().mean
}

#[test]
fn at_full_resolution_the_texture_mirror_is_the_stencil_mirror() {
    for plane in ["plane=floor", "plane=wall"] {
        let texture = picture(&[plane]);
        let stencil = picture(&[plane, "technique=stencil"]);
        let comparison = flip::compare(&stencil, &texture).unwrap();
        assert!(
            comparison.passes(STRICT),
            "{plane}: {}",
            comparison.summary()
        );
    }
}

#[test]
fn smaller_textures_differ_more_and_more() {
    let stencil = picture(&["technique=stencil"]);
    let means: Vec<f32> = ["full", "half", "quarter", "64"]
        .iter()
        .map(|r| mean(&stencil, &picture(&[&format!("resolution={r}")])))
        .collect();
    for pair in means.windows(2) {
        assert!(pair[0] < pair[1], "FLIP means by resolution: {means:?}");
    }
    let blocky = flip::compare(&stencil, &picture(&["resolution=64"])).unwrap();
    assert!(
        !blocky.passes(STRICT),
        "resolution=64: {}",
        blocky.summary()
    );
}

/// Rastertek's reflected camera is right for the floor (the same picture as view · R) and wrong for
/// the wall, which is not horizontal.
#[test]
fn rastertek_camera_is_right_for_the_floor_only() {
    let matrix = picture(&[]);
    let rastertek = picture(&["camera=rastertek"]);
    let floor = flip::compare(&matrix, &rastertek).unwrap();
    assert!(floor.passes(STRICT), "floor: {}", floor.summary());
    let matrix = picture(&["plane=wall"]);
    let rastertek = picture(&["plane=wall", "camera=rastertek"]);
    let wall = flip::compare(&matrix, &rastertek).unwrap();
    assert!(!wall.passes(STRICT), "wall: {}", wall.summary());
}

#[test]
fn without_the_clip_plane_what_is_under_the_floor_shows_in_the_mirror() {
    let clipped = picture(&["sink=2"]);
    let unclipped = picture(&["sink=2", "clip=off"]);
    let comparison = flip::compare(&clipped, &unclipped).unwrap();
    assert!(
        !comparison.passes(STRICT),
        "clip=off: {}",
        comparison.summary()
    );
    // And clipped, the texture mirror still agrees with the stencil mirror (which resets the depth
    // of the mark, lesson 8).
    let stencil = picture(&["sink=2", "technique=stencil"]);
    let comparison = flip::compare(&stencil, &clipped).unwrap();
    assert!(comparison.passes(STRICT), "sunk: {}", comparison.summary());
}

/// The room drawn as usual into the frame, but seen from Rastertek's camera below the floor.
struct RoomFromBelow(wgpu::RenderPipeline, FrameBinding);

impl Lesson for RoomFromBelow {
    const NAME: &'static str = "room-from-below";
    const TITLE: &'static str = "the room seen from the camera mirrored in the floor";
    const KNOBS: &'static [Knob] = &[];
    const CAMERA: workbook::room::camera::Camera = RenderToTexture::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let recipe = Recipe {
            clip: Clip::Discard,
            ..states::OPAQUE
        };
        let binding = scene.frame_binding(&gpu.device, "camera below the floor");
        Ok(Self(scene.pipeline(&gpu.device, &recipe), binding))
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let below = |p: Vec3| p * Vec3::new(1.0, -1.0, 1.0);
        let view = View::look_at(
            below(frame.view.eye),
            below(TARGET),
            Vec3::Y,
            frame.view.projection,
        );
        let floor = Vec4::new(0.0, 1.0, 0.0, 0.0);
        self.1.write(&frame.gpu.queue, &view, &LIGHTS, floor);
        frame.clear();
        frame.step("draw the room from below", |pass| {
            pass.set_pipeline(&self.0);
            self.1.bind(pass);
            for object in reflected(scene, true) {
                object.draw(pass);
            }
        });
    }
}

/// Measured on lavapipe: the texture, shown at its own size, is identical to the direct render. The
/// limit is the winding test's (edge pixels on another rasteriser).
const SAME_PICTURE: Threshold = Threshold {
    mean: 0.002,
    visible_share: 0.001,
    largest_patch: STRICT.largest_patch,
};

#[test]
fn the_texture_is_the_room_seen_from_the_reflected_camera() {
    let film = shots::film("render-to-texture", &["camera=rastertek"], |r| {
        (r.width, r.height) = SIZE
    })
    .unwrap();
    let texture = film
        .iter()
        .find(|still| still.step == "render the reflection into a texture")
        .expect("the texture's step");
    let mut request = Request::new::<RoomFromBelow>(&[] as &[&str]).unwrap();
    (request.width, request.height) = SIZE;
    let direct = headless::render::<RoomFromBelow>(&request).unwrap().color;
    let comparison = flip::compare(&direct, &texture.color).unwrap();
    assert!(comparison.passes(SAME_PICTURE), "{}", comparison.summary());
}
