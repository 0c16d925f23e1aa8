//! Lesson 4: the reflected skull.
//!
//! The skull is drawn a second time, transformed by the reflection in the mirror's plane and lit by
//! reflected lights, only where lesson 3's mark holds 1. This lesson keeps the usual front face, so
//! the reflection comes out inside out: lesson 5 fixes that.

use workbook::lesson::mirror::MarkedRoom;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, gpu::states, lesson::knobs};

pub struct ReflectSkull {
    marked_room: MarkedRoom,
    draw_reflection: wgpu::RenderPipeline,
    reflect_lights: bool,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "stencil",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether DRAW_REFLECTION tests the stencil; off, the reflection shows outside the mirror",
    },
    Knob {
        name: "reflect-lights",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether the reflection is lit by reflected lights; off, it is lit from the wrong side",
    },
];
// ANCHOR_END: knobs

// ANCHOR: recipes
/// DRAW_REFLECTION, or with stencil=off the wrong way: the reflection drawn wherever its depth test
/// passes.
pub fn draw_reflection(knobs: &Knobs) -> Recipe {
    if knobs.is_on("stencil") {
        states::DRAW_REFLECTION
    } else {
        Recipe {
            stencil: states::NO_STENCIL,
            ..states::DRAW_REFLECTION
        }
    }
}
// ANCHOR_END: recipes

impl Lesson for ReflectSkull {
    const NAME: &'static str = "reflect-skull";
    const TITLE: &'static str = "Lesson 4: the reflected skull";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            marked_room: MarkedRoom::new(gpu, scene),
            draw_reflection: scene.pipeline(&gpu.device, &draw_reflection(knobs)),
            reflect_lights: knobs.is_on("reflect-lights"),
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // Clear, draw the room but the mirror, mark the mirror's visible pixels with 1 (lesson 3's
        // frame, kept in the framework as MarkedRoom).
        self.marked_room.steps(frame);

        // Draw the skull again, reflected in the mirror's plane (world matrix R * world) and lit by
        // the reflected lights, with DRAW_REFLECTION: only where the stencil equals the reference,
        // 1. Its triangles now wind the other way on screen, and this recipe still culls "back"
        // faces by the usual rule — the skull shows its inside (lesson 5).
        frame.step("draw the reflected skull", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            if self.reflect_lights {
                scene.bind_reflected_frame(pass);
            }
            scene.skull.draw_reflected(pass);
        });
    }
    // ANCHOR_END: render
}
