//! Lesson 16, exercise 2: when the cut matters. Room 1 moved back by the room's whole depth, so
//! that nothing of it stands on this side of the doorway: clip=off then changes nothing.

use portal::Portal;
use workbook::glam::{Mat4, Vec3};
use workbook::room::camera::Camera;
use workbook::room::scene::{FLOOR_DEPTH, WALL_THICKNESS};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene};

// ANCHOR: solution
/// The portal: back by the floor's depth and the wall's thickness, so that room 1's floor ends
/// where this room's wall begins.
pub fn far() -> Mat4 {
    Mat4::from_translation(Vec3::new(0.0, 0.0, -(FLOOR_DEPTH + WALL_THICKNESS)))
}
// ANCHOR_END: solution

/// The lesson through the far portal.
pub struct Solution {
    lesson: Portal,
}

impl Lesson for Solution {
    const NAME: &'static str = "portal-exercise-2";
    const TITLE: &'static str = "Lesson 16, exercise 2: when the cut matters";
    const KNOBS: &'static [Knob] = portal::KNOBS;
    const CAMERA: Camera = Portal::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let lesson = Portal::through(gpu, scene, knobs, far())?;
        Ok(Self { lesson })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
