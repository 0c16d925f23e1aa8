//! Lesson 15, exercise 1: two answers in one stencil. The skull's count goes in the low seven
//! bits, the crate's parity in the top bit, each count writing only its own bits (its write
//! mask); the cap reads only the crate's bit (its read mask), and so closes the crate and leaves
//! the skull open.

use capping::{Capping, Cutting, DRAW_CAP, Solids, count_inside};
use workbook::room::camera::Camera;
use workbook::wgpu::{self, StencilOperation};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

// ANCHOR: solution
/// The skull's bits and the crate's.
pub const SKULL_BITS: u32 = 0x7f;
pub const CRATE_BIT: u32 = 0x80;

/// COUNT_THE_SKULL: the lesson's count, written to the low seven bits only: it wraps at 128, and
/// the top bit is left as it is.
pub fn count_the_skull(knobs: &Knobs) -> Recipe {
    let count = count_inside(knobs);
    Recipe {
        name: "COUNT_THE_SKULL",
        stencil: wgpu::StencilState {
            write_mask: SKULL_BITS,
            ..count.stencil
        },
        ..count
    }
}

/// COUNT_THE_CRATE: every face of the crate flips the top bit (`Invert`, written to that bit
/// only). A box is convex: a ray crosses it at most twice, and parity is enough.
pub fn count_the_crate(knobs: &Knobs) -> Recipe {
    let count = count_inside(knobs);
    let invert = wgpu::StencilFaceState {
        pass_op: StencilOperation::Invert,
        ..count.stencil.front
    };
    Recipe {
        name: "COUNT_THE_CRATE",
        stencil: wgpu::StencilState {
            front: invert,
            back: invert,
            read_mask: 0xff,
            write_mask: CRATE_BIT,
        },
        ..count
    }
}

/// CAP_THE_CRATE: the lesson's cap, its test reading the crate's bit alone:
/// `(0 & 0x80) != (stencil & 0x80)`.
pub const CAP_THE_CRATE: Recipe = Recipe {
    name: "CAP_THE_CRATE",
    stencil: wgpu::StencilState {
        read_mask: CRATE_BIT,
        write_mask: CRATE_BIT,
        ..DRAW_CAP.stencil
    },
    ..DRAW_CAP
};

/// The counts and the cap, each solid counted by itself.
pub fn cutting(knobs: &Knobs) -> Cutting {
    Cutting {
        counts: vec![
            (count_the_skull(knobs), Solids::Skull),
            (count_the_crate(knobs), Solids::Crate),
        ],
        caps: vec![CAP_THE_CRATE],
        solid: None,
    }
}
// ANCHOR_END: solution

/// The lesson with the crate through the skull, its solids counted apart and the crate capped.
pub struct Solution {
    lesson: Capping,
}

impl Lesson for Solution {
    const NAME: &'static str = "capping-exercise-1";
    const TITLE: &'static str = "Lesson 15, exercise 1: two answers in one stencil";
    const KNOBS: &'static [Knob] = &[];
    const CAMERA: Camera = Capping::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        let knobs = Knobs::from_settings(capping::KNOBS, &["crate=through"])?;
        let lesson = Capping::cutting(gpu, scene, &knobs, cutting(&knobs))?;
        Ok(Self { lesson })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
