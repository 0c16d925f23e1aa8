//! Lesson 3: marking the mirror.
//!
//! The room is drawn as usual; then the mirror is drawn into the stencil buffer only, writing 1 where
//! it is visible. The crate in front of the mirror leaves a hole in the mark, because the mark keeps
//! the depth test: that hole is what will stop the reflection being drawn over the crate.

use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, Start, knobs, states};

pub struct MarkMirror {
    draw_room: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
    show_stencil: bool,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "mark-depth-test",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether MARK_MIRROR keeps the depth test, so the crate in front leaves a hole",
    },
    Knob {
        name: "view",
        values: &["stencil", "color"],
        default: "stencil",
        meaning: "show the stencil buffer in false colour (0 dark, 1 white), or the colours",
    },
];
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

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            draw_room: scene.pipeline(&gpu.device, &states::OPAQUE),
            mark_mirror: scene.pipeline(&gpu.device, &mark_mirror(knobs)),
            show_stencil: knobs.get("view") == "stencil",
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // 1. Clear colour, depth (to 1.0) and stencil (to 0).
        let mut pass = frame.pass("mark mirror", Start::Cleared);

        // 2. Draw the room as usual, all but the mirror: the crate and the skull now hold the depth
        //    of everything in front of the mirror.
        pass.set_pipeline(&self.draw_room);
        scene.draw_room(&mut pass);

        // 3. Mark the mirror: MARK_MIRROR writes the reference, 1, into the stencil buffer wherever a
        //    mirror fragment passes the depth test. It writes no colour, so the mirror's pixels still
        //    show the sky behind it.
        pass.set_pipeline(&self.mark_mirror);
        pass.set_stencil_reference(1);
        scene.mirror.draw(&mut pass);
        drop(pass);

        // 4. With view=stencil, show what the stencil buffer now holds.
        if self.show_stencil {
            frame.show_stencil();
        }
    }
    // ANCHOR_END: render
}
