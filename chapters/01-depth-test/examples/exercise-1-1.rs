//! Lesson 1, exercise 1: a depth pre-pass. Draw every object once writing depth only, then once
//! more writing colour with the depth test `Equal` and no depth writes: the picture is the lesson's,
//! and each pixel is shaded once, by the surface that owns it.

use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    depth_only: wgpu::RenderPipeline,
    shade_equal: wgpu::RenderPipeline,
}

// ANCHOR: solution
/// The pre-pass: the lesson's DRAW_ROOM with every colour channel off; only depth is written.
pub fn depth_only(knobs: &Knobs) -> Recipe {
    Recipe {
        name: "DEPTH_PRE_PASS",
        color_writes: wgpu::ColorWrites::empty(),
        ..depth_test::draw_room(knobs)
    }
}

/// The shading pass: keep a fragment only where its depth is the one the pre-pass left there, and
/// leave the depth buffer as it is.
pub fn shade_equal(knobs: &Knobs) -> Recipe {
    Recipe {
        name: "SHADE_EQUAL",
        depth_compare: wgpu::CompareFunction::Equal,
        depth_write: false,
        ..depth_test::draw_room(knobs)
    }
}

impl Solution {
    fn draw_twice(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let objects = [
            &scene.skull,
            &scene.crate_box,
            &scene.mirror,
            &scene.wall,
            &scene.floor,
        ];
        frame.step("depth pre-pass", |pass| {
            pass.set_pipeline(&self.depth_only);
            objects.iter().for_each(|object| object.draw(pass));
        });
        frame.step("shade where the depth is equal", |pass| {
            pass.set_pipeline(&self.shade_equal);
            objects.iter().for_each(|object| object.draw(pass));
        });
    }
}
// ANCHOR_END: solution

impl Lesson for Solution {
    const NAME: &'static str = "depth-test-exercise-1";
    const TITLE: &'static str = "Lesson 1, exercise 1: a depth pre-pass";
    /// The lesson's knobs: `depth` and `depth-write` set the pre-pass (`order` changes nothing here).
    const KNOBS: &'static [Knob] = depth_test::KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            depth_only: scene.pipeline(&gpu.device, &depth_only(knobs)),
            shade_equal: scene.pipeline(&gpu.device, &shade_equal(knobs)),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        frame.clear();
        self.draw_twice(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
