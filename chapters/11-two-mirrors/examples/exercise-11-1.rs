//! Lesson 11, exercise 1: mark each level's mirror without the depth test (depth compare
//! `Always`), as if nothing could stand in front of a mirror. Look at the crate, which stands in
//! front of the first mirror, and explain what happens to it.

use two_mirrors::{TwoMirrors, level_recipes};
use workbook::room::camera::Camera;
use workbook::wgpu::{CompareFunction, FrontFace};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: TwoMirrors,
}

impl Lesson for Solution {
    const NAME: &'static str = "two-mirrors-exercise-1";
    const TITLE: &'static str = "Lesson 11, exercise 1: the marks without the depth test";
    const KNOBS: &'static [Knob] = two_mirrors::KNOBS;
    const CAMERA: Camera = TwoMirrors::CAMERA;

    // ANCHOR: solution
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let mut lesson = TwoMirrors::new(gpu, scene, knobs)?;
        let replace = knobs.get("mark") == "replace";
        // Each level's mark, for both front faces, with the depth test off.
        lesson.mark_level = [FrontFace::Ccw, FrontFace::Cw].map(|face| {
            let (_, mark, _) = level_recipes(face, replace);
            let recipe = Recipe {
                name: "MARK_LEVEL_NO_DEPTH_TEST",
                depth_compare: CompareFunction::Always,
                ..mark
            };
            scene.pipeline(&gpu.device, &recipe)
        });
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
