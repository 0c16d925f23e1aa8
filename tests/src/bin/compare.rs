//! `cargo compare THEIRS.png BOOK.png`: how far apart two screenshots are, by NVIDIA FLIP, and where.
//!
//! Use it to check your screenshot against the book's, or to see what one lesson changes from the
//! last. It prints the mean FLIP error and the share of visibly different pixels, and writes a
//! difference image (black: the same; through purple and orange to yellow: more and more different).

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use workbook_tests::flip;

#[derive(Parser)]
#[command(name = "compare", about = "Compare two screenshots with NVIDIA FLIP")]
struct Args {
    /// The image to judge (e.g. your screenshot).
    test: PathBuf,
    /// The image to judge it against (e.g. the book's, in book/src/images/).
    reference: PathBuf,
    /// Where to write the difference image.
    #[arg(long, default_value = "difference.png")]
    diff: PathBuf,
}

fn main() -> ExitCode {
    let args = Args::parse();
    let result = (|| -> anyhow::Result<()> {
        let test = flip::load(&args.test)?;
        let reference = flip::load(&args.reference)?;
        let comparison = flip::compare(&reference, &test)?;
        comparison
            .difference
            .save(&args.diff)
            .map_err(|error| anyhow::anyhow!("cannot write `{}`: {error}", args.diff.display()))?;
        // A closed pipe (`| head -1`) is not an error worth a panic.
        let mut out = std::io::stdout();
        let _ = writeln!(out, "{}", comparison.summary());
        let _ = writeln!(out, "difference image: {}", args.diff.display());
        Ok(())
    })();
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("compare: error: {error:#}");
            ExitCode::FAILURE
        }
    }
}
