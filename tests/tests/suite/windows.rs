//! Every lesson in a real window with its workbench panel shown: 30 frames, no wgpu error, a clean
//! exit. A process has one event loop, so each lesson runs in a child process of its own (this
//! test binary again, running only `window_child`). Needs a display (CI runs the suite under
//! `xvfb-run`); without one the test is skipped with a message, except under CI, where it fails.

use std::process::Command;

use std::sync::Mutex;

use workbook::Lesson;
use workbook_tests::shots::{ForLesson, LESSONS, for_lesson};

/// One window on the display at a time: another window opening over the idle one would rightly
/// make it draw.
static DISPLAY: Mutex<()> = Mutex::new(());

/// Each lesson's window for 30 frames at 640×360, the panel shown as it opens by default.
#[test]
fn every_lesson_runs_thirty_frames_in_a_window_with_its_panel() {
    workbook::skip_unless_linux!("the window tests run under Xvfb");
    if std::env::var_os("DISPLAY").is_none() {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must run this test with a display (xvfb-run)"
        );
        eprintln!("skipped: no DISPLAY (run under xvfb-run to include it)");
        return;
    }
    let _display = DISPLAY.lock().unwrap_or_else(|e| e.into_inner());
    let mut failures = Vec::new();
    for lesson in LESSONS {
        let output = Command::new(std::env::current_exe().unwrap())
            .args([
                "--exact",
                "windows::window_child",
                "--ignored",
                "--nocapture",
                "--test-threads=1",
            ])
            .env("WINDOW_CHILD_LESSON", lesson)
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&output.stdout);
        let stderr = String::from_utf8_lossy(&output.stderr);
        let shown = format!("window shown: {lesson}");
        if !output.status.success() || !stdout.contains(&shown) {
            failures.push(format!("{lesson}:\n{stdout}\n{stderr}"));
        } else if stderr.contains("wgpu") || stderr.to_lowercase().contains("validation") {
            failures.push(format!("{lesson}: wgpu complained:\n{stderr}"));
        }
    }
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

/// A window with its panel, left alone, draws nothing: no busy loop of egui asking for frame after
/// frame (a grid of changing times did, 12-18 frames a second). Its frames are counted in its log
/// (`RUST_LOG=workbook::frames=debug`) after it settled (its first frames and its comparison with
/// the book, on a thread), and again two seconds later.
#[test]
fn a_window_left_alone_draws_nothing() {
    use std::time::{Duration, Instant};
    workbook::skip_unless_linux!("the window tests run under Xvfb");
    if std::env::var_os("DISPLAY").is_none() {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must run this test with a display (xvfb-run)"
        );
        eprintln!("skipped: no DISPLAY (run under xvfb-run to include it)");
        return;
    }
    let _display = DISPLAY.lock().unwrap_or_else(|e| e.into_inner());
    let log = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("idle-window.log");
    let mut child = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "windows::window_child",
            "--ignored",
            "--nocapture",
            "--test-threads=1",
        ])
        .env("WINDOW_CHILD_LESSON", "reflect-skull")
        .env("WINDOW_CHILD_IDLE", "1")
        .env("RUST_LOG", "workbook::frames=debug")
        .stdout(std::process::Stdio::null())
        .stderr(std::fs::File::create(&log).unwrap())
        .spawn()
        .unwrap();
    let frames = || {
        let text = std::fs::read_to_string(&log).unwrap_or_default();
        text.lines().filter(|l| l.contains("drawn")).count()
    };
    let start = Instant::now();
    while frames() == 0 && start.elapsed() < Duration::from_secs(60) {
        std::thread::sleep(Duration::from_millis(100));
    }
    // Settled: no frame for a second (or 30 seconds gone, and the count below says why).
    let mut last = (frames(), Instant::now());
    while last.1.elapsed() < Duration::from_secs(1) && start.elapsed() < Duration::from_secs(60) {
        std::thread::sleep(Duration::from_millis(100));
        if frames() != last.0 {
            last = (frames(), Instant::now());
        }
    }
    let settled = frames();
    std::thread::sleep(Duration::from_secs(2));
    let later = frames();
    let ended = child.try_wait().unwrap();
    let _ = child.kill();
    let _ = child.wait();
    assert!(
        ended.is_none(),
        "the window ended: {}",
        std::fs::read_to_string(&log).unwrap()
    );
    assert!(
        settled > 0,
        "no frame drawn: {}",
        std::fs::read_to_string(&log).unwrap()
    );
    assert_eq!(
        later - settled,
        0,
        "the idle window drew {} frames in two seconds (after {settled} to settle)",
        later - settled
    );
}

/// One lesson's window (the lesson named by `WINDOW_CHILD_LESSON`), run by the tests above: 30
/// frames, or with `WINDOW_CHILD_IDLE` until it is killed.
#[test]
#[ignore = "a child of the tests above"]
fn window_child() {
    struct Open;
    impl ForLesson for Open {
        type Output = anyhow::Result<()>;
        fn run<L: Lesson>(self) -> Self::Output {
            let mut args = vec![L::NAME, "--size", "640x360"];
            if std::env::var_os("WINDOW_CHILD_IDLE").is_none() {
                args.extend(["--frames", "30"]);
            }
            workbook::app::cli::run::<L>(args.into_iter().map(Into::into))
        }
    }
    let lesson = std::env::var("WINDOW_CHILD_LESSON").expect("WINDOW_CHILD_LESSON");
    for_lesson(&lesson, Open).unwrap().unwrap();
    println!("window shown: {lesson}");
}
