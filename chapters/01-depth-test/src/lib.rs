//! Lesson 1: the depth test.
//!
//! The room is drawn nearest object first. With the depth test on, each pixel keeps the nearest
//! surface whatever the order; with `depth=always` (or `depth-write=off`) the last object drawn wins
//! and the floor and wall are painted over the skull and the crate.

use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, Start, knobs, states};

pub struct DepthTest {
    /// The room's pipeline: the OPAQUE recipe with the depth state the knobs choose.
    draw_room: wgpu::RenderPipeline,
    near_first: bool,
    show_depth: bool,
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
    Knob {
        name: "view",
        values: &["color", "depth"],
        default: "color",
        meaning: "show the colours, or the depth buffer (left raw, right linearised)",
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
            show_depth: knobs.get("view") == "depth",
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // 1. Clear: colour to the sky, every depth to 1.0 (the far plane), stencil to 0.
        let mut pass = frame.pass("room", Start::Cleared);

        // 2. Draw the room with DRAW_ROOM. Near first is the order that shows what the depth test
        //    does: with it on, the later, farther wall loses every pixel the skull already holds.
        pass.set_pipeline(&self.draw_room);
        let mut objects = [
            &scene.skull,
            &scene.crate_box,
            &scene.mirror,
            &scene.wall,
            &scene.floor,
        ];
        if !self.near_first {
            objects.reverse();
        }
        for object in objects {
            object.draw(&mut pass);
        }
        drop(pass);

        // 3. With view=depth, draw what the depth buffer holds instead of the colours.
        if self.show_depth {
            frame.show_depth();
        }
    }
    // ANCHOR_END: render
}
