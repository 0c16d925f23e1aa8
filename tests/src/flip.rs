//! Image comparison with NVIDIA FLIP: the framework's (the window's "compare with the book" and
//! `--check` judge by it too), re-exported for the tests.

pub use workbook::book::flip::*;
