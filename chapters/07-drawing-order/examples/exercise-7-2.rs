//! Lesson 7, exercise 2: a third order that works: the room's opaque objects first (as lessons 3-6
//! draw them), then the mark and the mirror's world, and the room's transparent objects last; compare
//! its stencil buffer with the default order's.

use drawing_order::{DrawingOrder, MirrorWorld, farthest_first};
use workbook::room::scene::Drawable;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene};

pub struct Solution {
    lesson: DrawingOrder,
}

impl Lesson for Solution {
    const NAME: &'static str = "drawing-order-exercise-2";
    const TITLE: &'static str = "Lesson 7, exercise 2: opaque first, transparent last";
    /// The order is the exercise's own: the lesson's `order` knob does not apply.
    const KNOBS: &'static [Knob] = &[];

    fn new(gpu: &Gpu, scene: &Scene, _knobs: &Knobs) -> anyhow::Result<Self> {
        let knobs = Knobs::defaults(drawing_order::KNOBS);
        Ok(Self {
            lesson: DrawingOrder::new(gpu, scene, &knobs)?,
        })
    }

    // ANCHOR: solution
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let opaque = [&scene.floor, &scene.wall, &scene.crate_box, &scene.skull];
        let transparent = [&scene.fence_box, &scene.water];
        let mirrored = MirrorWorld {
            opaque: [&scene.floor, &scene.crate_box, &scene.skull],
            transparent: farthest_first(frame, transparent, Drawable::reflected_centre),
        };
        let transparent = farthest_first(frame, transparent, Drawable::centre);
        frame.clear();
        // The opaque room first: the crate and the skull write their depth ...
        self.lesson.draw_opaque(frame, &opaque);
        // ... so the mark fails behind them, and the mirror's world is drawn only where it shows.
        self.lesson.mark_mirror(frame);
        self.lesson.draw_reflected_world(frame, &mirrored);
        // The transparent objects last, over a finished mirror.
        self.lesson.draw_transparent(frame, &transparent);
    }
    // ANCHOR_END: solution
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
