// ANCHOR: top
//! The smallest lesson, the example of the book's page "Writing a lesson": the skull marked in the
//! stencil buffer.
//!
//! The room is drawn, then the skull a second time, into the stencil buffer only. The second time,
//! each of its fragments meets the depth its first drawing stored: `LessEqual` keeps it and the mark
//! covers the skull where it is seen; `Less` throws every one away and the mark is empty.

use workbook::room::camera::Camera;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, Show, gpu::states};

/// The lesson's pipelines, built for one setting of its knob.
pub struct MyLesson {
    draw_room: wgpu::RenderPipeline,
    mark_skull: wgpu::RenderPipeline,
}
// ANCHOR_END: top

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[Knob {
    name: "mark-depth",
    values: &["less-equal", "less"],
    default: "less-equal",
    meaning: "the mark's depth test: the skull drawn again meets its own depth",
}];
// ANCHOR_END: knobs

// ANCHOR: recipe
/// MARK_SKULL: MARK_MIRROR's states (stencil test `Always`, pass op `Replace`, no colour, no depth
/// writes) with the depth test the knob chooses.
pub fn mark_skull(knobs: &Knobs) -> Recipe {
    Recipe {
        name: "MARK_SKULL",
        depth_compare: states::compare_function(knobs.get("mark-depth")),
        ..states::MARK_MIRROR
    }
}
// ANCHOR_END: recipe

// ANCHOR: consts
impl Lesson for MyLesson {
    const NAME: &'static str = "my-lesson";
    const TITLE: &'static str = "My lesson: the skull's mark";
    const KNOBS: &'static [Knob] = KNOBS;
    /// The mark is invisible in the colours: show the stencil buffer (0 dark, 1 white).
    const SHOWS: Show = Show::Stencil;
    /// Nearer the skull than the book's pose (22,14,11).
    const CAMERA: Camera = Camera {
        yaw: 22.0,
        pitch: 14.0,
        distance: 7.0,
    };
    // ANCHOR_END: consts

    // ANCHOR: new
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            draw_room: scene.pipeline(&gpu.device, &states::OPAQUE),
            mark_skull: scene.pipeline(&gpu.device, &mark_skull(knobs)),
        })
    }
    // ANCHOR_END: new

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // Colour to the sky, every depth to 1.0, every stencil value to 0.
        frame.clear();

        // The floor, the wall, the crate and the skull, with the usual depth test.
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            scene.draw_room(pass);
        });

        // The skull again, with MARK_SKULL: 1 into the stencil buffer wherever its fragment passes
        // the depth test against the depth its first drawing stored.
        frame.step("mark the skull", |pass| {
            pass.set_pipeline(&self.mark_skull);
            pass.set_stencil_reference(1);
            scene.skull.draw(pass);
        });
    }
}
// ANCHOR_END: render
