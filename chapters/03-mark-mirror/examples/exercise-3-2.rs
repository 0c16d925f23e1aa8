//! Lesson 3, exercise 2: mark what hides the mirror too. In the same single draw of the mirror, write
//! 1 where the mirror is seen and 2 where something in front of it hides it, with one reference.

use mark_mirror::{KNOBS, mark_mirror};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, Show, gpu::states};

pub struct Solution {
    draw_room: wgpu::RenderPipeline,
    mark_seen_and_hidden: wgpu::RenderPipeline,
}

// ANCHOR: solution
/// The lesson's MARK_MIRROR with other operations. Drawn with reference 2: where the mirror passes
/// the depth test, 0 + 1 = 1; where it fails (something nearer is there), the reference, 2.
pub fn mark_seen_and_hidden(knobs: &Knobs) -> Recipe {
    let face = wgpu::StencilFaceState {
        compare: wgpu::CompareFunction::Always,
        fail_op: wgpu::StencilOperation::Keep,
        depth_fail_op: wgpu::StencilOperation::Replace,
        pass_op: wgpu::StencilOperation::IncrementClamp,
    };
    let mark = mark_mirror(knobs);
    Recipe {
        name: "MARK_SEEN_AND_HIDDEN",
        stencil: wgpu::StencilState {
            front: face,
            back: face,
            ..mark.stencil
        },
        ..mark
    }
}
// ANCHOR_END: solution

impl Lesson for Solution {
    const NAME: &'static str = "mark-mirror-exercise-2";
    const TITLE: &'static str = "Lesson 3, exercise 2: mark what hides the mirror too";
    const KNOBS: &'static [Knob] = KNOBS;
    const SHOWS: Show = Show::Stencil;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            draw_room: scene.pipeline(&gpu.device, &states::OPAQUE),
            mark_seen_and_hidden: scene.pipeline(&gpu.device, &mark_seen_and_hidden(knobs)),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            scene.draw_room(pass);
        });
        frame.step("mark the mirror, seen and hidden", |pass| {
            pass.set_pipeline(&self.mark_seen_and_hidden);
            pass.set_stencil_reference(2);
            scene.mirror.draw(pass);
        });
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
