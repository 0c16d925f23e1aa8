//! `cargo web`: builds the web edition's module (`book/web`, every lesson in one WebAssembly module)
//! into the book, where the lesson pages' script (`book/web/live.js`) loads it.
//!
//! Steps: the module in release for `wasm32-unknown-unknown`; its JavaScript bindings by
//! `wasm-bindgen` (the command's version must be the `wasm-bindgen` crate's, read from
//! `Cargo.lock`); shrunk by `wasm-opt -Os` (binaryen's, from npm: a working `wasm-opt` in seconds,
//! where building it with cargo takes ten minutes); and beside it the room's assets, which the page
//! fetches — the very files the native lessons read, so the page draws the book's pictures.

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result, bail};

/// The binaryen release whose `wasm-opt` shrinks the module.
pub const BINARYEN: &str = "binaryen@132.0.0";

/// The folder the module goes into: `book/src/live`, copied by mdBook into `book/build/html/live`.
pub fn default_out() -> PathBuf {
    crate::workspace().join("book/src/live")
}

/// What one build made.
#[derive(Debug)]
pub struct Built {
    /// The module before `wasm-opt`, and after it, in bytes.
    pub bindgen_bytes: u64,
    pub module_bytes: u64,
    /// The module after `wasm-opt`, gzipped (as a web server sends it), in bytes.
    pub module_gzipped: u64,
}

/// Builds the module into `out` (see the module's documentation).
pub fn build(out: &Path, locked: bool) -> Result<Built> {
    let root = crate::workspace();
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut build = Command::new(&cargo);
    build.current_dir(&root).args([
        "build",
        "--release",
        "--target",
        "wasm32-unknown-unknown",
        "-p",
        "workbook-web",
    ]);
    if locked {
        build.arg("--locked");
    }
    run(&mut build, "cargo build (wasm32)")?;
    let target =
        std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root.join("target"), PathBuf::from);
    let wasm = target.join("wasm32-unknown-unknown/release/workbook_web.wasm");

    let version = lock_version(&root, "wasm-bindgen")?;
    let have = Command::new("wasm-bindgen").arg("--version").output();
    let have = have.map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string());
    match have {
        Ok(line) if line.ends_with(&version) => {}
        Ok(line) => bail!(
            "`wasm-bindgen --version` says `{line}`, but the module is built with wasm-bindgen \
             {version}: `cargo install wasm-bindgen-cli --version {version}`"
        ),
        Err(_) => bail!(
            "no `wasm-bindgen` command: `cargo install wasm-bindgen-cli --version {version}` \
             (about ten minutes; without --locked)"
        ),
    }
    std::fs::create_dir_all(out).with_context(|| format!("cannot make {}", out.display()))?;
    run(
        Command::new("wasm-bindgen")
            .args(["--target", "web", "--no-typescript", "--out-dir"])
            .arg(out)
            .arg(&wasm),
        "wasm-bindgen",
    )?;
    let module = out.join("workbook_web_bg.wasm");
    let bindgen_bytes = size(&module)?;
    let mut shrink = wasm_opt(&target)?;
    shrink.arg("-Os").arg(&module).arg("-o").arg(&module);
    run(&mut shrink, "wasm-opt -Os")?;

    let assets = out.join("assets");
    std::fs::create_dir_all(&assets)?;
    let files = std::iter::once(workbook::room::assets::MODEL_FILE)
        .chain(workbook::room::assets::TEXTURE_FILES);
    for name in files {
        let from = root.join("assets").join(name);
        std::fs::copy(&from, assets.join(name))
            .with_context(|| format!("cannot copy {}", from.display()))?;
    }
    Ok(Built {
        bindgen_bytes,
        module_bytes: size(&module)?,
        module_gzipped: gzipped(&module)?,
    })
}

/// `wasm-opt` of the pinned binaryen release from npm, installed under the target folder once (an
/// older one on the PATH may not know the WebAssembly features Rust's compiler now uses).
fn wasm_opt(target: &Path) -> Result<Command> {
    let prefix = target.join("binaryen");
    let script = prefix.join("node_modules/binaryen/bin/wasm-opt");
    if !script.exists() {
        run(
            Command::new("npm")
                .args(["install", "--silent", "--no-audit", "--no-fund", "--prefix"])
                .arg(&prefix)
                .arg(BINARYEN),
            "npm install binaryen (for wasm-opt)",
        )?;
    }
    let mut node = Command::new("node");
    node.arg(script);
    Ok(node)
}

fn run(command: &mut Command, what: &str) -> Result<()> {
    let status = command
        .status()
        .with_context(|| format!("cannot run {what}"))?;
    if !status.success() {
        bail!("{what} failed ({status})");
    }
    Ok(())
}

fn size(path: &Path) -> Result<u64> {
    Ok(std::fs::metadata(path)
        .with_context(|| format!("cannot read {}", path.display()))?
        .len())
}

/// The size of `path` gzipped at the strongest level, as `gzip -9` makes it.
fn gzipped(path: &Path) -> Result<u64> {
    let output = Command::new("gzip")
        .args(["-9", "-c"])
        .arg(path)
        .output()
        .context("cannot run gzip")?;
    Ok(output.stdout.len() as u64)
}

/// The version of `package` in the workspace's `Cargo.lock`.
pub fn lock_version(root: &Path, package: &str) -> Result<String> {
    let lock = std::fs::read_to_string(root.join("Cargo.lock"))?;
    let mut lines = lock.lines();
    while let Some(line) = lines.next() {
        if line == format!("name = \"{package}\"")
            && let Some(version) = lines.next().and_then(|l| l.strip_prefix("version = \""))
        {
            return Ok(version.trim_end_matches('"').to_string());
        }
    }
    bail!("Cargo.lock has no package `{package}`")
}
