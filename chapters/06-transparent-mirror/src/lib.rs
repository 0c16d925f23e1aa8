//! Lesson 6: the transparent mirror.
//!
//! A real mirror is glass: its own colour over what it reflects. The mirror is drawn last, blended
//! over the reflection with its material's alpha a: C = a·Cmirror + (1 − a)·Creflection.

use workbook::lesson::mirror::MarkedRoom;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, gpu::states, lesson::knobs};

pub struct TransparentMirror {
    marked_room: MarkedRoom,
    draw_reflection: wgpu::RenderPipeline,
    draw_mirror: wgpu::RenderPipeline,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "mirror-alpha",
        values: &["0", "0.25", "0.5", "0.75", "1"],
        default: "0.5",
        meaning: "the mirror material's alpha: how much of the glass's own colour covers the reflection",
    },
    Knob {
        name: "blend",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether the mirror is blended; off, the opaque glass hides the reflection",
    },
];
// ANCHOR_END: knobs

// ANCHOR: recipes
/// TRANSPARENT for the glass, or with blend=off the wrong way: OPAQUE, the glass replacing whatever
/// the mirror reflected.
pub fn draw_mirror(knobs: &Knobs) -> Recipe {
    if knobs.is_on("blend") {
        states::TRANSPARENT
    } else {
        states::OPAQUE
    }
}
// ANCHOR_END: recipes

impl Lesson for TransparentMirror {
    const NAME: &'static str = "transparent-mirror";
    const TITLE: &'static str = "Lesson 6: the transparent mirror";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        // ANCHOR: alpha
        // The glass's alpha is part of its material: set it from the knob.
        let alpha: f32 = knobs.get("mirror-alpha").parse()?;
        scene.mirror.set_alpha(&gpu.queue, alpha);
        // ANCHOR_END: alpha
        Ok(Self {
            marked_room: MarkedRoom::new(gpu, scene),
            draw_reflection: scene.pipeline(&gpu.device, &states::FRONT_CLOCKWISE),
            draw_mirror: scene.pipeline(&gpu.device, &draw_mirror(knobs)),
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // Clear, draw the room but the mirror, mark the mirror with 1 (lesson 3).
        self.marked_room.steps(frame);

        // Draw the reflected skull where the stencil is 1, right side out (lessons 4 and 5).
        frame.step("draw the reflected skull", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            scene.bind_reflected_frame(pass);
            scene.skull.draw_reflected(pass);
        });

        // Draw the mirror's glass itself, last, with TRANSPARENT: its colour mixed over the
        // reflection, a·Cmirror + (1 − a)·Creflection. The depth test keeps it behind the crate
        // and the skull.
        frame.step("draw the glass", |pass| {
            pass.set_pipeline(&self.draw_mirror);
            scene.mirror.draw(pass);
        });
    }
    // ANCHOR_END: render
}
