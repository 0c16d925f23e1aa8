//! Lesson 10, exercise 2: let the crate cast a shadow too, from the same key light, so that where
//! the crate's shadow and the skull's overlap the floor is darkened once, not twice.

use planar_shadow::{PlanarShadow, draw_shadow, key_light, shadow_plane, shadow_world};
use workbook::room::camera::Camera;
use workbook::room::scene::{Placed, SHADOW_MATERIAL};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene};

pub struct Solution {
    lesson: PlanarShadow,
    draw_shadow: wgpu::RenderPipeline,
    crate_shadow: Placed,
}

impl Lesson for Solution {
    const NAME: &'static str = "planar-shadow-exercise-2";
    const TITLE: &'static str = "Lesson 10, exercise 2: the crate's shadow";
    const KNOBS: &'static [Knob] = planar_shadow::KNOBS;
    const CAMERA: Camera = PlanarShadow::CAMERA;

    // ANCHOR: solution
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let surface = knobs.get("surface");
        let key = key_light(knobs.get("light"), surface);
        // The crate flattened along the same light onto the same plane, black at 50%.
        let world = shadow_world(
            scene.crate_box.world(),
            &key,
            shadow_plane(surface),
            knobs.get("lift"),
        );
        let crate_shadow =
            scene.placed_as(&gpu.device, &scene.crate_box, world, Some(SHADOW_MATERIAL));
        Ok(Self {
            lesson: PlanarShadow::new(gpu, scene, knobs)?,
            draw_shadow: scene.pipeline(&gpu.device, &draw_shadow(knobs)),
            crate_shadow,
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
        // After the skull's shadow, with the same recipe and reference 0: where the skull's
        // shadow already set the stencil to 1, the crate's fails.
        let scene = frame.scene;
        frame.step("draw the crate's shadow", |pass| {
            pass.set_pipeline(&self.draw_shadow);
            pass.set_stencil_reference(0);
            scene.crate_box.draw_placed(pass, &self.crate_shadow);
        });
    }
    // ANCHOR_END: solution
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
