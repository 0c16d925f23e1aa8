//! Lesson 7, exercise 1: keep Luna's order (the room first, the mirror last), but draw the
//! transparent objects without writing depth. Does the dark fringe along the waterline go, and what
//! does the mirror's lowest strip show instead?

use drawing_order::DrawingOrder;
use workbook::gpu::states;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: DrawingOrder,
}

impl Lesson for Solution {
    const NAME: &'static str = "drawing-order-exercise-1";
    const TITLE: &'static str = "Lesson 7, exercise 1: Luna's order without depth writes";
    /// Always Luna's order: that is the exercise.
    const KNOBS: &'static [Knob] = &[];

    // ANCHOR: solution
    fn new(gpu: &Gpu, scene: &Scene, _knobs: &Knobs) -> anyhow::Result<Self> {
        let luna = Knobs::from_settings(drawing_order::KNOBS, &["order=luna"])?;
        let mut lesson = DrawingOrder::new(gpu, scene, &luna)?;
        // The water and the fence still blend, but leave the depth buffer alone: the mirror's
        // mark behind them no longer fails.
        let no_depth_write = Recipe {
            name: "TRANSPARENT_NO_CULL_NO_DEPTH_WRITE",
            depth_write: false,
            ..states::TRANSPARENT_NO_CULL
        };
        lesson.draw_transparent = scene.pipeline(&gpu.device, &no_depth_write);
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
