//! Lesson 6, exercise 1: the glass first. Draw the mirror's glass before the reflected skull, predict
//! the picture, and explain where the reflection went.

use transparent_mirror::{KNOBS, draw_mirror};
use workbook::lesson::mirror::MarkedRoom;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene, gpu::states};

pub struct Solution {
    marked_room: MarkedRoom,
    draw_reflection: wgpu::RenderPipeline,
    draw_mirror: wgpu::RenderPipeline,
}

impl Lesson for Solution {
    const NAME: &'static str = "transparent-mirror-exercise-1";
    const TITLE: &'static str = "Lesson 6, exercise 1: the glass first";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        scene
            .mirror
            .set_alpha(&gpu.queue, knobs.get("mirror-alpha").parse()?);
        Ok(Self {
            marked_room: MarkedRoom::new(gpu, scene),
            draw_reflection: scene.pipeline(&gpu.device, &states::FRONT_CLOCKWISE),
            draw_mirror: scene.pipeline(&gpu.device, &draw_mirror(knobs)),
        })
    }

    // ANCHOR: solution
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        self.marked_room.steps(frame);

        // The glass first: TRANSPARENT blends it over the sky, and writes its depth, the plane z = 0.
        frame.step("draw the glass", |pass| {
            pass.set_pipeline(&self.draw_mirror);
            scene.mirror.draw(pass);
        });
        // The reflected skull lies behind that plane: every fragment fails the depth test.
        frame.step("draw the reflected skull", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            scene.bind_reflected_frame(pass);
            scene.skull.draw_reflected(pass);
        });
    }
    // ANCHOR_END: solution
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
