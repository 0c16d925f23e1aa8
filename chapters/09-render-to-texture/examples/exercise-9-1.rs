//! Lesson 9, exercise 1: draw the reflected camera's view with the usual front face (counter-
//! clockwise), forgetting lesson 5. What does the stone show of the crate and the skull, and why?

use render_to_texture::{RenderToTexture, reflected_view_recipe};
use workbook::room::camera::Camera;
use workbook::wgpu::FrontFace;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: RenderToTexture,
}

impl Lesson for Solution {
    const NAME: &'static str = "render-to-texture-exercise-1";
    const TITLE: &'static str = "Lesson 9, exercise 1: the reflected view without the winding fix";
    const KNOBS: &'static [Knob] = render_to_texture::KNOBS;
    const CAMERA: Camera = RenderToTexture::CAMERA;

    // ANCHOR: solution
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let mut lesson = RenderToTexture::new(gpu, scene, knobs)?;
        // The lesson's recipe for the reflected view (view · R, clipped), with wgpu's default
        // front face instead of the clockwise one a reflection needs.
        let unflipped = Recipe {
            name: "DRAW_REFLECTED_VIEW_UNFLIPPED",
            front_face: FrontFace::Ccw,
            ..reflected_view_recipe(false, knobs.is_on("clip"))
        };
        lesson.draw_reflected_view = scene.pipeline(&gpu.device, &unflipped);
        Ok(Self { lesson })
    }
    // ANCHOR_END: solution

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
