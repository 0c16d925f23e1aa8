//! The `depth-test` window under use: a storm of resizes (down to 1×1), hides and shows, knob, step
//! and buffer keys, after which it still shows the picture a headless render gives; and surface
//! answers a real surface seldom gives (`Lost`, `Outdated`, `Timeout`, `Suboptimal`), injected with
//! the runner's test hook, all recovered from; and the workbench's panel, laid beside the picture
//! and hidden with `H`, after which the window is the headless render again.
//!
//! Needs a display (CI runs the suite under `xvfb-run`), `xdotool` and ImageMagick's `import`:
//! without them the tests are skipped with a message, except under CI, where they fail.

use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Mutex, MutexGuard};
use std::thread::{JoinHandle, sleep};
use std::time::{Duration, Instant};

use image::RgbImage;
use workbook::app::testing::{run, run_with};

const EXE: &str = env!("CARGO_BIN_EXE_depth-test");

/// The tests share the display: one window at a time, so that none covers another's capture and
/// none takes another's keys.
static DISPLAY_LOCK: Mutex<()> = Mutex::new(());

/// The display, this test's alone, and kept from resetting while it is (see [`KeepDisplay`]).
struct Display {
    name: String,
    _keep: KeepDisplay,
    _lock: MutexGuard<'static, ()>,
}

/// The display to use, or `None` (with a message) where the tests cannot run here.
fn display() -> Option<Display> {
    workbook::skip_unless_linux!("needs Xvfb, xdotool and import", None);
    let display = std::env::var("DISPLAY").ok();
    // Only whether they are installed: asking them anything would need the display already.
    let tools = [("xdotool", "version"), ("import", "-version")]
        .into_iter()
        .all(|(tool, version)| Command::new(tool).arg(version).output().is_ok());
    let missing = match (display, tools) {
        (Some(name), true) => {
            let lock = DISPLAY_LOCK.lock().unwrap_or_else(|e| e.into_inner());
            return Some(Display {
                _keep: KeepDisplay::new(&name),
                name,
                _lock: lock,
            });
        }
        (None, _) => "no DISPLAY (run under xvfb-run to include it)",
        (Some(_), false) => {
            "no xdotool or no ImageMagick `import` (apt-get install xdotool imagemagick)"
        }
    };
    assert!(
        std::env::var_os("CI").is_none(),
        "CI must run this test with a display and its tools: {missing}"
    );
    eprintln!("skipped: {missing}");
    None
}

/// An X client kept connected while a test uses the display. An X server resets when its last
/// client leaves and hangs up on any that connects meanwhile: in the gaps between a test's short
/// xdotool calls a lesson starting could find "no display" (2 runs in 6 on a loaded machine).
/// `xdotool exec` connects first, then starts a shell that says so and waits on its stdin, which
/// closes when this is dropped (or the test process ends).
struct KeepDisplay(Child);

impl KeepDisplay {
    fn new(display: &str) -> KeepDisplay {
        let script = "echo connected; exec cat >/dev/null";
        for _ in 0..20 {
            let mut child = Command::new("xdotool")
                .args(["exec", "--sync", "sh", "-c", script])
                .env("DISPLAY", display)
                .stdin(Stdio::piped())
                .stdout(Stdio::piped())
                .stderr(Stdio::null())
                .spawn()
                .expect("cannot start xdotool");
            let mut said = String::new();
            let _ = BufReader::new(child.stdout.take().unwrap()).read_line(&mut said);
            if said.trim() == "connected" {
                return KeepDisplay(child);
            }
            // Hung up on: the server was resetting. Again, in a moment.
            let _ = child.wait();
            sleep(Duration::from_millis(200));
        }
        panic!("cannot stay connected to the display {display}");
    }
}

impl Drop for KeepDisplay {
    fn drop(&mut self) {
        drop(self.0.stdin.take());
        let _ = self.0.wait();
    }
}

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("depth-test-storm");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// The lesson running in its window, killed if the test ends early.
struct Running {
    child: Child,
    stdout: Option<JoinHandle<String>>,
    stderr: Option<JoinHandle<String>>,
}

