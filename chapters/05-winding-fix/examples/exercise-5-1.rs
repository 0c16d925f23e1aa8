//! Lesson 5, exercise 1: the fix in the wrong place. Draw the room itself with clockwise as the front
//! face, as the reflection is drawn, and explain what happens to the crate, the floor and the wall.

use winding_fix::{KNOBS, reflection_recipe};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, gpu::states};

pub struct Solution {
    draw_room: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
    draw_reflection: wgpu::RenderPipeline,
}

// ANCHOR: solution
/// OPAQUE with the reflection's front face: for the room, which no reflection has turned, this
/// culls the faces that look at the camera.
pub const OPAQUE_FRONT_CLOCKWISE: Recipe = Recipe {
    name: "OPAQUE_FRONT_CLOCKWISE",
    front_face: wgpu::FrontFace::Cw,
    ..states::OPAQUE
};
// ANCHOR_END: solution

impl Lesson for Solution {
    const NAME: &'static str = "winding-fix-exercise-1";
    const TITLE: &'static str = "Lesson 5, exercise 1: the fix in the wrong place";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let pipeline = |recipe| scene.pipeline(&gpu.device, recipe);
        Ok(Self {
            draw_room: pipeline(&OPAQUE_FRONT_CLOCKWISE),
            mark_mirror: pipeline(&states::MARK_MIRROR),
            draw_reflection: pipeline(&reflection_recipe(knobs.get("winding-fix"))),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();
        frame.step("draw the room, clockwise as the front", |pass| {
            pass.set_pipeline(&self.draw_room);
            scene.draw_room(pass);
        });
        frame.step("mark the mirror", |pass| {
            pass.set_pipeline(&self.mark_mirror);
            pass.set_stencil_reference(1);
            scene.mirror.draw(pass);
        });
        frame.step("draw the reflected skull", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            scene.bind_reflected_frame(pass);
            scene.skull.draw_reflected(pass);
        });
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
