//! Lesson 5: the winding fix.
//!
//! A reflection has determinant −1: it turns counter-clockwise triangles clockwise on screen. So the
//! reflected pass tells the rasterizer that clockwise is the front (FRONT_CLOCKWISE), and the
//! mirror shows the skull's outside again.

use workbook::lesson::mirror::MarkedRoom;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene, gpu::states};

pub struct WindingFix {
    marked_room: MarkedRoom,
    draw_reflection: wgpu::RenderPipeline,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[Knob {
    name: "winding-fix",
    values: &["front-face-cw", "cull-front", "no-culling", "off"],
    default: "front-face-cw",
    meaning: "how the reflected pass copes with flipped winding (off: lesson 4's inside-out skull)",
}];
// ANCHOR_END: knobs

// ANCHOR: recipes
/// The recipe of the reflected pass for a value of the `winding-fix` knob.
pub fn reflection_recipe(winding_fix: &str) -> Recipe {
    match winding_fix {
        // Fix 1: clockwise is the front now; cull the back faces as always.
        "front-face-cw" => states::FRONT_CLOCKWISE,
        // Fix 2, the same pixels: keep counter-clockwise as the front, cull the front faces instead.
        "cull-front" => Recipe {
            name: "DRAW_REFLECTION_CULL_FRONT",
            cull_mode: Some(wgpu::Face::Front),
            ..states::DRAW_REFLECTION
        },
        // Not a fix: both sides are drawn, the depth test sorts them out, at twice the cost.
        "no-culling" => Recipe {
            name: "DRAW_REFLECTION_NO_CULLING",
            cull_mode: None,
            ..states::DRAW_REFLECTION
        },
        // Lesson 4: the usual front face, so the outside is culled and the inside shows.
        _ => states::DRAW_REFLECTION,
    }
}
// ANCHOR_END: recipes

impl Lesson for WindingFix {
    const NAME: &'static str = "winding-fix";
    const TITLE: &'static str = "Lesson 5: the winding fix";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let draw_reflection = reflection_recipe(knobs.get("winding-fix"));
        Ok(Self {
            marked_room: MarkedRoom::new(gpu, scene),
            draw_reflection: scene.pipeline(&gpu.device, &draw_reflection),
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // Clear, draw the room but the mirror, mark the mirror with 1 (lesson 3).
        self.marked_room.steps(frame);

        // Draw the reflected skull where the stencil is 1 (lesson 4), now with FRONT_CLOCKWISE: the
        // triangles the reflection turned clockwise are the ones facing the camera.
        frame.step("draw the reflected skull", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            scene.bind_reflected_frame(pass);
            scene.skull.draw_reflected(pass);
        });
    }
    // ANCHOR_END: render
}
