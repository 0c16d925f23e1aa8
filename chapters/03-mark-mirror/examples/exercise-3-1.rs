//! Lesson 3, exercise 1: mark the mirror first. Swap the lesson's two steps, so the mirror is marked
//! before the room is drawn, and explain why the mark now runs under the crate although MARK_MIRROR
//! still tests depth.

use mark_mirror::{KNOBS, mark_mirror};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene, Show, gpu::states};

pub struct Solution {
    draw_room: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
}

impl Lesson for Solution {
    const NAME: &'static str = "mark-mirror-exercise-1";
    const TITLE: &'static str = "Lesson 3, exercise 1: mark the mirror first";
    const KNOBS: &'static [Knob] = KNOBS;
    const SHOWS: Show = Show::Stencil;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            draw_room: scene.pipeline(&gpu.device, &states::OPAQUE),
            mark_mirror: scene.pipeline(&gpu.device, &mark_mirror(knobs)),
        })
    }

    // ANCHOR: solution
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();

        // The mark first: the depth buffer still holds 1.0 everywhere, so every mirror fragment
        // passes the depth test, behind the crate too.
        frame.step("mark the mirror", |pass| {
            pass.set_pipeline(&self.mark_mirror);
            pass.set_stencil_reference(1);
            scene.mirror.draw(pass);
        });
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            scene.draw_room(pass);
        });
    }
    // ANCHOR_END: solution
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
