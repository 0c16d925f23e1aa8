//! Lesson 2: the stencil test.
//!
//! Two discs are written into the stencil buffer — a porthole of 1s with a bullseye of 2s — and the
//! room is drawn through them with a stencil state built from the knobs:
//! `(reference & read_mask) CMP (stored & read_mask)` decides, the operations update the buffer.

use workbook::glam::Vec2;
use workbook::room::shapes::{self, Shape};
use workbook::wgpu;
use workbook::{
    Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, gpu::states, lesson::knobs, math::stencil,
};

pub struct StencilBasics {
    mark_shape: wgpu::RenderPipeline,
    draw_through: wgpu::RenderPipeline,
    porthole: Shape,
    bullseye: Shape,
    reference: u32,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "compare",
        values: knobs::COMPARE_VALUES,
        default: "equal",
        meaning: "stencil test: draw where (reference & read-mask) CMP (stored & read-mask)",
    },
    Knob {
        name: "reference",
        values: knobs::BYTE_VALUES,
        default: "1",
        meaning: "the reference value the room is drawn with (set_stencil_reference)",
    },
    Knob {
        name: "read-mask",
        values: knobs::MASK_VALUES,
        default: "0xff",
        meaning: "bits of the reference and of the stored value that the test compares",
    },
    Knob {
        name: "write-mask",
        values: knobs::MASK_VALUES,
        default: "0xff",
        meaning: "bits of the stored value that an operation may change",
    },
    Knob {
        name: "fail-op",
        values: stencil::OPERATION_VALUES,
        default: "keep",
        meaning: "what happens to the stored value where the stencil test fails",
    },
    Knob {
        name: "depth-fail-op",
        values: stencil::OPERATION_VALUES,
        default: "keep",
        meaning: "... where the stencil test passes but the depth test fails",
    },
    Knob {
        name: "pass-op",
        values: stencil::OPERATION_VALUES,
        default: "keep",
        meaning: "... where both tests pass",
    },
];
// ANCHOR_END: knobs

// ANCHOR: recipe
/// DRAW_THROUGH: the room drawn with the stencil test, masks and operations the knobs choose.
pub fn draw_through(knobs: &Knobs) -> Recipe {
    let face = wgpu::StencilFaceState {
        compare: states::compare_function(knobs.get("compare")),
        fail_op: stencil::operation(knobs.get("fail-op")),
        depth_fail_op: stencil::operation(knobs.get("depth-fail-op")),
        pass_op: stencil::operation(knobs.get("pass-op")),
    };
    Recipe {
        name: "DRAW_THROUGH",
        stencil: wgpu::StencilState {
            front: face,
            back: face,
            read_mask: knobs::byte(knobs.get("read-mask")) as u32,
            write_mask: knobs::byte(knobs.get("write-mask")) as u32,
        },
        ..states::OPAQUE
    }
}
// ANCHOR_END: recipe

impl Lesson for StencilBasics {
    const NAME: &'static str = "stencil-basics";
    const TITLE: &'static str = "Lesson 2: the stencil test";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let device = &gpu.device;
        Ok(Self {
            mark_shape: shapes::pipeline(device, scene, &states::MARK_SHAPE),
            draw_through: scene.pipeline(device, &draw_through(knobs)),
            porthole: Shape::disc(device, "porthole", Vec2::new(0.0, 0.0), 0.8),
            bullseye: Shape::disc(device, "bullseye", Vec2::new(0.0, 0.0), 0.35),
            reference: knobs::byte(knobs.get("reference")) as u32,
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // Clear colour, depth (to 1.0) and stencil (to 0).
        frame.clear();

        // Write the shapes into the stencil buffer with MARK_SHAPE (compare Always, pass op
        // Replace, no colour, no depth): the porthole with reference 1, then the bullseye inside
        // it with reference 2. The buffer then holds 0 outside, 1 in the ring, 2 inside.
        frame.step("mark the porthole", |pass| {
            pass.set_pipeline(&self.mark_shape);
            pass.set_stencil_reference(1);
            self.porthole.draw(pass);
        });
        frame.step("mark the bullseye", |pass| {
            pass.set_pipeline(&self.mark_shape);
            pass.set_stencil_reference(2);
            self.bullseye.draw(pass);
        });

        // Draw the room through the stencil with DRAW_THROUGH, the knobs' stencil state, and the
        // knobs' reference. Nearest first, so the wall behind the skull fails the depth test (and
        // gets the depth-fail operation).
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
    // ANCHOR_END: render
}
