//! The workbook's test suite: one binary, so wgpu is linked once.
//!
//! Every render goes through `workbook::app::headless::render`, which fails on any wgpu error, validation
//! errors above all: no test here can pass while wgpu complains.

mod assets;
mod backends;
mod bench;
mod book;
mod capping;
mod depth;
mod depth_complexity;
mod drawing_order;
mod exercises;
mod floor_mirror;
mod fuzz;
mod heap;
mod knobs;
mod lessons;
mod maps;
mod mark_mirror;
mod outline;
mod panel;
mod pixel;
mod planar_shadow;
mod portal;
mod readme;
mod reflect_skull;
mod render_to_texture;
mod screenshots;
mod shadow_volume;
mod shape;
mod soak;
mod stencil_basics;
mod steps;
mod transparent_mirror;
mod truth_table;
mod two_mirrors;
mod validation;
mod winding_fix;
mod windows;

/// Counts the bytes live on the heap, for the tests that measure memory.
#[global_allocator]
static ALLOCATOR: heap::Counting = heap::Counting;
