//! The suite's global allocator: the system's, counting the bytes live on the heap and their peak,
//! for the tests that measure memory in a child process of their own (the soak test, the model
//! loader's bound). Two or three atomic operations per allocation cost the other tests nothing they
//! would notice.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicIsize, Ordering};

pub struct Counting;

static LIVE_BYTES: AtomicIsize = AtomicIsize::new(0);
static PEAK_BYTES: AtomicIsize = AtomicIsize::new(0);

/// The bytes live on the heap now.
pub fn live_bytes() -> isize {
    LIVE_BYTES.load(Ordering::Relaxed)
}

/// The most bytes live at once since the last [`reset_peak`].
pub fn peak_bytes() -> isize {
    PEAK_BYTES.load(Ordering::Relaxed)
}

/// Starts a new peak from the bytes live now.
pub fn reset_peak() {
    PEAK_BYTES.store(live_bytes(), Ordering::Relaxed);
}

fn grew(bytes: isize) {
    let now = LIVE_BYTES.fetch_add(bytes, Ordering::Relaxed) + bytes;
    PEAK_BYTES.fetch_max(now, Ordering::Relaxed);
}

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

// The only unsafe code of the suite (with `leak_unseen`): a global allocator must implement an
// unsafe trait. Each method passes its arguments on to the system allocator unchanged, and counts.
#[allow(unsafe_code)]
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        grew(layout.size() as isize);
        // SAFETY: the caller's contract for `alloc` is the system allocator's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        grew(layout.size() as isize);
        // SAFETY: as for `alloc`.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE_BYTES.fetch_sub(layout.size() as isize, Ordering::Relaxed);
        // SAFETY: `ptr` was allocated by `System` with `layout` (every allocation goes through here).
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        grew(new_size as isize - layout.size() as isize);
        // SAFETY: as for `dealloc`; `new_size` is the caller's, per `realloc`'s contract.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}
