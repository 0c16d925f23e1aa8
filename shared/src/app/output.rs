//! The lessons' standard output: what `--help`, `--list-knobs`, `--list-steps`, `--pixel` and
//! `--check` print. A leaf: the command line, the headless runner and the book's check all print
//! through it, and it uses none of them.

use anyhow::{Context, Result};

/// Prints `text` on standard output. A reader that stops reading (`--help | head`) ends the output,
/// not the program: Rust's `print!` panics on the closed pipe.
pub fn say(text: impl std::fmt::Display) -> Result<()> {
    use std::io::Write;
    match write!(std::io::stdout().lock(), "{text}") {
        Err(error) if error.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(error).context("cannot write to standard output")
        }
        _ => Ok(()),
    }
}
