//! `cargo web [--out FOLDER]`: builds the web edition's module of every lesson into the book
//! (`book/src/live`, which mdBook copies into `book/build/html/live`). `book/build.sh` runs it.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use workbook_tests::web;

#[derive(Parser)]
#[command(name = "web", about = "Build the web edition's module into the book")]
struct Args {
    /// Where to put the module, its bindings and the assets (default: book/src/live).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Build with `--locked`, as CI does.
    #[arg(long)]
    locked: bool,
}

fn main() -> ExitCode {
    let args = Args::parse();
    let out = args.out.unwrap_or_else(web::default_out);
    match web::build(&out, args.locked) {
        Ok(built) => {
            println!(
                "web: module {:.2} MB ({:.2} MB before wasm-opt), {:.2} MB gzipped, in {}",
                built.module_bytes as f64 / 1e6,
                built.bindgen_bytes as f64 / 1e6,
                built.module_gzipped as f64 / 1e6,
                out.display()
            );
            ExitCode::SUCCESS
        }
        Err(error) => {
            eprintln!("web: {error:#}");
            ExitCode::FAILURE
        }
    }
}
