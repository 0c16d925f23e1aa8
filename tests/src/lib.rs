//! What the tests, the book and the learners' tools share: the catalogue of the book's screenshots,
//! rendering any lesson by name, and image comparison with NVIDIA FLIP.

pub mod bench;
pub mod book;
pub mod browser;
pub mod flip;
pub mod geometry;
pub mod launches;
pub mod pairs;
pub mod shots;
pub mod stories;
pub mod strips;
pub mod trend;
pub mod web;

use std::path::PathBuf;

/// How many pixels changed from `before` to `after` (two captures of one frame, stopped after two
/// steps); fails naming the first pixel that changed where `before`'s stencil does not hold `mark`:
/// a step that draws "only where the mark is" must leave everything else alone.
pub fn changed_only_inside_mark(
    before: &workbook::app::headless::Capture,
    after: &workbook::app::headless::Capture,
    mark: u8,
) -> Result<usize, String> {
    let mut changed = 0;
    for (x, y, pixel) in after.color.enumerate_pixels() {
        if pixel != before.color.get_pixel(x, y) {
            if before.stencil_at(x, y) != Some(mark) {
                return Err(format!("({x}, {y}) changed outside the mark"));
            }
            changed += 1;
        }
    }
    Ok(changed)
}

/// The workspace's root folder.
pub fn workspace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ lies inside the workspace")
        .to_path_buf()
}

/// Where the book's images, which are also the tests' references, live.
pub fn images() -> PathBuf {
    workspace().join("book/src/images")
}
