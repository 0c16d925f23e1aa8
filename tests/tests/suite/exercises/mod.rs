//! The exercises' solutions (`chapters/NN-name/examples/exercise-N-K.rs`), each tested by what its
//! exercise asks for, and each with a counterpart that shows the lesson alone does not already do it:
//! no exercise can be a no-op. The solutions are compiled into the lessons crate as modules
//! (`lessons::exercises::two_mirrors::exercise_1`, its feature `exercises`), so wgpu is linked once.

mod lesson_01;
mod lesson_02;
mod lesson_03;
mod lesson_04;
mod lesson_05;
mod lesson_06;
mod lesson_07;
mod lesson_08;
mod lesson_09;
mod lesson_10;
mod lesson_11;
mod lesson_12;
mod lesson_13;
mod lesson_14;
mod lesson_15;
mod lesson_16;

use workbook::gpu::{linear_to_srgb, srgb_to_linear};

/// k·top + (1 − k)·under for each channel, in linear light, encoded back to sRGB: what blending
/// with factors k and 1 − k stores.
fn blend(top: [u8; 3], under: [u8; 3], k: [f32; 3]) -> [u8; 3] {
    std::array::from_fn(|c| {
        linear_to_srgb(k[c] * srgb_to_linear(top[c]) + (1.0 - k[c]) * srgb_to_linear(under[c]))
    })
}
