//! Lesson 1: the depth test.
//!
//! The room is drawn nearest object first. With the depth test on, each pixel keeps the nearest
//! surface whatever the order; with `depth=always` (or `depth-write=off`) the last object drawn wins
//! and the floor and wall are painted over the skull and the crate.

use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, gpu::states, lesson::knobs};

pub struct DepthTest {
    /// The room's pipeline: the OPAQUE recipe with the depth state the knobs choose.
    draw_room: wgpu::RenderPipeline,
    near_first: bool,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "depth",
        values: knobs::COMPARE_VALUES,
        default: "less",
        meaning: "depth compare: keep a fragment when (its depth CMP the stored depth)",
    },
    Knob {
        name: "depth-write",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether a fragment that passes writes its depth into the buffer",
    },
    Knob {
        name: "order",
        values: &["near-first", "far-first"],
        default: "near-first",
        meaning: "draw the skull and crate before the wall and floor, or after (the painter's order)",
    },
];
// ANCHOR_END: knobs

// ANCHOR: recipe
/// DRAW_ROOM: the OPAQUE recipe with the depth test the knobs choose.
pub fn draw_room(knobs: &Knobs) -> Recipe {
    Recipe {
        name: "DRAW_ROOM",
        depth_compare: states::compare_function(knobs.get("depth")),
        depth_write: knobs.is_on("depth-write"),
        ..states::OPAQUE
    }
}
// ANCHOR_END: recipe

impl Lesson for DepthTest {
    const NAME: &'static str = "depth-test";
    const TITLE: &'static str = "Lesson 1: the depth test";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Ok(Self {
            draw_room: scene.pipeline(&gpu.device, &draw_room(knobs)),
            near_first: knobs.get("order") == "near-first",
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // Clear: colour to the sky, every depth to 1.0 (the far plane), stencil to 0.
        frame.clear();

        // Draw the room with DRAW_ROOM, one object a step. Near first is the order that shows what
        // the depth test does: with it on, the later, farther wall loses every pixel the skull
        // already holds.
        let mut objects = [
            ("draw the skull", &scene.skull),
            ("draw the crate", &scene.crate_box),
            ("draw the mirror", &scene.mirror),
            ("draw the wall", &scene.wall),
            ("draw the floor", &scene.floor),
        ];
        if !self.near_first {
            objects.reverse();
        }
        for (step, object) in objects {
            frame.step(step, |pass| {
                pass.set_pipeline(&self.draw_room);
                object.draw(pass);
            });
        }
    }
    // ANCHOR_END: render
}
