//! The mathematics the lessons teach, on the CPU and tested on their own: the planar reflection
//! matrix, and a model of the stencil test and its operations.
//! Clip planes and Lengyel's oblique near plane, for wgpu's 0..1 depth ([`clip`]).
//! The planar shadow matrix, and lights seen in a mirror ([`shadow`]).
//! Where a flat shape can show on the screen, for a scissor rectangle ([`screen`]).

pub mod clip;
pub mod reflect;
pub mod screen;
pub mod shadow;
pub mod stencil;
