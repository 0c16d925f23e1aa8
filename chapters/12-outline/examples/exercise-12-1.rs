//! Lesson 12, exercise 1: the hidden part of the band, dimmed. The band is drawn where nothing
//! stands in front of it, as with outline-depth=less, and where something does, at 35 % over it.

use outline::{Outline, SELECTION_BIT, SHADER};
use workbook::wgpu::{self, CompareFunction};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: Outline,
    hidden: wgpu::RenderPipeline,
}

// ANCHOR: solution
/// How much of the band shows where something hides it.
pub const DIMMED: f64 = 0.35;

/// The lesson's outline, hidden by what is nearer.
pub const KNOB_VALUES: &[&str] = &["outline-depth=less"];

/// The band's hidden part: OUTLINE where the copy is *not* nearer than what is there, mixed in by
/// the blend constant — once a pixel: where it passes, it sets the selection bit, so that another
/// layer of the copy behind the same pixel fails (lesson 10's NO_DOUBLE_BLEND, by a bit).
pub fn hidden_outline(outline: &Recipe) -> Recipe {
    let once = wgpu::StencilFaceState {
        compare: CompareFunction::NotEqual,
        pass_op: wgpu::StencilOperation::Replace,
        ..outline.stencil.front
    };
    Recipe {
        name: "OUTLINE_HIDDEN",
        depth_compare: CompareFunction::GreaterEqual,
        stencil: wgpu::StencilState {
            front: once,
            back: once,
            read_mask: SELECTION_BIT,
            write_mask: SELECTION_BIT,
        },
        blend: Some(wgpu::BlendState {
            color: wgpu::BlendComponent {
                src_factor: wgpu::BlendFactor::Constant,
                dst_factor: wgpu::BlendFactor::OneMinusConstant,
                operation: wgpu::BlendOperation::Add,
            },
            alpha: wgpu::BlendComponent::OVER,
        }),
        ..outline.clone()
    }
}

impl Solution {
    fn outline_hidden_part(&self, frame: &mut Frame<'_>) {
        let skull = &frame.scene.skull;
        frame.step("outline the hidden part, dimmed", |pass| {
            pass.set_pipeline(&self.hidden);
            pass.set_stencil_reference(SELECTION_BIT);
            pass.set_blend_constant(wgpu::Color {
                r: DIMMED,
                g: DIMMED,
                b: DIMMED,
                a: 1.0,
            });
            skull.draw(pass);
        });
    }
}
// ANCHOR_END: solution

impl Lesson for Solution {
    const NAME: &'static str = "outline-exercise-1";
    const TITLE: &'static str = "Lesson 12, exercise 1: the hidden part, dimmed";
    const KNOBS: &'static [Knob] = &[];

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let knobs = Knobs::from_settings(outline::KNOBS, KNOB_VALUES)?;
        let recipe = hidden_outline(&outline::recipes(&knobs).outline);
        let shader = scene.shader_with(&gpu.device, "outline.wgsl", SHADER);
        Ok(Self {
            lesson: Outline::new(gpu, scene, &knobs)?,
            hidden: scene.pipeline_in(&gpu.device, &recipe, (&shader, "vs_grown", "fs_outline")),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
        self.outline_hidden_part(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
