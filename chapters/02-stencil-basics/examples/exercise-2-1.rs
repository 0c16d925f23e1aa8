//! Lesson 2, exercise 1: a Venn diagram in the stencil buffer. Mark three overlapping discs so that
//! each pixel counts the discs that cover it (0 to 3), then draw the room with the lesson's
//! stencil test: `reference=2` shows the room where exactly two discs overlap.

use stencil_basics::{KNOBS, draw_through};
use workbook::glam::Vec2;
use workbook::room::shapes::{self, Shape};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, gpu::states, lesson::knobs};

/// The discs' centres (screen units: the screen is 2 high) and their radius.
pub const CENTRES: [Vec2; 3] = [
    Vec2::new(-0.3, 0.2),
    Vec2::new(0.3, 0.2),
    Vec2::new(0.0, -0.3),
];
pub const RADIUS: f32 = 0.5;

pub struct Solution {
    count_shape: wgpu::RenderPipeline,
    draw_through: wgpu::RenderPipeline,
    discs: Vec<Shape>,
    reference: u32,
}

// ANCHOR: solution
/// MARK_SHAPE counting instead of replacing: each disc adds 1 where it covers (clamped at 255).
pub const COUNT_SHAPE: Recipe = Recipe {
    name: "COUNT_SHAPE",
    stencil: wgpu::StencilState {
        front: COUNT,
        back: COUNT,
        read_mask: 0xff,
        write_mask: 0xff,
    },
    ..states::MARK_SHAPE
};

const COUNT: wgpu::StencilFaceState = wgpu::StencilFaceState {
    compare: wgpu::CompareFunction::Always,
    fail_op: wgpu::StencilOperation::Keep,
    depth_fail_op: wgpu::StencilOperation::Keep,
    pass_op: wgpu::StencilOperation::IncrementClamp,
};

impl Solution {
    fn count_discs(&self, frame: &mut Frame<'_>) {
        frame.step("count the discs", |pass| {
            pass.set_pipeline(&self.count_shape);
            self.discs.iter().for_each(|disc| disc.draw(pass));
        });
    }
}
// ANCHOR_END: solution

impl Lesson for Solution {
    const NAME: &'static str = "stencil-basics-exercise-1";
    const TITLE: &'static str = "Lesson 2, exercise 1: a Venn diagram in the stencil buffer";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let names = ["left disc", "right disc", "lower disc"];
        Ok(Self {
            count_shape: shapes::pipeline(device, scene, &COUNT_SHAPE),
            draw_through: scene.pipeline(device, &draw_through(knobs)),
            discs: (CENTRES.iter().zip(names))
                .map(|(&centre, name)| Shape::disc(device, name, centre, RADIUS))
                .collect(),
            reference: knobs::byte(knobs.get("reference")) as u32,
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();
        self.count_discs(frame);
        frame.step("draw the room through the stencil", |pass| {
            pass.set_pipeline(&self.draw_through);
            pass.set_stencil_reference(self.reference);
            for object in [
                &scene.skull,
                &scene.crate_box,
                &scene.mirror,
                &scene.wall,
                &scene.floor,
            ] {
                object.draw(pass);
            }
        });
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
