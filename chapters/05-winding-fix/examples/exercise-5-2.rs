//! Lesson 5, exercise 2: reflect the floor. Draw the floor's mirror image with the lesson's reflected
//! recipe, so the floor runs on behind the glass; then try `--set winding-fix=off` and explain why
//! the reflected floor vanishes instead of showing its inside.

use winding_fix::{KNOBS, reflection_recipe};
use workbook::lesson::mirror::MarkedRoom;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene};

pub struct Solution {
    marked_room: MarkedRoom,
    draw_reflection: wgpu::RenderPipeline,
}

impl Lesson for Solution {
    const NAME: &'static str = "winding-fix-exercise-2";
    const TITLE: &'static str = "Lesson 5, exercise 2: reflect the floor";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let recipe = reflection_recipe(knobs.get("winding-fix"));
        Ok(Self {
            marked_room: MarkedRoom::new(gpu, scene),
            draw_reflection: scene.pipeline(&gpu.device, &recipe),
        })
    }

    // ANCHOR: solution
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        self.marked_room.steps(frame);
        frame.step("draw the reflected skull and floor", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            scene.bind_reflected_frame(pass);
            scene.skull.draw_reflected(pass);
            // The floor's image lies in y = 0 behind the mirror (z from -12 to 0), facing up.
            scene.floor.draw_reflected(pass);
        });
    }
    // ANCHOR_END: solution
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
