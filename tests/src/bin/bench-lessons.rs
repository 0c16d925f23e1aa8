//! `cargo bench-lessons [--quick] [--only PART,...] [--out PREFIX]`: measures every lesson (see
//! `workbook_tests::bench`) in a release build, prints the table, and writes PREFIX.csv and
//! PREFIX-<size>.svg; then the window's panel, every lesson's frame with and without it, into
//! PREFIX-panel.csv; then what a learner waits for (`workbook_tests::launches`): headless start to
//! PNG of every lesson's binary, debug and release, into PREFIX-start-up.csv, and, on a display, the
//! window's frames/s at full and half resolution into PREFIX-window.csv.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;
use workbook_tests::bench::{self, Plan};
use workbook_tests::launches;
use workbook_tests::shots::LESSONS;

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
    /// Where to write PREFIX.csv and PREFIX-WxH.svg (and PREFIX-panel.csv, PREFIX-start-up.csv,
    /// PREFIX-window.csv).
    #[arg(long, value_name = "PREFIX")]
    out: Option<PathBuf>,
    /// Only these parts (comma-separated; all of them by default).
    #[arg(long, value_enum, value_delimiter = ',', value_name = "PART")]
    only: Vec<Part>,
}

/// What `bench-lessons` measures.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Part {
    /// Every lesson's frames headless: GPU time per step, CPU time, frames/s, memory.
    Frames,
    /// The window's panel: every lesson's window frame with the panel and without.
    Panel,
    /// Headless start to PNG of every lesson's binary, debug and release (builds them first).
    StartUp,
    /// The window's frames/s at full and half resolution, release (needs a display: run under
    /// `xvfb-run -a` without one).
    Window,
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
        && !LESSONS.contains(&name.as_str())
    {
        eprintln!("bench-lessons: error: no lesson `{name}`");
        return ExitCode::FAILURE;
    }
    let wanted = |part| args.only.is_empty() || args.only.contains(&part);
    let started = std::time::Instant::now();
    let mut results = Vec::new();
    for size in plan.sizes.iter().filter(|_| wanted(Part::Frames)) {
        for case in bench::cases()
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
    if wanted(Part::Frames) {
        println!("adapter: {adapter}");
        print!("{}", bench::table(&results));
    }
    if wanted(Part::Frames) && results.iter().all(|m| m.gpu_ms.is_none()) {
        println!(
            "this adapter has no timestamp queries: GPU times are not measured (CPU and frame times are)"
        );
    }
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
    for lesson in panel_lessons
        .iter()
        .filter(only)
        .filter(|_| wanted(Part::Panel))
    {
        match bench::measure_panel(lesson, panel_size, &plan) {
            Ok(measured) => panel.push(measured),
            Err(error) => {
                eprintln!("bench-lessons: error: {error:#}");
                return ExitCode::FAILURE;
            }
        }
    }
    if wanted(Part::Panel) {
        println!(
            "\nthe window's frame, the lesson alone and with the panel (wall time, waited for):"
        );
        print!("{}", bench::panel_table(&panel));
    }
    // What a learner waits for, on the lessons' own binaries (the quick run: one lesson, in this
    // program's own profile, once).
    let (launch_lessons, profiles, runs): (Vec<&'static str>, Vec<&'static str>, usize) =
        match args.quick {
            true => (vec!["reflect-skull"], vec![launches::own_profile()], 1),
            false => (LESSONS.to_vec(), launches::PROFILES.to_vec(), 5),
        };
    let launch_lessons: Vec<_> = launch_lessons.into_iter().filter(|l| only(&l)).collect();
    let mut start_up = Vec::new();
    let mut window = Vec::new();
    let window_wanted =
        wanted(Part::Window) && (!args.only.is_empty() || launches::display().is_some());
    if wanted(Part::StartUp) || window_wanted {
        let profiles: Vec<_> = match wanted(Part::StartUp) {
            true => profiles.clone(),
            false => vec![window_profile(args.quick)],
        };
        if let Err(error) = launches::build_lessons(&profiles, &launch_lessons) {
            eprintln!("bench-lessons: error: {error:#}");
            return ExitCode::FAILURE;
        }
    }
    if wanted(Part::StartUp) {
        for lesson in &launch_lessons {
            match launches::measure_start_up(lesson, (1280, 720), &profiles, runs) {
                Ok(measured) => start_up.push(measured),
                Err(error) => {
                    eprintln!("bench-lessons: error: {lesson}'s start-up: {error:#}");
                    return ExitCode::FAILURE;
                }
            }
        }
        println!("\nheadless start to PNG, 1280x720, the median of {runs} runs in turns:");
        print!("{}", launches::start_up_table(&start_up));
    }
    if window_wanted {
        if launches::display().is_none() {
            eprintln!(
                "bench-lessons: error: the window's frames/s need a display (run under xvfb-run -a)"
            );
            return ExitCode::FAILURE;
        }
        for lesson in &launch_lessons {
            match launches::measure_window(lesson, window_profile(args.quick), runs.min(2)) {
                Ok(measured) => window.push(measured),
                Err(error) => {
                    eprintln!("bench-lessons: error: {lesson}'s window: {error:#}");
                    return ExitCode::FAILURE;
                }
            }
        }
        println!(
            "\nthe window with its panel, 1280x720, frames/s over frames 30 to 90 ({}):",
            window_profile(args.quick)
        );
        print!("{}", launches::window_table(&window));
    } else if wanted(Part::Window) {
        println!("\nno display: the window's frames/s are not measured (run under xvfb-run -a)");
    }
    println!("measured in {:.0?}", started.elapsed());
    if let Some(prefix) = args.out {
        let report = Report {
            frames: wanted(Part::Frames).then_some(&results[..]),
            panel: wanted(Part::Panel).then_some(&panel[..]),
            start_up: &start_up,
            window: &window,
            launch_lessons: &launch_lessons,
            sizes: &plan.sizes,
            adapter: &adapter,
        };
        if !write(&prefix, &report) {
            return ExitCode::FAILURE;
        }
    }
    ExitCode::SUCCESS
}

