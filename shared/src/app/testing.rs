//! Helpers for the lessons' command-line tests: run a lesson binary as a learner would and look at
//! what it printed.

use std::path::Path;
use std::process::Command;

/// Skips the test it stands in, with one line on stderr, on any system but Linux: for what only
/// the Linux machines that run the suite have (`/proc`, `mkfifo`, a tmpfs, Xvfb, `xdotool`,
/// ImageMagick's `import`). `skip_unless_linux!("needs mkfifo")` returns from the test on Windows
/// after printing `skipped on windows: needs mkfifo`; `skip_unless_linux!("needs Xvfb", None)`
/// returns `None`.
#[macro_export]
macro_rules! skip_unless_linux {
    ($why:expr) => {
        if !cfg!(target_os = "linux") {
            eprintln!("skipped on {}: {}", std::env::consts::OS, $why);
            return;
        }
    };
    ($why:expr, $value:expr) => {
        if !cfg!(target_os = "linux") {
            eprintln!("skipped on {}: {}", std::env::consts::OS, $why);
            return $value;
        }
    };
}

/// What a run of a lesson binary left.
#[derive(Debug)]
pub struct Outcome {
    pub code: Option<i32>,
    pub stdout: String,
    pub stderr: String,
}

/// Runs `exe` with `args`, with no display and no backtraces (as a learner's plain shell).
pub fn run(exe: &Path, args: &[&str]) -> Outcome {
    run_with(exe, args, &[])
}

