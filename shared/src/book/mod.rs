//! The book as the lessons see it: the list of its screenshots and the settings that make each, the
//! FLIP comparison they are judged by, and the comparison of a lesson with them (`--check`, and the
//! window's "compare with the book").

#[cfg(not(target_arch = "wasm32"))]
pub mod check;
#[cfg(not(target_arch = "wasm32"))]
pub mod flip;
pub mod shots;
