//! Lesson 13, exercise 1: nearest first. With count=passed-depth, draw the room's objects in the
//! reverse order, the see-through ones and the skull first, the floor and the wall last: fewer
//! fragments pass the depth test, because what is near is drawn before what it hides.

use depth_complexity::{DepthComplexity, LEVELS, count, counting, see_through, solid};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: DepthComplexity,
    /// COUNT with the depth test: for the solid objects (culled) and the see-through ones.
    count: [wgpu::RenderPipeline; 2],
}

impl Lesson for Solution {
    const NAME: &'static str = "depth-complexity-exercise-1";
    const TITLE: &'static str = "Lesson 13, exercise 1: nearest first";
    const KNOBS: &'static [Knob] = &[];

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let knobs = Knobs::from_settings(depth_complexity::KNOBS, &["count=passed-depth"])?;
        let recipe = count(&knobs);
        let both_sides = Recipe {
            cull_mode: None,
            ..recipe.clone()
        };
        Ok(Self {
            lesson: DepthComplexity::new(gpu, scene, &knobs)?,
            count: [
                counting(&gpu.device, scene, &recipe),
                counting(&gpu.device, scene, &both_sides),
            ],
        })
    }

    // ANCHOR: solution
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();
        frame.step("count the fragments, nearest first", |pass| {
            pass.set_pipeline(&self.count[1]);
            for object in see_through(scene).into_iter().rev() {
                object.draw(pass);
            }
            pass.set_pipeline(&self.count[0]);
            for object in solid(scene).into_iter().rev() {
                object.draw(pass);
            }
        });
        frame.step("paint the levels", |pass| {
            self.lesson.paint(pass, 0..LEVELS)
        });
    }
    // ANCHOR_END: solution
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
