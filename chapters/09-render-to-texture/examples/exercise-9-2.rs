//! Lesson 9, exercise 2: make the wall mirror a texture mirror too, beside the stone: a second
//! reflected camera, a second texture, and the wall mirror's surface looking it up.

use std::cell::RefCell;

use render_to_texture::{RenderToTexture, reflected_view_recipe};
use workbook::gpu::Offscreen;
use workbook::gpu::states;
use workbook::math::reflect::reflection;
use workbook::room::camera::Camera;
use workbook::room::scene::{FrameBinding, LIGHTS, mirror_plane};
use workbook::room::texture_mirror::TextureMirror;
use workbook::wgpu::{self, CompareFunction};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: RenderToTexture,
    wall_camera: FrameBinding,
    draw_wall_view: wgpu::RenderPipeline,
    wall_mirror: TextureMirror,
    wall_texture: RefCell<Option<Offscreen>>,
}

/// How much of the reflection the wall's glass mixes in (the lesson's default blend).
const BLEND: f32 = 0.5;

impl Lesson for Solution {
    const NAME: &'static str = "render-to-texture-exercise-2";
    const TITLE: &'static str = "Lesson 9, exercise 2: two texture mirrors";
    /// The lesson's defaults: the stone's texture mirror at full resolution.
    const KNOBS: &'static [Knob] = &[];
    const CAMERA: Camera = RenderToTexture::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, _knobs: &Knobs) -> anyhow::Result<Self> {
        let knobs = Knobs::defaults(render_to_texture::KNOBS);
        // The room drew the wall mirror already, opaque: its textured surface lies at the same
        // depth, so it must pass where the depth is equal.
        let over_itself = Recipe {
            depth_compare: CompareFunction::LessEqual,
            ..states::OPAQUE
        };
        Ok(Self {
            lesson: RenderToTexture::new(gpu, scene, &knobs)?,
            wall_camera: scene.frame_binding(&gpu.device, "wall's reflected camera"),
            draw_wall_view: scene.pipeline(&gpu.device, &reflected_view_recipe(false, true)),
            wall_mirror: TextureMirror::new(gpu, scene, &over_itself),
            wall_texture: RefCell::new(None),
        })
    }

    // ANCHOR: solution
    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
        let scene = frame.scene;
        // The camera reflected in the wall, cut at the wall's plane, and its texture.
        let camera = frame.view.reflected(reflection(mirror_plane()));
        let queue = &frame.gpu.queue;
        let clip_plane = mirror_plane().as_vec4();
        self.wall_camera.write(queue, &camera, &LIGHTS, clip_plane);
        self.wall_mirror.update(queue, &camera, BLEND);
        let texture = self.texture(frame);
        let texture = texture.as_ref().expect("made by texture()");
        // What the wall mirror sees: this lesson's room, the stone as plain stone.
        let room = [
            &scene.floor_around_mirror,
            &scene.floor_mirror,
            &scene.wall,
            &scene.crate_box,
            &scene.skull,
        ];
        frame.step_into(
            "render the wall's reflection into a texture",
            texture,
            |pass| {
                pass.set_pipeline(&self.draw_wall_view);
                self.wall_camera.bind(pass);
                room.iter().for_each(|object| object.draw(pass));
            },
        );
        let device = &frame.gpu.device;
        frame.step("draw the wall mirror with its texture", |pass| {
            self.wall_mirror.bind(device, pass, texture);
            scene.mirror.draw(pass);
        });
    }
    // ANCHOR_END: solution
}

impl Solution {
    /// The wall's reflection texture, the frame's size, made again when that changes.
    fn texture(&self, frame: &Frame<'_>) -> std::cell::Ref<'_, Option<Offscreen>> {
        let size = frame.size();
        if self.wall_texture.borrow().as_ref().map(Offscreen::size) != Some(size) {
            let (device, format) = (&frame.gpu.device, frame.scene.color_format);
            let texture = Offscreen::new(device, "wall reflection texture", format, size);
            *self.wall_texture.borrow_mut() = Some(texture);
        }
        self.wall_texture.borrow()
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
