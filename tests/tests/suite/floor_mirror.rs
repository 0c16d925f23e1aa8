//! Lesson 8, by independent oracles: no reflected fragment lands above the floor once clipped (depth
//! read back and turned into world positions), the three clip methods give one picture, the floor's
//! reflection is the room seen from the camera mirrored in the floor (flipped upside down), and the
//! stencil keeps the reflection inside the stone where the other recipes do not.

use glam::{Vec3, Vec4, Vec4Swizzles};
use image::imageops;
use lessons::floor_mirror;
use workbook::app::headless::{self, Capture, Request};
use workbook::gpu::states::{self, Clip};
use workbook::math::clip::oblique_projection;
use workbook::room::camera::{Camera, View};
use workbook::room::mirror_world::MirrorWorld;
use workbook::room::scene::{FrameBinding, LIGHTS};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, Stop, wgpu};
use workbook_tests::flip::{self, Threshold};
use workbook_tests::shots::{self, STRICT};

use lessons::floor_mirror::{FloorMirror, floor_plane, reflected, sink_skull};

const SIZE: (u32, u32) = (400, 225);

/// The floor's mirror world alone — no room, no stencil — drawn with lesson 8's reflection recipe
/// and clip method, the skull lowered as its knobs say.
struct ReflectionAlone {
    draw: wgpu::RenderPipeline,
    world: MirrorWorld,
    oblique: bool,
}

impl Lesson for ReflectionAlone {
    const NAME: &'static str = "floor-reflection-alone";
    const TITLE: &'static str = "the floor's mirror world alone";
    const KNOBS: &'static [Knob] = floor_mirror::KNOBS;
    const CAMERA: Camera = FloorMirror::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        sink_skull(gpu, scene, knobs)?;
        let recipe = Recipe {
            stencil: states::NO_STENCIL,
            ..floor_mirror::draw_reflection(knobs)
        };
        Ok(Self {
            draw: scene.pipeline(&gpu.device, &recipe),
            world: MirrorWorld::new(gpu, scene, floor_plane(), &reflected(scene)),
            oblique: knobs.get("clip") == "oblique",
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        self.world.update(frame, self.oblique);
        frame.clear();
        frame.step("draw the reflection", |pass| {
            pass.set_pipeline(&self.draw);
            self.world.bind(pass);
            for object in reflected(scene) {
                self.world.draw(pass, object);
            }
        });
    }
}

/// Renders the mirror world alone and counts the pixels whose fragment lies above the floor: the
/// depth read back, unprojected with the projection that drew it (the oblique one for
/// clip=oblique, computed here from `math::clip` alone), gives each pixel's world position.
fn fragments_above_the_floor(clip: &str) -> (usize, usize) {
    let settings = [format!("clip={clip}"), "sink=2".to_string()];
    let mut request = Request::new::<ReflectionAlone>(&settings).unwrap();
    (request.width, request.height) = SIZE;
    request.read_depth = true;
    let capture = headless::render::<ReflectionAlone>(&request).unwrap();
    let view = FloorMirror::CAMERA.view_at(SIZE.0 as f32 / SIZE.1 as f32);
    let projection = if clip == "oblique" {
        let kept = floor_plane().flipped().transformed(view.view);
        oblique_projection(view.projection, kept)
    } else {
        view.projection
    };
    let inverse = (projection * view.view).inverse();
    let (mut drawn, mut above) = (0, 0);
    for y in 0..SIZE.1 {
        for x in 0..SIZE.0 {
            let depth = capture.depth_at(x, y).unwrap();
            if depth >= 1.0 {
                continue;
            }
            let ndc_x = (x as f32 + 0.5) / SIZE.0 as f32 * 2.0 - 1.0;
            let ndc_y = 1.0 - (y as f32 + 0.5) / SIZE.1 as f32 * 2.0;
            let p = inverse * Vec4::new(ndc_x, ndc_y, depth, 1.0);
            let world = p.xyz() / p.w;
            drawn += 1;
            // 2 cm: depth precision and the clipped edge's pixels, far below the 0.5-1 m the
            // unclipped jaw rises.
            if world.y > 0.02 {
                above += 1;
            }
        }
    }
    (drawn, above)
}

#[test]
fn every_clip_method_keeps_the_reflection_below_the_floor() {
    for clip in ["clip-distances", "discard", "oblique"] {
        let (drawn, above) = fragments_above_the_floor(clip);
        assert!(drawn > 5000, "clip={clip}: only {drawn} reflected pixels");
        assert_eq!(
            above, 0,
            "clip={clip}: {above} of {drawn} pixels above the floor"
        );
    }
    let (drawn, above) = fragments_above_the_floor("off");
    assert!(
        above > 200,
        "clip=off with the skull sunk: only {above} of {drawn} reflected pixels above the floor"
    );
}

fn render(settings: &[&str], stop: Stop) -> Capture {
    shots::render("floor-mirror", settings, |request| {
        (request.width, request.height) = SIZE;
        request.read_stencil = true;
        request.stop = stop;
    })
    .unwrap()
}

#[test]
fn the_three_clip_methods_give_one_picture_and_no_clip_another() {
    let picture = |clip: &str| render(&["sink=2", &format!("clip={clip}")], Stop::Last).color;
    let discard = picture("discard");
    for clip in ["clip-distances", "oblique"] {
        let comparison = flip::compare(&discard, &picture(clip)).unwrap();
        assert!(
            comparison.passes(STRICT),
            "clip={clip}: {}",
            comparison.summary()
        );
    }
    let comparison = flip::compare(&discard, &picture("off")).unwrap();
    assert!(
        !comparison.passes(STRICT),
        "clip=off: {}",
        comparison.summary()
    );
}

/// The stencil recipe changes no pixel outside the mark when it draws the reflection; SPE's recipe
/// (no stencil) changes pixels outside the stone, and the blog's (depth `Always`) changes what the
/// stone shows.
#[test]
fn only_the_stencil_keeps_the_reflection_inside_the_stone() {
    let step = |name| shots::after_step("floor-mirror", &[], name).unwrap();
    let marked = render(&[], step("mark the floor mirror"));
    let reflected = render(&[], step("draw the reflection"));
    let inside = workbook_tests::changed_only_inside_mark(&marked, &reflected, 1).unwrap();
    assert!(inside > 2000, "the reflection changed only {inside} pixels");

    let ours = render(&[], Stop::Last);
    let spe = render(&["recipe=spe"], Stop::Last);
    let outside = ours
        .color
        .enumerate_pixels()
        .filter(|(x, y, pixel)| {
            ours.stencil_at(*x, *y) == Some(0) && **pixel != *spe.color.get_pixel(*x, *y)
        })
        .count();
    assert!(
        outside > 500,
        "recipe=spe differs outside the stone in only {outside} pixels"
    );

    let always = render(&["recipe=always"], Stop::Last);
    let comparison = flip::compare(&ours.color, &always.color).unwrap();
    assert!(
        !comparison.passes(STRICT),
        "recipe=always: {}",
        comparison.summary()
    );
}

/// The skull's mirror image alone, as lesson 8 draws it.
struct ReflectedSkull(wgpu::RenderPipeline, MirrorWorld);

impl Lesson for ReflectedSkull {
    const NAME: &'static str = "floor-reflected-skull";
    const TITLE: &'static str = "the skull's image in the floor";
    const KNOBS: &'static [Knob] = &[];

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let recipe = Recipe {
            stencil: states::NO_STENCIL,
            clip: Clip::None,
            ..states::FRONT_CLOCKWISE
        };
        let world = MirrorWorld::new(gpu, scene, floor_plane(), &[&scene.skull]);
        Ok(Self(scene.pipeline(&gpu.device, &recipe), world))
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        self.1.update(frame, false);
        frame.clear();
        frame.step("draw the reflected skull", |pass| {
            pass.set_pipeline(&self.0);
            self.1.bind(pass);
            self.1.draw(pass, &scene.skull);
        });
    }
}

