//! Lesson 15, exercise 2: a hollow ball. The skull is replaced by a ball with a ball-shaped hollow
//! inside it, the inner wall turned inside out: its triangles face the hollow. Cut through its
//! centre, the cap is a ring.

use capping::{Capping, Cutting};
use workbook::room::camera::Camera;
use workbook::room::mesh::MeshData;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene};

// ANCHOR: solution
/// The ball's outer and inner radii, in the skull's units (the skull is 1 across).
pub const OUTER: f32 = 0.5;
pub const INNER: f32 = 0.3;

/// A ball of radius `OUTER` with a hollow of radius `INNER`: the outer wall faces out, the inner
/// wall faces in, towards the hollow — out of the solid, as every face of a closed solid must.
pub fn hollow_ball() -> MeshData {
    let mut ball = MeshData::ball(OUTER);
    ball.append(MeshData::ball(INNER).inside_out());
    ball
}
// ANCHOR_END: solution

/// The lesson, the skull replaced by the hollow ball.
pub struct Solution {
    lesson: Capping,
}

impl Lesson for Solution {
    const NAME: &'static str = "capping-exercise-2";
    const TITLE: &'static str = "Lesson 15, exercise 2: a hollow ball";
    const KNOBS: &'static [Knob] = &[];
    const CAMERA: Camera = Capping::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let knobs = Knobs::defaults(capping::KNOBS);
        let cutting = Cutting {
            solid: Some(hollow_ball()),
            ..Cutting::of(&knobs, scene)
        };
        let lesson = Capping::cutting(gpu, scene, &knobs, cutting)?;
        Ok(Self { lesson })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
