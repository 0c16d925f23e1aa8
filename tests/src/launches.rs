//! What a learner waits for, measured on the lesson binaries themselves, run as a learner runs them:
//! headless start to PNG (debug, as `cargo run` builds it, and release), and the window's frames per
//! second on a display, with the software GPU's half resolution on and off. `cargo bench-lessons`
//! reports both beside the frames' costs (see `bench`).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

use anyhow::{Context, Result, bail};

use crate::bench::spread;

/// The two builds a lesson's binary comes in.
pub const PROFILES: [&str; 2] = ["debug", "release"];

/// The profile this program was built in: its binaries' folder's name.
pub fn own_profile() -> &'static str {
    if cfg!(debug_assertions) {
        "debug"
    } else {
        "release"
    }
}

/// Builds these lessons' binaries in these profiles (cargo, in the workspace), so that what is
/// timed is the code as it stands.
pub fn build_lessons(profiles: &[&str], lessons: &[&str]) -> Result<()> {
    for profile in profiles {
        let mut cargo = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()));
        cargo
            .current_dir(crate::workspace())
            .args(["build", "--quiet"]);
        for lesson in lessons {
            cargo.args(["-p", lesson]);
        }
        if *profile == "release" {
            cargo.arg("--release");
        }
        let status = cargo.status().context("cannot run cargo")?;
        if !status.success() {
            bail!("cargo build ({profile}) failed: {status}");
        }
    }
    Ok(())
}

/// Where a lesson's binary of `profile` lies: beside this program's own profile folder.
pub fn binary(profile: &str, lesson: &str) -> Result<PathBuf> {
    let exe = std::env::current_exe().context("where is this program?")?;
    let target = exe
        .parent()
        .and_then(Path::parent)
        .context("this program lies outside a target folder")?;
    let path = target.join(profile).join(lesson);
    if !path.is_file() {
        bail!("{} is missing: build the lessons first", path.display());
    }
    Ok(path)
}

