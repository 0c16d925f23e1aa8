//! Lesson 4, exercise 2: reflect before you mark. Move the reflection step before the mark, predict
//! the picture, and explain why the stencil test lets nothing through.

use reflect_skull::{KNOBS, draw_reflection};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene, gpu::states};

pub struct Solution {
    draw_room: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
    draw_reflection: wgpu::RenderPipeline,
    reflect_lights: bool,
}

impl Lesson for Solution {
    const NAME: &'static str = "reflect-skull-exercise-2";
    const TITLE: &'static str = "Lesson 4, exercise 2: reflect before you mark";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let pipeline = |recipe| scene.pipeline(&gpu.device, recipe);
        Ok(Self {
            draw_room: pipeline(&states::OPAQUE),
            mark_mirror: pipeline(&states::MARK_MIRROR),
            draw_reflection: pipeline(&draw_reflection(knobs)),
            reflect_lights: knobs.is_on("reflect-lights"),
        })
    }

    // ANCHOR: solution
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            scene.draw_room(pass);
        });
        // Too early: the stencil buffer still holds the cleared 0 at every pixel.
        frame.step("draw the reflected skull", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            if self.reflect_lights {
                scene.bind_reflected_frame(pass);
            }
            scene.skull.draw_reflected(pass);
        });
        frame.step("mark the mirror", |pass| {
            pass.set_pipeline(&self.mark_mirror);
            pass.set_stencil_reference(1);
            scene.mirror.draw(pass);
        });
    }
    // ANCHOR_END: solution
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
