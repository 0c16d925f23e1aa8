//! Lesson 13, exercise 2: what culling saves. Count every fragment with no face culled: the
//! difference from the lesson's count is the fragments back-face culling throws away.

use depth_complexity::{DepthComplexity, LEVELS, count, counting, see_through, solid};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: DepthComplexity,
    count_both_sides: wgpu::RenderPipeline,
}

impl Lesson for Solution {
    const NAME: &'static str = "depth-complexity-exercise-2";
    const TITLE: &'static str = "Lesson 13, exercise 2: what culling saves";
    const KNOBS: &'static [Knob] = &[];

    // ANCHOR: solution
    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let knobs = Knobs::defaults(depth_complexity::KNOBS);
        // COUNT, every fragment, with both sides of every triangle.
        let both_sides = Recipe {
            cull_mode: None,
            ..count(&knobs)
        };
        Ok(Self {
            lesson: DepthComplexity::new(gpu, scene, &knobs)?,
            count_both_sides: counting(&gpu.device, scene, &both_sides),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();
        frame.step("count the fragments of both sides", |pass| {
            pass.set_pipeline(&self.count_both_sides);
            for object in solid(scene).into_iter().chain(see_through(scene)) {
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
