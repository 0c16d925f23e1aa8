//! Lesson 4, exercise 1: reflect the crate too. Draw the crate's mirror image in the reflection step
//! with the lesson's DRAW_REFLECTION, and find out with `--show depth` which of its faces you see.

use reflect_skull::{KNOBS, draw_reflection};
use workbook::lesson::mirror::MarkedRoom;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene};

pub struct Solution {
    marked_room: MarkedRoom,
    draw_reflection: wgpu::RenderPipeline,
    reflect_lights: bool,
}

impl Lesson for Solution {
    const NAME: &'static str = "reflect-skull-exercise-1";
    const TITLE: &'static str = "Lesson 4, exercise 1: reflect the crate too";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            marked_room: MarkedRoom::new(gpu, scene),
            draw_reflection: scene.pipeline(&gpu.device, &draw_reflection(knobs)),
            reflect_lights: knobs.is_on("reflect-lights"),
        })
    }

    // ANCHOR: solution
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        self.marked_room.steps(frame);

        // Every object is reflected by its own R * world (the framework keeps one for each), so
        // the crate's mirror image is one more draw in the same step, with the same pipeline.
        frame.step("draw the reflected skull and crate", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            if self.reflect_lights {
                scene.bind_reflected_frame(pass);
            }
            scene.skull.draw_reflected(pass);
            scene.crate_box.draw_reflected(pass);
        });
    }
    // ANCHOR_END: solution
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