impl Running {
    /// The lesson alone, without the workbench's panel: the window must then show exactly what
    /// the headless runner renders (the panel has its own tests in the suite).
    fn start(display: &str, args: &[&str], env: &[(&str, &str)]) -> Running {
        let args: Vec<&str> = ["--no-panel"]
            .into_iter()
            .chain(args.iter().copied())
            .collect();
        Running::start_with_panel(display, &args, env)
    }

    /// The lesson in its workbench, the panel shown unless `args` say `--no-panel`. At full
    /// resolution: on a software GPU the window would otherwise draw half as many pixels a side
    /// and scale them up, and it must show exactly what the headless runner renders.
    fn start_with_panel(display: &str, args: &[&str], env: &[(&str, &str)]) -> Running {
        let mut command = Command::new(EXE);
        command
            .args(["--resolution", "full"])
            .args(args)
            .env("DISPLAY", display);
        for name in ["WAYLAND_DISPLAY", "RUST_BACKTRACE", "RUST_LOG"] {
            command.env_remove(name);
        }
        command.envs(env.iter().copied());
        let mut child = command
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("cannot start depth-test");
        // Read both pipes as they fill, so the lesson never blocks on a full one.
        let drain = |mut pipe: Box<dyn Read + Send>| {
            std::thread::spawn(move || {
                let mut text = String::new();
                let _ = pipe.read_to_string(&mut text);
                text
            })
        };
        let stdout = Some(drain(Box::new(child.stdout.take().unwrap())));
        let stderr = Some(drain(Box::new(child.stderr.take().unwrap())));
        Running {
            child,
            stdout,
            stderr,
        }
    }

    /// Panics (with what the lesson said) if it is no longer running.
    fn assert_alive(&mut self, when: &str) {
        if let Some(status) = self.child.try_wait().unwrap() {
            let stderr = self.stderr.take().unwrap().join().unwrap();
            panic!("depth-test ended {when} ({status}); stderr:\n{stderr}");
        }
    }

