//! Lesson 16, exercise 1: the turned room. The portal turns the room half round about the
//! doorway's upright axis instead of moving it back: through the doorway, the room behind is this
//! one turned round, seen from its own doorway. And there is no room 2.

use portal::Portal;
use workbook::glam::Mat4;
use workbook::room::camera::Camera;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene};

// ANCHOR: solution
/// The portal: half a turn about the doorway's upright axis (x = 0, z = 0). Still a move, not a
/// reflection: its determinant is +1.
pub fn turned() -> Mat4 {
    Mat4::from_rotation_y(std::f32::consts::PI)
}
// ANCHOR_END: solution

/// The lesson through the turned portal.
pub struct Solution {
    lesson: Portal,
}

impl Lesson for Solution {
    const NAME: &'static str = "portal-exercise-1";
    const TITLE: &'static str = "Lesson 16, exercise 1: the turned room";
    const KNOBS: &'static [Knob] = portal::KNOBS;
    const CAMERA: Camera = Portal::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let lesson = Portal::through(gpu, scene, knobs, turned())?;
        Ok(Self { lesson })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
