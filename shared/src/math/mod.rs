//! The mathematics the lessons teach, on the CPU and tested on their own: the planar reflection
//! matrix, and a model of the stencil test and its operations.

pub mod reflect;
pub mod stencil;
