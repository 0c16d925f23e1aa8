//! The suite's global allocator is the workbook's counting one ([`workbook::app::heap`]), for the
//! tests that measure memory in a child process of their own (the soak test, the model loader's
//! bound); and a mutant for the soak test.

use std::alloc::{GlobalAlloc, Layout, System};

pub use workbook::app::heap::{Counting, live_bytes, peak_bytes, reset_peak};

/// A mutant for the soak test: keeps `bytes` that the count above does not see, written so that
/// their pages are resident — as a driver's C allocation would be. Never freed.
pub fn leak_unseen(bytes: usize) {
    if bytes == 0 {
        return;
    }
    let layout = Layout::from_size_align(bytes, 16).expect("a small layout");
    // SAFETY: `layout` has a non-zero size; the block is written within its `bytes` before it is
    // dropped on the floor, and never read or freed.
    #[allow(unsafe_code)]
    unsafe {
        let block = System.alloc(layout);
        assert!(!block.is_null(), "the system allocator is out of memory");
        std::ptr::write_bytes(block, 1, bytes);
    }
}
