//! `make-assets`: regenerates every file in the workspace's `assets/` folder.
//!
//! Run it with `cargo run -p asset-generator --release`.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Context;

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("make-assets: error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> anyhow::Result<()> {
    let dir = assets_dir()?;
    let start = std::time::Instant::now();
    let files = asset_generator::generate_all()?;
    let mut out = std::io::stdout().lock();
    for (name, bytes) in &files {
        let path = dir.join(name);
        std::fs::write(&path, bytes).with_context(|| format!("cannot write {}", path.display()))?;
        writeln!(out, "{:>9} bytes  {}", bytes.len(), path.display())?;
    }
    writeln!(
        out,
        "generated {} files in {:.2?}",
        files.len(),
        start.elapsed()
    )?;
    Ok(())
}

/// The workspace's `assets/` folder: the parent of this crate's folder.
fn assets_dir() -> anyhow::Result<PathBuf> {
    let dir = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    dir.canonicalize()
        .with_context(|| format!("cannot find the assets folder {}", dir.display()))
}
