//! Lesson 2, exercise 2: mark the bullseye first. Swap the two marks and the porthole's `Replace`
//! wipes out the bullseye; keep the new order and change only the porthole's stencil test so that
//! the buffer again holds 0 outside, 1 in the ring and 2 inside.

use stencil_basics::{KNOBS as LESSON_KNOBS, draw_through};
use workbook::glam::Vec2;
use workbook::room::shapes::{self, Shape};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, gpu::states};

pub struct Solution {
    mark_bullseye: wgpu::RenderPipeline,
    mark_porthole: wgpu::RenderPipeline,
    draw_through: wgpu::RenderPipeline,
    porthole: Shape,
    bullseye: Shape,
}

pub const KNOBS: &[Knob] = &[Knob {
    name: "porthole-compare",
    values: &["greater", "always"],
    default: "greater",
    meaning: "the porthole's stencil test: greater keeps the bullseye, always (MARK_SHAPE) wipes it out",
}];

// ANCHOR: solution
/// The porthole's mark, drawn after the bullseye's: Replace with reference 1 only where
/// (1 & 0xff) > (stored & 0xff), that is where nothing is marked yet.
pub fn mark_porthole(compare: &str) -> Recipe {
    let face = wgpu::StencilFaceState {
        compare: states::compare_function(compare),
        ..states::MARK_SHAPE.stencil.front
    };
    Recipe {
        name: "MARK_WHERE_UNMARKED",
        stencil: wgpu::StencilState {
            front: face,
            back: face,
            ..states::MARK_SHAPE.stencil
        },
        ..states::MARK_SHAPE
    }
}

impl Solution {
    fn mark_bullseye_first(&self, frame: &mut Frame<'_>) {
        frame.step("mark the bullseye", |pass| {
            pass.set_pipeline(&self.mark_bullseye);
            pass.set_stencil_reference(2);
            self.bullseye.draw(pass);
        });
        frame.step("mark the porthole", |pass| {
            pass.set_pipeline(&self.mark_porthole);
            pass.set_stencil_reference(1);
            self.porthole.draw(pass);
        });
    }
}
// ANCHOR_END: solution

impl Lesson for Solution {
    const NAME: &'static str = "stencil-basics-exercise-2";
    const TITLE: &'static str = "Lesson 2, exercise 2: mark the bullseye first";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let device = &gpu.device;
        // The room is drawn as the lesson draws it by default: where the stencil equals 1.
        let lesson_knobs = Knobs::defaults(LESSON_KNOBS);
        Ok(Self {
            mark_bullseye: shapes::pipeline(device, scene, &states::MARK_SHAPE),
            mark_porthole: shapes::pipeline(
                device,
                scene,
                &mark_porthole(knobs.get("porthole-compare")),
            ),
            draw_through: scene.pipeline(device, &draw_through(&lesson_knobs)),
            porthole: Shape::disc(device, "porthole", Vec2::ZERO, 0.8),
            bullseye: Shape::disc(device, "bullseye", Vec2::ZERO, 0.35),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();
        self.mark_bullseye_first(frame);
        frame.step("draw the room through the stencil", |pass| {
            pass.set_pipeline(&self.draw_through);
            pass.set_stencil_reference(1);
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