/// One lesson's headless start to PNG, in seconds, for each profile measured: median, 10th and
/// 90th percentile of the runs, which take turns (debug, release, debug, ...) so that a machine
/// busier at one moment weighs on both.
#[derive(Debug, Clone)]
pub struct StartUp {
    pub lesson: &'static str,
    pub size: (u32, u32),
    pub seconds: Vec<(&'static str, [f64; 3])>,
}

/// Runs `path` with `args` to its end, output discarded, and says how long it took.
fn seconds(path: &Path, args: &[&str]) -> Result<f64> {
    let start = Instant::now();
    let status = Command::new(path)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .with_context(|| format!("cannot run {}", path.display()))?;
    let elapsed = start.elapsed().as_secs_f64();
    if !status.success() {
        bail!("{} {} failed: {status}", path.display(), args.join(" "));
    }
    Ok(elapsed)
}

/// Measures one lesson's start-up, headless, to a PNG of `size`, `runs` times in each profile.
pub fn measure_start_up(
    lesson: &'static str,
    size: (u32, u32),
    profiles: &[&'static str],
    runs: usize,
) -> Result<StartUp> {
    let out = std::env::temp_dir().join(format!("bench-start-up-{}.png", std::process::id()));
    let (out_arg, size_arg) = (out.display().to_string(), format!("{}x{}", size.0, size.1));
    let args = ["--screenshot", &out_arg, "--size", &size_arg];
    let binaries = profiles
        .iter()
        .map(|profile| binary(profile, lesson))
        .collect::<Result<Vec<_>>>()?;
    // One run each first, not counted: the binaries' pages come into the file cache.
    for path in &binaries {
        seconds(path, &args)?;
    }
    let mut times = vec![Vec::new(); binaries.len()];
    for _ in 0..runs {
        for (path, times) in binaries.iter().zip(&mut times) {
            times.push(seconds(path, &args)?);
        }
    }
    let _ = std::fs::remove_file(&out);
    Ok(StartUp {
        lesson,
        size,
        seconds: profiles
            .iter()
            .zip(&times)
            .map(|(profile, times)| (*profile, spread(times)))
            .collect(),
    })
}

/// The start-up table: one line per lesson, a column per profile (the medians).
pub fn start_up_table(results: &[StartUp]) -> String {
    let mut out = format!("{:<20}", "lesson");
    for (profile, _) in results.first().map_or(&[][..], |m| &m.seconds[..]) {
        let _ = write!(out, " {:>10}", format!("{profile} s"));
    }
    out.push('\n');
    for m in results {
        let _ = write!(out, "{:<20}", m.lesson);
        for (_, s) in &m.seconds {
            let _ = write!(out, " {:>10.3}", s[0]);
        }
        out.push('\n');
    }
    out
}

pub const START_UP_CSV_HEADER: &str =
    "lesson,width,height,profile,seconds_median,seconds_p10,seconds_p90";

pub fn start_up_csv(results: &[StartUp]) -> String {
    let mut out = format!("{START_UP_CSV_HEADER}\n");
    for m in results {
        for (profile, s) in &m.seconds {
            let _ = writeln!(
                out,
                "{},{},{},{profile},{:.3},{:.3},{:.3}",
                m.lesson, m.size.0, m.size.1, s[0], s[1], s[2]
            );
        }
    }
    out
}

/// A display to open windows on (X11 or Wayland), if there is one.
pub fn display() -> Option<String> {
    ["DISPLAY", "WAYLAND_DISPLAY"]
        .into_iter()
        .find_map(|name| std::env::var(name).ok().filter(|v| !v.is_empty()))
}

/// One lesson's window with its panel: frames per second at full resolution and at
/// half (`--resolution`), each the median of `runs` runs taken in turns.
#[derive(Debug, Clone)]
pub struct WindowRate {
    pub lesson: &'static str,
    /// Frames per second: full resolution, half resolution.
    pub fps: [f64; 2],
}

/// The window's first frames (start-up, the panel's comparison with the book) are left out: a run of
/// `SHORT` frames is timed, then one of `LONG`, and the difference is `LONG - SHORT` frames drawn.
const SHORT: u64 = 30;
const LONG: u64 = 90;

/// Measures one lesson's window frames/s at both resolutions (needs [`display`]).
pub fn measure_window(lesson: &'static str, profile: &str, runs: usize) -> Result<WindowRate> {
    let path = binary(profile, lesson)?;
    let mut rates = [Vec::new(), Vec::new()];
    for _ in 0..runs {
        for (resolution, rates) in ["full", "half"].into_iter().zip(&mut rates) {
            let run = |frames: u64| {
                let frames = frames.to_string();
                seconds(
                    &path,
                    &[
                        "--frames",
                        &frames,
                        "--resolution",
                        resolution,
                        "--size",
                        "1280x720",
                    ],
                )
            };
            let (short, long) = (run(SHORT)?, run(LONG)?);
            match frame_rate(short, long) {
                Some(rate) => rates.push(rate),
                None => eprintln!(
                    "bench-lessons: {lesson} at {resolution} resolution: {LONG} frames took \
                     {long:.3} s, {SHORT} took {short:.3} s: noise, not a rate; run left out"
                ),
            }
        }
    }
    if rates.iter().any(Vec::is_empty) {
        bail!("{lesson}'s window: every run was noise (the longer run no slower than the shorter)");
    }
    Ok(WindowRate {
        lesson,
        fps: [spread(&rates[0])[0], spread(&rates[1])[0]],
    })
}

/// Frames per second from a run of [`SHORT`] frames that took `short` seconds and one of [`LONG`]
/// that took `long`: the frames between them over the time between them. `None` where the longer
/// run took no longer by at least a millisecond a frame drawn — a difference that small is the
/// start-up's noise, not frames (with no floor, 60 frames over 1 µs read as 60 million a second).
pub fn frame_rate(short: f64, long: f64) -> Option<f64> {
    let frames = (LONG - SHORT) as f64;
    let time = long - short;
    (time >= frames * 1e-3).then(|| frames / time)
}

pub fn window_table(results: &[WindowRate]) -> String {
    let mut out = format!("{:<20} {:>10} {:>10}\n", "lesson", "full fps", "half fps");
    for m in results {
        let _ = writeln!(
            out,
            "{:<20} {:>10.1} {:>10.1}",
            m.lesson, m.fps[0], m.fps[1]
        );
    }
    out
}

pub const WINDOW_CSV_HEADER: &str = "lesson,width,height,full_fps,half_fps";

pub fn window_csv(results: &[WindowRate]) -> String {
    let mut out = format!("{WINDOW_CSV_HEADER}\n");
    for m in results {
        let _ = writeln!(out, "{},1280,720,{:.1},{:.1}", m.lesson, m.fps[0], m.fps[1]);
    }
    out
}
