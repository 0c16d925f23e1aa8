//! `cargo bench-lessons [--quick] [--out PREFIX]`: measures every lesson (see `workbook_tests::bench`)
//! in a release build, prints the table, and writes PREFIX.csv and PREFIX-<size>.svg; then the
//! window's panel, every lesson's frame with and without it, into PREFIX-panel.csv.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use workbook_tests::bench::{self, CASES, Plan};

#[derive(Parser)]
#[command(
    name = "bench-lessons",
    about = "What every lesson's frame costs, step by step"
)]
struct Args {
    /// A few frames of each lesson's defaults at 160x90: to check the benchmark works (CI).
    #[arg(long)]
    quick: bool,
    /// Frames measured per case, after the warm-up.
    #[arg(long, default_value_t = 40)]
    frames: usize,
    /// Only this lesson's cases (all of its knob values), and its panel.
    #[arg(long, value_name = "NAME")]
    lesson: Option<String>,
    /// Where to write PREFIX.csv and PREFIX-WxH.svg.
    #[arg(long, value_name = "PREFIX")]
    out: Option<PathBuf>,
}

fn main() -> ExitCode {
    workbook::app::cli::quiet_mesa();
    let args = Args::parse();
    let plan = match args.quick {
        true => Plan {
            sizes: vec![(160, 90)],
            warm_up: 2,
            frames: 5,
            defaults_only: true,
        },
        false => Plan {
            sizes: vec![(1280, 720), (1920, 1080)],
            warm_up: 8,
            frames: args.frames,
            defaults_only: false,
        },
    };
    if let Some(name) = &args.lesson
        && !CASES.iter().any(|c| c.lesson == name)
    {
        eprintln!("bench-lessons: error: no lesson `{name}`");
        return ExitCode::FAILURE;
    }
    let started = std::time::Instant::now();
    let mut results = Vec::new();
    for size in &plan.sizes {
        for case in CASES
            .iter()
            .filter(|c| !plan.defaults_only || c.label().is_empty())
            .filter(|c| args.lesson.as_ref().is_none_or(|name| name == c.lesson))
        {
            match bench::measure(case, *size, &plan) {
                Ok(measured) => results.push(measured),
                Err(error) => {
                    eprintln!("bench-lessons: error: {error:#}");
                    return ExitCode::FAILURE;
                }
            }
        }
    }
    let adapter = results.first().map_or(String::new(), |m| m.adapter.clone());
    println!("adapter: {adapter}");
    if results.iter().all(|m| m.gpu_ms.is_none()) {
        println!(
            "this adapter has no timestamp queries: GPU times are not measured (CPU and frame times are)"
        );
    }
    print!("{}", bench::table(&results));
    let peak = std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .map(|l| l.to_string())
        });
    if let Some(peak) = peak {
        println!(
            "peak resident memory of the whole run: {}",
            peak.trim_start_matches("VmHWM:").trim()
        );
    }
    // The window's panel: every lesson at the window's size (the quick run: one, smaller).
    let (panel_size, panel_lessons) = match args.quick {
        true => ((640, 360), &workbook_tests::shots::LESSONS[3..4]),
        false => ((1280, 720), workbook_tests::shots::LESSONS),
    };
    let mut panel = Vec::new();
    let only = |lesson: &&&str| args.lesson.as_ref().is_none_or(|name| name == *lesson);
    for lesson in panel_lessons.iter().filter(only) {
        match bench::measure_panel(lesson, panel_size, &plan) {
            Ok(measured) => panel.push(measured),
            Err(error) => {
                eprintln!("bench-lessons: error: {error:#}");
                return ExitCode::FAILURE;
            }
        }
    }
    println!("\nthe window's frame, the lesson alone and with the panel (wall time, waited for):");
    print!("{}", bench::panel_table(&panel));
    println!("measured in {:.0?}", started.elapsed());
    if let Some(prefix) = args.out {
        let csv = prefix.with_extension("csv");
        let panel_csv = PathBuf::from(format!("{}-panel.csv", prefix.display()));
        let written = std::fs::write(&csv, bench::csv(&results)).and_then(|()| {
            std::fs::write(&panel_csv, bench::panel_csv(&panel))?;
            for size in &plan.sizes {
                let name = format!("{}-{}x{}.svg", prefix.display(), size.0, size.1);
                let title = format!("GPU time per frame, {}x{}, {adapter}", size.0, size.1);
                std::fs::write(name, bench::plot(&results, *size, &title))?;
            }
            Ok(())
        });
        if let Err(error) = written {
            eprintln!(
                "bench-lessons: error: cannot write {}: {error}",
                csv.display()
            );
            return ExitCode::FAILURE;
        }
        println!("wrote {} and its plots", csv.display());
    }
    ExitCode::SUCCESS
}
