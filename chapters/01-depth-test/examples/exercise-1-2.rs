//! Lesson 1, exercise 2: the skull that forgets its depth. Draw the skull with depth writes off and
//! everything else as the lesson does; drawn near first, the wall and mirror paint over it, drawn far
//! first it shows again. Explain both pictures.

use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    draw_room: wgpu::RenderPipeline,
    draw_skull: wgpu::RenderPipeline,
    near_first: bool,
}

// ANCHOR: solution
/// The skull's own recipe: the lesson's DRAW_ROOM, testing depth but never writing it.
pub fn draw_skull(knobs: &Knobs) -> Recipe {
    Recipe {
        name: "DRAW_SKULL_NO_DEPTH_WRITE",
        depth_write: false,
        ..depth_test::draw_room(knobs)
    }
}

impl Solution {
    fn draw_objects(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let mut objects = [
            ("draw the skull", &scene.skull, &self.draw_skull),
            ("draw the crate", &scene.crate_box, &self.draw_room),
            ("draw the mirror", &scene.mirror, &self.draw_room),
            ("draw the wall", &scene.wall, &self.draw_room),
            ("draw the floor", &scene.floor, &self.draw_room),
        ];
        if !self.near_first {
            objects.reverse();
        }
        for (step, object, pipeline) in objects {
            frame.step(step, |pass| {
                pass.set_pipeline(pipeline);
                object.draw(pass);
            });
        }
    }
}
// ANCHOR_END: solution

impl Lesson for Solution {
    const NAME: &'static str = "depth-test-exercise-2";
    const TITLE: &'static str = "Lesson 1, exercise 2: the skull that forgets its depth";
    const KNOBS: &'static [Knob] = depth_test::KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            draw_room: scene.pipeline(&gpu.device, &depth_test::draw_room(knobs)),
            draw_skull: scene.pipeline(&gpu.device, &draw_skull(knobs)),
            near_first: knobs.get("order") == "near-first",
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        frame.clear();
        self.draw_objects(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
