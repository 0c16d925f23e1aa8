//! Lesson 14, exercise 1: counting by parity, as Kilgard's 1999 stencil shadows did. Every volume
//! face z-fail would count (where the depth test fails) inverts the stencil instead of adding or
//! subtracting 1: a pixel ends at 255 after an odd number of faces, 0 after an even one, and the
//! key light is added where it is 0.

use shadow_volume::{KEY, ShadowVolume, count_volumes};
use workbook::room::camera::Camera;
use workbook::wgpu::{self, StencilOperation};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

// ANCHOR: solution
/// COUNT_BY_PARITY: z-fail's recipe, but both sides of every face behind the visible point invert
/// the stencil (0 ↔ 255) instead of adding or subtracting 1. What is left is the parity of the
/// faces crossed: 0 for an even number, 255 for an odd one.
pub fn count_by_parity() -> Recipe {
    let z_fail = count_volumes(&Knobs::defaults(shadow_volume::KNOBS));
    let invert = wgpu::StencilFaceState {
        depth_fail_op: StencilOperation::Invert,
        ..z_fail.stencil.back
    };
    Recipe {
        name: "COUNT_BY_PARITY",
        stencil: wgpu::StencilState {
            front: invert,
            back: invert,
            read_mask: 0xff,
            write_mask: 0xff,
        },
        ..z_fail
    }
}
// ANCHOR_END: solution

/// The lesson, its volumes counted by parity.
pub struct Solution {
    lesson: ShadowVolume,
}

impl Lesson for Solution {
    const NAME: &'static str = "shadow-volume-exercise-1";
    const TITLE: &'static str = "Lesson 14, exercise 1: counting by parity";
    const KNOBS: &'static [Knob] = &[];
    const CAMERA: Camera = ShadowVolume::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let knobs = Knobs::defaults(shadow_volume::KNOBS);
        let counts = [count_by_parity()];
        let lesson = ShadowVolume::counting_with(gpu, scene, &knobs, KEY, &counts)?;
        Ok(Self { lesson })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
