//! Lesson 4: the reflected skull.
//!
//! The skull is drawn a second time, transformed by the reflection in the mirror's plane and lit by
//! reflected lights, only where lesson 3's mark holds 1. This lesson keeps the usual front face, so
//! the reflection comes out inside out: lesson 5 fixes that.

use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, Start, knobs, states};

pub struct ReflectSkull {
    draw_room: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
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

impl Lesson for ReflectSkull {
    const NAME: &'static str = "reflect-skull";
    const TITLE: &'static str = "Lesson 4: the reflected skull";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        // ANCHOR: recipes
        let draw_reflection = if knobs.is_on("stencil") {
            states::DRAW_REFLECTION
        } else {
            // The wrong way: the reflection is drawn wherever its depth test passes.
            Recipe {
                stencil: states::NO_STENCIL,
                ..states::DRAW_REFLECTION
            }
        };
        // ANCHOR_END: recipes
        Ok(Self {
            draw_room: scene.pipeline(&gpu.device, &states::OPAQUE),
            mark_mirror: scene.pipeline(&gpu.device, &states::MARK_MIRROR),
            draw_reflection: scene.pipeline(&gpu.device, &draw_reflection),
            reflect_lights: knobs.is_on("reflect-lights"),
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // 1. Clear colour, depth (to 1.0) and stencil (to 0).
        let mut pass = frame.pass("reflect skull", Start::Cleared);

        // 2. Draw the room as usual, all but the mirror.
        pass.set_pipeline(&self.draw_room);
        scene.draw_room(&mut pass);

        // 3. Mark the mirror's visible pixels with 1 (lesson 3).
        pass.set_pipeline(&self.mark_mirror);
        pass.set_stencil_reference(1);
        scene.mirror.draw(&mut pass);

        // 4. Draw the skull again, reflected in the mirror's plane (world matrix R * world) and lit
        //    by the reflected lights, with DRAW_REFLECTION: only where the stencil equals the
        //    reference, 1. Its triangles now wind the other way on screen, and this recipe still
        //    culls "back" faces by the usual rule — the skull shows its inside (lesson 5).
        pass.set_pipeline(&self.draw_reflection);
        pass.set_stencil_reference(1);
        if self.reflect_lights {
            scene.bind_reflected_frame(&mut pass);
        }
        scene.skull.draw_reflected(&mut pass);
    }
    // ANCHOR_END: render
}
