//! Lesson 6, exercise 2: tinted glass. Blend the glass over the reflection with a constant blend
//! colour instead of the material's alpha, one factor per channel, so the mirror keeps 20% of the
//! glass in red, 50% in green and 80% in blue.

use workbook::lesson::mirror::MarkedRoom;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, gpu::states};

pub struct Solution {
    marked_room: MarkedRoom,
    draw_reflection: wgpu::RenderPipeline,
    draw_tinted: wgpu::RenderPipeline,
}

// ANCHOR: solution
/// How much of the glass each channel keeps: C = k·Cglass + (1 − k)·Creflection, per channel.
pub const TINT: wgpu::Color = wgpu::Color {
    r: 0.2,
    g: 0.5,
    b: 0.8,
    a: 1.0,
};

/// TRANSPARENT with the blend constant in place of the fragment's alpha.
pub const TINTED_GLASS: Recipe = Recipe {
    name: "TINTED_GLASS",
    blend: Some(wgpu::BlendState {
        color: wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::Constant,
            dst_factor: wgpu::BlendFactor::OneMinusConstant,
            operation: wgpu::BlendOperation::Add,
        },
        alpha: wgpu::BlendComponent::OVER,
    }),
    ..states::TRANSPARENT
};

impl Solution {
    fn draw_glass(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.step("draw the tinted glass", |pass| {
            pass.set_pipeline(&self.draw_tinted);
            // Not part of the pipeline: set on the pass, like the stencil reference.
            pass.set_blend_constant(TINT);
            scene.mirror.draw(pass);
        });
    }
}
// ANCHOR_END: solution

impl Lesson for Solution {
    const NAME: &'static str = "transparent-mirror-exercise-2";
    const TITLE: &'static str = "Lesson 6, exercise 2: tinted glass";
    const KNOBS: &'static [Knob] = &[];

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            marked_room: MarkedRoom::new(gpu, scene),
            draw_reflection: scene.pipeline(&gpu.device, &states::FRONT_CLOCKWISE),
            draw_tinted: scene.pipeline(&gpu.device, &TINTED_GLASS),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        self.marked_room.steps(frame);
        frame.step("draw the reflected skull", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            scene.bind_reflected_frame(pass);
            scene.skull.draw_reflected(pass);
        });
        self.draw_glass(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