    /// Waits for the lesson to end: its exit code, stdout and stderr.
    fn wait(mut self, limit: Duration) -> (Option<i32>, String, String) {
        let start = Instant::now();
        let status = loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                break status;
            }
            assert!(start.elapsed() < limit, "depth-test did not close");
            sleep(Duration::from_millis(50));
        };
        let stdout = self.stdout.take().unwrap().join().unwrap();
        let stderr = self.stderr.take().unwrap().join().unwrap();
        (status.code(), stdout, stderr)
    }

    /// Closes the window with Escape and checks that the lesson ended with exit code 0 and said
    /// nothing on stderr; returns what it printed.
    fn close_cleanly(mut self, window: &str) -> String {
        self.xdotool(&["windowfocus", "--sync", window, "key", "Escape"]);
        let (code, stdout, stderr) = self.wait(Duration::from_secs(20));
        assert_eq!(code, Some(0), "exit code; stderr:\n{stderr}");
        assert!(stderr.trim().is_empty(), "stderr:\n{stderr}");
        stdout
    }

    /// The lesson's window, once it has one and has put its state in the title.
    fn window(&mut self) -> String {
        let pid = self.child.id().to_string();
        let start = Instant::now();
        loop {
            self.assert_alive("before its window opened");
            let found = Command::new("xdotool")
                .args(["search", "--pid", &pid])
                .output()
                .unwrap();
            let text = String::from_utf8_lossy(&found.stdout);
            if let Some(window) = text.split_whitespace().next()
                && title(window).starts_with("depth-test — ")
            {
                return window.to_string();
            }
            assert!(start.elapsed() < Duration::from_secs(30), "no window");
            sleep(Duration::from_millis(100));
        }
    }

    /// Runs one chain of xdotool commands; if it fails, says first whether the lesson ended (and
    /// what it said), else what xdotool complained of.
    fn xdotool<S: AsRef<str>>(&mut self, args: &[S]) {
        let args: Vec<&str> = args.iter().map(AsRef::as_ref).collect();
        let out = Command::new("xdotool").args(&args).output().unwrap();
        if !out.status.success() {
            self.assert_alive(&format!("during `xdotool {}`", args.join(" ")));
            panic!(
                "xdotool {}: {}",
                args.join(" "),
                String::from_utf8_lossy(&out.stderr)
            );
        }
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn title(window: &str) -> String {
    let out = Command::new("xdotool")
        .args(["getwindowname", window])
        .output()
        .unwrap();
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

/// What the window shows now.
fn capture(window: &str) -> RgbImage {
    let out = Command::new("import")
        .args(["-window", window, "png:-"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "import: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    image::load_from_memory(&out.stdout).unwrap().to_rgb8()
}

/// The headless render at the windows' size, 320×240, with default settings.
fn headless(name: &str) -> RgbImage {
    headless_sized(name, 320, 240)
}

/// The headless render of `width`×`height` pixels, with default settings.
fn headless_sized(name: &str, width: u32, height: u32) -> RgbImage {
    let shot = scratch(name);
    let size = format!("{width}x{height}");
    let args = ["--size", &size, "--screenshot", shot.to_str().unwrap()];
    run(Path::new(EXE), &args).assert_clean_success();
    image::open(&shot).unwrap().to_rgb8()
}

/// The share of pixels whose red, green or blue differs by more than 8 (of 255): room for the
/// window's colour format and presentation, none for a wrong or stale picture.
fn differing_share(a: &RgbImage, b: &RgbImage) -> f64 {
    assert_eq!(a.dimensions(), b.dimensions(), "sizes differ");
    let differing = a
        .pixels()
        .zip(b.pixels())
        .filter(|(p, q)| p.0.iter().zip(q.0).any(|(x, y)| x.abs_diff(y) > 8))
        .count();
    differing as f64 / (a.width() * a.height()) as f64
}

/// Waits until the window shows `expected` (a frame may still be on its way), or fails saying how
/// far off it is and saving both pictures; returns the share of pixels off.
fn assert_shows(window: &str, expected: &RgbImage, name: &str) -> f64 {
    wait_until_shown(window, expected, name, false)
}

/// [`assert_shows`] for the window's left part, as wide as `expected`: the view beside the panel.
fn assert_shows_at_left(window: &str, expected: &RgbImage, name: &str) -> f64 {
    wait_until_shown(window, expected, name, true)
}

fn wait_until_shown(window: &str, expected: &RgbImage, name: &str, at_left: bool) -> f64 {
    let start = Instant::now();
    loop {
        let mut shown = capture(window);
        if at_left && shown.height() == expected.height() && shown.width() > expected.width() {
            shown = image::imageops::crop_imm(&shown, 0, 0, expected.width(), expected.height())
                .to_image();
        }
        let share = if shown.dimensions() == expected.dimensions() {
            differing_share(&shown, expected)
        } else {
            1.0
        };
        if share < 0.01 {
            return share;
        }
        if start.elapsed() > Duration::from_secs(10) {
            shown.save(scratch(&format!("{name}-window.png"))).unwrap();
            expected
                .save(scratch(&format!("{name}-headless.png")))
                .unwrap();
            panic!(
                "the window ({}x{}) differs from the headless render in {:.1}% of its pixels; see {}",
                shown.width(),
                shown.height(),
                share * 100.0,
                scratch(name).display()
            );
        }
        sleep(Duration::from_millis(200));
    }
}

/// Waits until the window's title says `parts` (keys are handled in turn), or fails with the title.
fn assert_title(window: &str, parts: &[String]) {
    let start = Instant::now();
    loop {
        let now = title(window);
        if parts.iter().all(|part| now.contains(part.as_str())) {
            return;
        }
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "the title should say {parts:?}, it says: {now}"
        );
        sleep(Duration::from_millis(50));
    }
}

/// A small deterministic generator (xorshift64*): the same storm every run.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u32) -> u32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        ((self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 32) % u64::from(n)) as u32
    }
}

/// What the keys should have made of the window: the `depth` knob's value, the step the frame
/// stops after, and the buffer shown.
struct Expected {
    depth: usize,
    step: usize,
    steps: usize,
    show: usize,
}

impl Expected {
    /// What `Tab` cycles through, in order.
    const SHOWS: [workbook::Show; 5] = workbook::Show::VIEWS;

    /// The window as it opens, on a frame of `steps` steps: every knob and view at its default.
    fn at_defaults(steps: usize) -> Expected {
        Expected {
            depth: default_depth(),
            step: steps,
            steps,
            show: 0,
        }
    }

    fn press(&mut self, key: &str) {
        let values = depth_test::KNOBS[0].values.len();
        match key {
            "1" => self.depth = (self.depth + 1) % values,
            "shift+1" => self.depth = (self.depth + values - 1) % values,
            "bracketleft" => self.step = (self.step - 1).max(1),
            "bracketright" => self.step = (self.step + 1).min(self.steps),
            "Tab" => self.show = (self.show + 1) % Self::SHOWS.len(),
            _ => unreachable!("{key}"),
        }
    }

    fn title(&self) -> Vec<String> {
        let depth = depth_test::KNOBS[0].values[self.depth];
        vec![
            format!(" — step {}/{}: ", self.step, self.steps),
            format!(" — showing {} — ", Self::SHOWS[self.show].name()),
            format!(" [1] depth={depth} "),
        ]
    }

    /// The xdotool chain of keys that undoes the keys' net effect: the knob on round to its
    /// default, the steps on to the last, the views on round to colour.
    fn undoing_keys(&self) -> Vec<String> {
        let mut reset = vec!["key".to_string(), "--delay".into(), "0".into()];
        let values = depth_test::KNOBS[0].values.len();
        let forward = (default_depth() + values - self.depth) % values;
        reset.extend(std::iter::repeat_n("1".to_string(), forward));
        reset.extend(std::iter::repeat_n(
            "bracketright".into(),
            self.steps - self.step,
        ));
        let shows = Self::SHOWS.len();
        reset.extend(std::iter::repeat_n(
            "Tab".into(),
            (shows - self.show) % shows,
        ));
        reset
    }
}

/// The index of the `depth` knob's default value.
fn default_depth() -> usize {
    let depth = &depth_test::KNOBS[0];
    depth
        .values
        .iter()
        .position(|v| *v == depth.default)
        .unwrap()
}

/// The storm: xdotool chains of resizes, hides and shows, and keys, sent to one window, with the
/// count of each.
struct Storm {
    window: String,
    rng: Rng,
    /// The chain being gathered, sent every fifth resize.
    chain: Vec<String>,
    resizes: usize,
    tiny: usize,
    huge: usize,
    hides: usize,
    presses: usize,
}

impl Storm {
    const RESIZES: usize = 500;
    const KEYS: [&'static str; 5] = ["1", "shift+1", "bracketleft", "bracketright", "Tab"];

    fn new(window: &str) -> Storm {
        Storm {
            window: window.to_string(),
            rng: Rng(0x5eed_5707),
            chain: Vec::new(),
            resizes: 0,
            tiny: 0,
            huge: 0,
            hides: 0,
            presses: 0,
        }
    }

    /// Sends the whole storm to `lesson`, keeping `expected` up with the keys pressed.
    fn blow(&mut self, lesson: &mut Running, expected: &mut Expected) {
        while self.resizes < Self::RESIZES {
            self.resize();
            self.resizes += 1;
            if !self.resizes.is_multiple_of(5) {
                continue;
            }
            if self.resizes % 50 == 25 {
                self.hide_and_show();
            }
            // Between some of the resizes, a few keys.
            self.press_keys(expected);
            // A breath now and then, for frames to be drawn at these sizes.
            self.chain.extend(["sleep".into(), "0.03".into()]);
            lesson.xdotool(&self.chain);
            self.chain.clear();
            if self.resizes.is_multiple_of(100) {
                lesson.assert_alive(&format!("after {} resizes", self.resizes));
            }
        }
        if !self.chain.is_empty() {
            lesson.xdotool(&self.chain);
        }
    }

    /// One resize to a random size.
    fn resize(&mut self) {
        let rng = &mut self.rng;
        // Mostly anything up to most of Xvfb's default 1280×1024 screen; now and then 1×1, and
        // now and then wider or taller than the GPU's textures may be (X's limit is 32767).
        let (width, height) = match rng.below(40) {
            0 | 1 => (1, 1),
            2 => (1 + rng.below(3), 1 + rng.below(3)),
            3 => (32_000, 1 + rng.below(8)),
            4 => (1 + rng.below(8), 32_000),
            _ => (1 + rng.below(1100), 1 + rng.below(900)),
        };
        self.tiny += usize::from(width * height == 1);
        self.huge += usize::from(width.max(height) == 32_000);
        self.chain.extend([
            "windowsize".into(),
            self.window.clone(),
            width.to_string(),
            height.to_string(),
        ]);
        if self.rng.below(3) == 0 {
            // Time for a frame at this size, now and then.
            self.chain.extend(["sleep".into(), "0.01".into()]);
        }
    }

    /// The window hidden, resized while hidden, and shown again (counted as a resize).
    fn hide_and_show(&mut self) {
        // Minimised and restored: with a window manager `windowminimize` iconifies; plain Xvfb
        // has none, and unmapping is what iconifying does to the window. Resized while hidden,
        // too. Mapping it again loses the focus: take it back for the keys.
        let (width, height) = (1 + self.rng.below(600), 1 + self.rng.below(500));
        let w = &self.window;
        for part in [
            "windowminimize",
            w,
            "windowunmap",
            "--sync",
            w,
            "windowsize",
            w,
            &width.to_string(),
            &height.to_string(),
            "sleep",
            "0.05",
            "windowmap",
            "--sync",
            w,
            "windowfocus",
            "--sync",
            w,
            // winit learns of modifiers held at the moment of focus a little late: a shift+1
            // sent at once came as a plain 1. No hand is that quick; wait as one would.
            "sleep",
            "0.1",
        ] {
            self.chain.push(part.into());
        }
        self.resizes += 1;
        self.hides += 1;
    }

    /// None to three random keys, each one `expected` is told of.
    fn press_keys(&mut self, expected: &mut Expected) {
        let count = self.rng.below(4);
        if count > 0 {
            self.chain
                .extend(["key".into(), "--delay".into(), "0".into()]);
            for _ in 0..count {
                let key = Self::KEYS[self.rng.below(Self::KEYS.len() as u32) as usize];
                expected.press(key);
                self.chain.push(key.into());
                self.presses += 1;
            }
        }
    }
}

/// 500 resizes to random sizes (1×1 among them), hides and shows, and keys between them; then the
/// window, back at 320×240 and the keys' net effect undone, shows what a headless render shows, and
/// closes cleanly on Escape.
#[test]
fn a_storm_of_resizes_and_keys_leaves_the_window_whole() {
    let Some(display) = display() else { return };
    let expected_picture = headless("storm-headless.png");
    let steps = run(Path::new(EXE), &["--list-steps"])
        .stdout
        .lines()
        .count();
    let mut expected = Expected::at_defaults(steps);
    let defaults = expected.title();

    let start = Instant::now();
    let mut lesson = Running::start(&display.name, &["--size", "320x240"], &[]);
    let window = lesson.window();
    lesson.xdotool(&["windowfocus", "--sync", &window]);
    let mut storm = Storm::new(&window);
    storm.blow(&mut lesson, &mut expected);
    lesson.assert_alive("after the storm");
    let storm_time = start.elapsed();

    // Every key counted, none lost or taken twice; then their net effect undone.
    lesson.xdotool(&["windowsize", "--sync", &window, "320", "240"]);
    assert_title(&window, &expected.title());
    let reset = expected.undoing_keys();
    storm.presses += reset.len() - 3;
    lesson.xdotool(&reset);
    assert_title(&window, &defaults);
    let share = assert_shows(&window, &expected_picture, "storm");
    lesson.assert_alive("after the storm's last frame");

    lesson.xdotool(&["windowfocus", "--sync", &window, "key", "Escape"]);
    let (code, _, stderr) = lesson.wait(Duration::from_secs(20));
    let Storm {
        resizes,
        tiny,
        huge,
        hides,
        presses,
        ..
    } = storm;
    eprintln!(
        "storm: {resizes} resizes ({tiny} to 1×1, {huge} to 32000 a side, {hides} hidden and \
         shown), {presses} keys in {:.1}s; then {:.2}% of the pixels off the headless render; \
         whole test {:.1}s",
        storm_time.as_secs_f64(),
        share * 100.0,
        start.elapsed().as_secs_f64()
    );
    assert_eq!(code, Some(0), "exit code; stderr:\n{stderr}");
    assert!(stderr.trim().is_empty(), "stderr:\n{stderr}");
}

const INJECTED: &str = "lost,outdated,timeout,suboptimal";

/// Every surface answer the runner knows how to recover from, once each, on the first frames: the
/// window still shows 30 frames (the answers that are no frame do not count as one) and closes
/// cleanly.
#[test]
fn injected_surface_errors_are_recovered_from() {
    let Some(display) = display() else { return };
    let outcome = run_with(
        Path::new(EXE),
        &["--frames", "30", "--size", "320x240"],
        &[
            ("DISPLAY", &display.name),
            ("WORKBOOK_INJECT_SURFACE_ERRORS", INJECTED),
        ],
    );
    outcome.assert_clean_success();
    let said: Vec<&str> = outcome.stdout.lines().collect();
    let expected: Vec<String> = INJECTED
        .split(',')
        .map(|name| format!("injected surface answer: {name}"))
        .collect();
    assert_eq!(said, expected, "stdout:\n{}", outcome.stdout);

    // A misspelt answer is refused in one line rather than ignored.
    run_with(
        Path::new(EXE),
        &["--frames", "1"],
        &[
            ("DISPLAY", &display.name),
            ("WORKBOOK_INJECT_SURFACE_ERRORS", "lost,lots"),
        ],
    )
    .assert_one_line_error("unknown surface answer `lots`");
}

/// Without `--frames` the window draws only when something changes: a frame the surface did not
/// give must be tried again, or the window would stay blank until the mouse moves.
#[test]
fn after_injected_surface_errors_an_idle_window_still_shows_the_picture() {
    let Some(display) = display() else { return };
    let expected_picture = headless("idle-headless.png");
    let mut lesson = Running::start(
        &display.name,
        &["--size", "320x240"],
        &[("WORKBOOK_INJECT_SURFACE_ERRORS", INJECTED)],
    );
    let window = lesson.window();
    assert_shows(&window, &expected_picture, "idle");
    lesson.assert_alive("after its first frame");
    let stdout = lesson.close_cleanly(&window);
    assert_eq!(stdout.lines().count(), 4, "stdout:\n{stdout}");
}

/// The panel is laid out beside the lesson's picture, never over it: with the panel, the window's
/// left part is the headless render of the view's size (the window less the panel's width); `H`
/// hides the panel and the whole window is the headless render of its size; shown and hidden again
/// (the view's buffers resized both ways), it still is.
#[test]
fn the_panel_sits_beside_the_picture_and_h_hides_it() {
    let Some(display) = display() else { return };
    let (width, height) = (800, 450);
    // At the X server's scale of 1, a point of egui is a pixel.
    let view_width = width - workbook::app::workbench::panel::WIDTH as u32;
    let beside = headless_sized("panel-beside.png", view_width, height);
    let whole = headless_sized("panel-hidden.png", width, height);
    let size = format!("{width}x{height}");
    let mut lesson = Running::start_with_panel(&display.name, &["--size", &size], &[]);
    let window = lesson.window();
    assert_shows_at_left(&window, &beside, "panel-shown");
    let press_h = ["windowfocus", "--sync", &window, "key", "h"];
    lesson.xdotool(&press_h);
    assert_shows(&window, &whole, "panel-hidden");
    lesson.xdotool(&press_h);
    assert_shows_at_left(&window, &beside, "panel-shown-again");
    lesson.xdotool(&press_h);
    assert_shows(&window, &whole, "panel-hidden-again");
    lesson.assert_alive("after hiding and showing its panel");
    lesson.close_cleanly(&window);
}
