//! Lesson 3: marking the mirror.
//!
//! The room is drawn as usual; then the mirror is drawn into the stencil buffer only, writing 1 where
//! it is visible. The crate in front of the mirror leaves a hole in the mark, because the mark keeps
//! the depth test: that hole is what will stop the reflection being drawn over the crate.

use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, Show, gpu::states, lesson::knobs};

pub struct MarkMirror {
    draw_room: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[Knob {
    name: "mark-depth-test",
    values: knobs::ON_OFF,
    default: "on",
    meaning: "whether MARK_MIRROR keeps the depth test, so the crate in front leaves a hole",
}];
// ANCHOR_END: knobs

// ANCHOR: recipes
/// MARK_MIRROR, or with mark-depth-test=off the wrong way: a mark that ignores what stands in front
/// of the mirror.
pub fn mark_mirror(knobs: &Knobs) -> Recipe {
    if knobs.is_on("mark-depth-test") {
        states::MARK_MIRROR
    } else {
        Recipe {
            depth_compare: wgpu::CompareFunction::Always,
            ..states::MARK_MIRROR
        }
    }
}
// ANCHOR_END: recipes

impl Lesson for MarkMirror {
    const NAME: &'static str = "mark-mirror";
    const TITLE: &'static str = "Lesson 3: marking the mirror";
    const KNOBS: &'static [Knob] = KNOBS;
    /// The mark is invisible in the colours: show the stencil buffer (0 dark, 1 white).
    const SHOWS: Show = Show::Stencil;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            draw_room: scene.pipeline(&gpu.device, &states::OPAQUE),
            mark_mirror: scene.pipeline(&gpu.device, &mark_mirror(knobs)),
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // Clear colour, depth (to 1.0) and stencil (to 0).
        frame.clear();

        // Draw the room as usual, all but the mirror: the crate and the skull now hold the depth
        // of everything in front of the mirror.
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            scene.draw_room(pass);
        });

        // Mark the mirror: MARK_MIRROR writes the reference, 1, into the stencil buffer wherever a
        // mirror fragment passes the depth test. It writes no colour, so the mirror's pixels still
        // show the sky behind it.
        frame.step("mark the mirror", |pass| {
            pass.set_pipeline(&self.mark_mirror);
            pass.set_stencil_reference(1);
            scene.mirror.draw(pass);
        });
    }
    // ANCHOR_END: render
}
