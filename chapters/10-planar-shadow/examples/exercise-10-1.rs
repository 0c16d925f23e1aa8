//! Lesson 10, exercise 1: draw the shadow with the depth test off (depth compare `Always`). Where
//! does the shadow darken now, and why only once there?

use planar_shadow::PlanarShadow;
use workbook::room::camera::Camera;
use workbook::wgpu::CompareFunction;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: PlanarShadow,
}

impl Lesson for Solution {
    const NAME: &'static str = "planar-shadow-exercise-1";
    const TITLE: &'static str = "Lesson 10, exercise 1: the shadow without the depth test";
    const KNOBS: &'static [Knob] = planar_shadow::KNOBS;
    const CAMERA: Camera = PlanarShadow::CAMERA;

    // ANCHOR: solution
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let mut lesson = PlanarShadow::new(gpu, scene, knobs)?;
        // The lesson's shadow recipe (NO_DOUBLE_BLEND by default), but drawn whatever depth the
        // room left: nothing hides the flattened skull any more.
        let no_depth_test = Recipe {
            name: "SHADOW_NO_DEPTH_TEST",
            depth_compare: CompareFunction::Always,
            ..planar_shadow::draw_shadow(knobs)
        };
        lesson.draw_shadow = scene.pipeline(&gpu.device, &no_depth_test);
        Ok(Self { lesson })
    }
    // ANCHOR_END: solution

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
