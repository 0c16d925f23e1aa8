//! Lesson 8, exercise 1: mark the floor mirror without the depth test (depth compare `Always`), as
//! if nothing could stand on the stone. Look at the crate and the skull, and explain what you see.

use floor_mirror::FloorMirror;
use workbook::gpu::states;
use workbook::room::camera::Camera;
use workbook::wgpu::CompareFunction;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: FloorMirror,
}

impl Lesson for Solution {
    const NAME: &'static str = "floor-mirror-exercise-1";
    const TITLE: &'static str = "Lesson 8, exercise 1: the mark without the depth test";
    const KNOBS: &'static [Knob] = floor_mirror::KNOBS;
    const CAMERA: Camera = FloorMirror::CAMERA;

    // ANCHOR: solution
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let mut lesson = FloorMirror::new(gpu, scene, knobs)?;
        // MARK_MIRROR with the depth test off: every pixel of the stone is marked, also where
        // the crate or the skull stands in front of it.
        let mark_everywhere = Recipe {
            name: "MARK_MIRROR_NO_DEPTH_TEST",
            depth_compare: CompareFunction::Always,
            ..states::MARK_MIRROR
        };
        lesson.mark_mirror = scene.pipeline(&gpu.device, &mark_everywhere);
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
