//! Lesson 14, exercise 2: the sun. The key light made directional, shining from behind the skull,
//! to the left and above, as the lesson's point light does: every point of a volume then goes to
//! the same point at infinity, and the far cap has no area.

use shadow_volume::ShadowVolume;
use workbook::glam::Vec3;
use workbook::math::shadow::LightSource;
use workbook::room::camera::Camera;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene};

pub struct Solution {
    lesson: ShadowVolume,
}

// ANCHOR: solution
/// The sun: a directional light, its rays going right, down and forwards (towards the camera).
/// The length of the direction does not matter: the volumes and the shader take only its way.
pub const SUN: LightSource = LightSource::Directional {
    direction: Vec3::new(0.6, -1.0, 0.5),
};

impl Lesson for Solution {
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let lesson = ShadowVolume::lit_by(gpu, scene, knobs, SUN)?;
        Ok(Self { lesson })
    }
    // ANCHOR_END: solution

    const NAME: &'static str = "shadow-volume-exercise-2";
    const TITLE: &'static str = "Lesson 14, exercise 2: the sun";
    const KNOBS: &'static [Knob] = shadow_volume::KNOBS;
    const CAMERA: Camera = ShadowVolume::CAMERA;

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
