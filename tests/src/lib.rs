//! What the tests, the book and the learners' tools share: the catalogue of the book's screenshots,
//! rendering any lesson by name, and image comparison with NVIDIA FLIP.

pub mod bench;
pub mod book;
pub mod flip;
pub mod geometry;
pub mod pairs;
pub mod shots;
pub mod strips;

use std::path::PathBuf;

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