/// What a run measured, for [`write`]: each part measured (`None`, or empty, where it was not).
struct Report<'a> {
    frames: Option<&'a [bench::Measured]>,
    panel: Option<&'a [bench::PanelCost]>,
    start_up: &'a [launches::StartUp],
    window: &'a [launches::WindowRate],
    launch_lessons: &'a [&'static str],
    sizes: &'a [(u32, u32)],
    adapter: &'a str,
}

/// Writes PREFIX.csv, PREFIX-panel.csv, PREFIX-start-up.csv, PREFIX-window.csv (each part
/// measured) and the frames' plots, then reads each CSV back: it must hold what the cost page
/// reads, a row for every lesson measured and figures that are figures (a rate out of noise, a
/// zero, a NaN where a measure was due, is not). Says what failed and returns false if anything did.
fn write(prefix: &std::path::Path, report: &Report) -> bool {
    let named = |suffix: &str| PathBuf::from(format!("{}{suffix}", prefix.display()));
    let of = |lessons: &mut dyn Iterator<Item = &'static str>| lessons.collect::<Vec<_>>();
    let mut csvs: Vec<(PathBuf, String, &str, Vec<&str>)> = Vec::new();
    if let Some(frames) = report.frames {
        let lessons = of(&mut frames.iter().map(|m| m.lesson));
        csvs.push((
            named(".csv"),
            bench::csv(frames),
            bench::CSV_HEADER,
            lessons,
        ));
    }
    if let Some(panel) = report.panel {
        let lessons = of(&mut panel.iter().map(|m| m.lesson));
        let text = bench::panel_csv(panel);
        csvs.push((named("-panel.csv"), text, bench::PANEL_CSV_HEADER, lessons));
    }
    let lessons = report.launch_lessons.to_vec();
    if !report.start_up.is_empty() {
        let text = launches::start_up_csv(report.start_up);
        let header = launches::START_UP_CSV_HEADER;
        csvs.push((named("-start-up.csv"), text, header, lessons.clone()));
    }
    if !report.window.is_empty() {
        let text = launches::window_csv(report.window);
        csvs.push((
            named("-window.csv"),
            text,
            launches::WINDOW_CSV_HEADER,
            lessons,
        ));
    }
    let plots = report
        .sizes
        .iter()
        .filter(|_| report.frames.is_some())
        .map(|size| {
            let title = format!(
                "GPU time per frame, {}x{}, {}",
                size.0, size.1, report.adapter
            );
            let plot = bench::plot(report.frames.unwrap_or_default(), *size, &title);
            (named(&format!("-{}x{}.svg", size.0, size.1)), plot)
        });
    let files = csvs
        .iter()
        .map(|(path, text, ..)| (path.clone(), text.clone()));
    for (path, text) in files.chain(plots) {
        if let Err(error) = std::fs::write(&path, text) {
            eprintln!(
                "bench-lessons: error: cannot write {}: {error}",
                path.display()
            );
            return false;
        }
    }
    println!("wrote {}-*", prefix.display());
    for (path, _, header, lessons) in &csvs {
        let checked = std::fs::read_to_string(path)
            .map_err(anyhow::Error::from)
            .and_then(|text| bench::check_csv(&text, header, lessons));
        match checked {
            Ok(rows) => println!("checked {}: {rows} rows", path.display()),
            Err(error) => {
                eprintln!("bench-lessons: error: {}: {error:#}", path.display());
                return false;
            }
        }
    }
    true
}

/// The window is measured as a learner runs it fast: release (the quick run: this program's own
/// profile, already built).
fn window_profile(quick: bool) -> &'static str {
    match quick {
        true => launches::own_profile(),
        false => "release",
    }
}