/// Runs `exe` with `args` and extra environment variables; `DISPLAY`, `WAYLAND_DISPLAY` and
/// `RUST_BACKTRACE` are removed unless given.
pub fn run_with(exe: &Path, args: &[&str], env: &[(&str, &str)]) -> Outcome {
    let mut command = Command::new(exe);
    command.args(args);
    for name in ["DISPLAY", "WAYLAND_DISPLAY", "RUST_BACKTRACE", "RUST_LOG"] {
        command.env_remove(name);
    }
    for (name, value) in env {
        command.env(name, value);
    }
    let output = command
        .output()
        .unwrap_or_else(|e| panic!("cannot run {}: {e}", exe.display()));
    Outcome {
        code: output.status.code(),
        stdout: String::from_utf8_lossy(&output.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
    }
}

impl Outcome {
    /// Asserts the run failed with exit code 1 and exactly one line on stderr, an error naming
    /// `expected`, and no panic.
    pub fn assert_one_line_error(&self, expected: &str) {
        let lines: Vec<&str> = self.stderr.lines().collect();
        assert_eq!(self.code, Some(1), "exit code; stderr:\n{}", self.stderr);
        assert_eq!(
            lines.len(),
            1,
            "expected one line on stderr, got:\n{}",
            self.stderr
        );
        assert!(!self.stderr.contains("panicked"), "{}", self.stderr);
        assert!(lines[0].contains(": error: "), "{}", lines[0]);
        assert!(
            lines[0].to_lowercase().contains(&expected.to_lowercase()),
            "expected `{expected}` in: {}",
            lines[0]
        );
    }

    /// Asserts the run succeeded with nothing on stderr.
    pub fn assert_clean_success(&self) {
        assert_eq!(self.code, Some(0), "stderr:\n{}", self.stderr);
        assert!(self.stderr.trim().is_empty(), "stderr:\n{}", self.stderr);
    }
}

/// The checks every lesson binary gets, as a learner would run it: it lists its knobs, renders a
/// screenshot without a display, refuses a bad knob value in one line, and — on Linux, where a
/// display exists (CI runs under `xvfb-run`) — shows 30 frames in a real window and closes.
pub fn check_lesson_binary(exe: &Path, scratch: &Path) {
    run(exe, &["--list-knobs"]).assert_clean_success();

    std::fs::create_dir_all(scratch).expect("scratch folder");
    let shot = scratch.join("screenshot.png");
    let _ = std::fs::remove_file(&shot);
    let shot_arg = shot.to_str().expect("a UTF-8 path");
    run(exe, &["--size", "320x180", "--screenshot", shot_arg]).assert_clean_success();
    assert!(shot.exists(), "no screenshot written");

    run(exe, &["--set", "no-such-knob=1", "--screenshot", shot_arg])
        .assert_one_line_error("unknown knob `no-such-knob`");

    // The frame's steps: listed as the book's strip captions them, each one a screenshot away,
    // and all of them filmed.
    let listed = run(exe, &["--list-steps"]);
    listed.assert_clean_success();
    let count = listed.stdout.lines().count();
    assert!(count >= 2, "--list-steps printed:\n{}", listed.stdout);
    let lesson = exe
        .file_stem()
        .and_then(|s| s.to_str())
        .expect("a lesson binary");
    let strip = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../book/src/images/steps")
        .join(lesson)
        .join("strip.html");
    let strip = std::fs::read_to_string(&strip).unwrap_or_default();
    assert_eq!(
        listed.stdout,
        strip_captions(&strip),
        "--list-steps against the book's strip"
    );
    let step = [
        "--size",
        "320x180",
        "--step",
        "2",
        "--show",
        "stencil",
        "--screenshot",
        shot_arg,
    ];
    run(exe, &step).assert_clean_success();
    let film = scratch.join("film");
    let _ = std::fs::remove_dir_all(&film);
    let film_arg = film.to_str().expect("a UTF-8 path");
    run(exe, &["--size", "160x90", "--film", film_arg]).assert_clean_success();
    let files = std::fs::read_dir(&film).map_or(0, |entries| entries.count());
    let shows = crate::Show::FILM.len();
    assert_eq!(
        files,
        shows * count,
        "--film wrote {files} files for {count} steps"
    );
    check_maps(exe, shot_arg);
    let past = (count + 1).to_string();
    run(exe, &["--step", &past, "--screenshot", shot_arg]).assert_one_line_error("no step");

    crate::skip_unless_linux!("the window checks run under Xvfb");
    match std::env::var("DISPLAY") {
        Ok(display) => {
            let window = ["--frames", "30", "--size", "320x240"];
            run_with(exe, &window, &[("DISPLAY", &display)]).assert_clean_success();
            let stepped = [
                "--frames", "5", "--size", "320x240", "--step", "2", "--show", "depth",
            ];
            run_with(exe, &stepped, &[("DISPLAY", &display)]).assert_clean_success();
            let mapped = ["--frames", "5", "--size", "320x240", "--show", "tests"];
            run_with(exe, &mapped, &[("DISPLAY", &display)]).assert_clean_success();
        }
        Err(_) => {
            assert!(
                std::env::var_os("CI").is_none(),
                "CI must run the tests with a display (xvfb-run)"
            );
            eprintln!("window check skipped: no DISPLAY (run under xvfb-run to include it)");
        }
    }
}

/// The maps: the complexity, the last step's test map, a draw past the step's last refused, and
/// `--draw` without the test map refused.
fn check_maps(exe: &Path, shot_arg: &str) {
    let complexity = ["--size", "160x90", "--show", "complexity", "--screenshot"];
    run(exe, &[&complexity[..], &[shot_arg]].concat()).assert_clean_success();
    let tests = ["--size", "160x90", "--show", "tests", "--screenshot"];
    run(exe, &[&tests[..], &[shot_arg]].concat()).assert_clean_success();
    run(exe, &[&tests[..], &[shot_arg, "--draw", "999"]].concat())
        .assert_one_line_error("--draw takes 1 to");
    run(exe, &["--draw", "1", "--screenshot", shot_arg]).assert_one_line_error("add --show tests");
}

/// The step captions of a book strip (see the tests' `strips` module), as `--list-steps` prints
/// them: `1. clear`, one a line.
pub fn strip_captions(html: &str) -> String {
    html.split("<th class=\"step\">")
        .skip(1)
        .filter_map(|row| row.split_once("</th>"))
        .map(|(caption, _)| format!("{caption}\n"))
        .collect()
}
