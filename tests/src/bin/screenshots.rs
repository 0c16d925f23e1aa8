//! `cargo screenshots [NAME...]`: renders the book's screenshots (all, or those named) into
//! `book/src/images/`. These files are also the tests' references, so run this only on purpose: when a
//! picture is meant to change, look at the new one, and say why in the commit.

use std::process::ExitCode;

use workbook_tests::shots::SHOTS;

fn main() -> ExitCode {
    workbook::cli::quiet_mesa();
    let names: Vec<String> = std::env::args().skip(1).collect();
    if let Some(unknown) = names.iter().find(|n| !SHOTS.iter().any(|s| s.name == *n)) {
        let known: Vec<_> = SHOTS.iter().map(|s| s.name).collect();
        eprintln!(
            "screenshots: error: no screenshot called `{unknown}`; there are: {}",
            known.join(", ")
        );
        return ExitCode::FAILURE;
    }
    let _ = std::fs::create_dir_all(workbook_tests::images());
    for shot in SHOTS {
        if !names.is_empty() && !names.iter().any(|n| n == shot.name) {
            continue;
        }
        let result = shot.render().and_then(|image| {
            workbook::cli::save_png(&image, &shot.path())?;
            Ok(())
        });
        match result {
            Ok(()) => println!("wrote {}   ({})", shot.path().display(), shot.command()),
            Err(error) => {
                eprintln!("screenshots: error: {}: {error:#}", shot.name);
                return ExitCode::FAILURE;
            }
        }
    }
    ExitCode::SUCCESS
}