/// The skull itself, seen from the camera mirrored in the floor: the eye and the target below it,
/// the up vector still up.
struct SkullFromBelow(wgpu::RenderPipeline, FrameBinding);

impl Lesson for SkullFromBelow {
    const NAME: &'static str = "skull-from-below";
    const TITLE: &'static str = "the skull seen from the mirrored camera";
    const KNOBS: &'static [Knob] = &[];

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let draw = scene.pipeline(&gpu.device, &states::OPAQUE);
        Ok(Self(
            draw,
            scene.frame_binding(&gpu.device, "mirrored camera"),
        ))
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let below = |p: Vec3| p * Vec3::new(1.0, -1.0, 1.0);
        let target = below(workbook::room::camera::TARGET);
        let view = View::look_at(
            below(frame.view.eye),
            target,
            Vec3::Y,
            frame.view.projection,
        );
        self.1.write(&frame.gpu.queue, &view, &LIGHTS, Vec4::ZERO);
        frame.clear();
        frame.step("draw the skull", |pass| {
            pass.set_pipeline(&self.0);
            self.1.bind(pass);
            scene.skull.draw(pass);
        });
    }
}

/// Measured on lavapipe: identical (FLIP mean 0) from the three cameras. The limit is the winding
/// test's: another rasteriser may break ties on edge pixels differently.
const SAME_PICTURE: Threshold = Threshold {
    mean: 0.002,
    visible_share: 0.001,
    largest_patch: STRICT.largest_patch,
};

#[test]
fn the_floor_shows_the_skull_seen_from_below_upside_down() {
    for camera in [
        FloorMirror::CAMERA,
        Camera::parse("-30,30,12").unwrap(),
        Camera::parse("50,35,13").unwrap(),
    ] {
        let mut request = Request::new::<ReflectedSkull>(&[] as &[&str]).unwrap();
        (request.width, request.height, request.camera) = (SIZE.0, SIZE.1, camera);
        let reflected = headless::render::<ReflectedSkull>(&request).unwrap().color;
        let mut request = Request::new::<SkullFromBelow>(&[] as &[&str]).unwrap();
        (request.width, request.height, request.camera) = (SIZE.0, SIZE.1, camera);
        let below = headless::render::<SkullFromBelow>(&request).unwrap().color;
        let comparison = flip::compare(&imageops::flip_vertical(&below), &reflected).unwrap();
        assert!(
            comparison.passes(SAME_PICTURE),
            "camera {camera}: {}",
            comparison.summary()
        );
        assert!(
            reflected
                .pixels()
                .filter(|p| p.0[..3] != workbook::room::scene::CLEAR_SRGB)
                .count()
                > 500,
            "the skull's image is not in the picture from {camera}"
        );
    }
}
