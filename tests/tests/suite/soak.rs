//! A long run leaks nothing: the heaviest frame (two mirrors, six levels) rendered again and again
//! keeps the process's memory and its count of live wgpu objects flat.
//!
//! The measuring runs in a child process of its own (this test binary again, running only
//! `soak_child`): resident memory is the process's, and the other tests' threads would blur it.
//! After a warm-up the child samples, every [`EVERY`] frames, two measures:
//!
//! - **the Rust heap's live bytes**, from a counting allocator (the suite's global allocator, see
//!   [`crate::heap`]): everything the workbook, wgpu and the lessons allocate from Rust. Exact and
//!   quiet: between samples it moves by a few KiB at most.
//! - **resident memory** (RSS, from /proc): also what the driver allocates in C. Noisy: the process
//!   takes or gives back a ~30 MiB block at random moments (an allocator arena or the driver's
//!   working memory; measured as +30,332, −28,816 and +30,260 KiB between two samples in three of five
//!   runs), as often before the measured span as inside it.
//!
//! Each is judged by its trend, not by two points: the floor (least value) of the last third of the
//! samples against the floor of the first third. A leak raises every later sample, so it raises the
//! floor; a block taken or given back once moves the floors only if it stays taken for the whole of
//! the last third and was given back at some sample of the first, and that one step is then
//! discounted ([`trend`] removes the largest single step between two samples from the growth; a
//! leak's growth is spread over all of them).
//!
//! What it can see, in the quick form CI runs (1,500 frames, samples from frame 500; the floors'
//! thirds lie about 700 frames apart, one step of 100 frames discounted): the heap limit, 64 KiB,
//! is a leak of ~110 bytes a frame; the RSS limit, 4 MiB, a leak of ~7 KiB a frame in the driver. A
//! mutant that keeps 1 KiB a frame fails the heap measure by ~600 KiB
//! (`a_leak_of_one_kib_a_frame_fails`). `SOAK_FRAMES=20000` runs
//! the long form (about six minutes on lavapipe), which sees ten times less.

use std::process::Command;

use workbook::app::headless::{Headless, Request};
use workbook::wgpu;

/// Frames between two samples.
const EVERY: u64 = 100;

/// Growth of the Rust heap's floor allowed between the first and the last third of the samples,
/// beyond the largest single step. Measured without a leak: 1.4 and 0.9 KiB over 1,000 frames in
/// two runs; a third kept one 20 KiB step.
const HEAP_LIMIT_BYTES: i64 = 64 * 1024;

/// Growth of resident memory's floor allowed, after the largest single step is discounted.
const RSS_LIMIT_KIB: i64 = 4 * 1024;

#[test]
fn memory_and_wgpu_objects_stay_flat_over_many_frames() {
    let line = run_child(None);
    println!("{line}");
    if let Err(error) = judge(&line) {
        panic!("{error}\n{line}");
    }
}

/// The measurement can fail: a child that keeps 1 KiB a frame (on the Rust heap, touched so that
/// the pages are resident) is caught.
#[test]
fn a_leak_of_one_kib_a_frame_fails() {
    let line = run_child(Some(1024));
    let error = judge(&line).expect_err("a leak of 1 KiB a frame passed the soak test");
    println!("the leaking child: {error}");
    assert!(error.contains("heap"), "{error}");
}

/// Runs the child (leaking `leak` bytes a frame if asked) and returns its report line.
fn run_child(leak: Option<usize>) -> String {
    let mut command = Command::new(std::env::current_exe().unwrap());
    command
        .args([
            "--exact",
            "soak::soak_child",
            "--ignored",
            "--nocapture",
            "--test-threads=1",
        ])
        .env("SOAK_CHILD", "1");
    if let Some(bytes) = leak {
        command.env("SOAK_LEAK_BYTES_PER_FRAME", bytes.to_string());
    }
    let output = command.output().unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "the soak child failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    // libtest prints "test soak::soak_child ... " before the child's own output, on the same line.
    stdout
        .lines()
        .find_map(|line| line.find("soak: ").map(|at| line[at..].to_string()))
        .unwrap_or_else(|| panic!("no soak report in:\n{stdout}"))
}

/// Judges the child's report: live wgpu objects unchanged, and neither measure's floor rising.
fn judge(line: &str) -> Result<(), String> {
    let field = |key: &str| -> &str {
        let prefix = format!("{key}=");
        line.split_whitespace()
            .find_map(|f| f.strip_prefix(&prefix))
            .unwrap_or_else(|| panic!("{key} in {line}"))
    };
    let samples = |key: &str| -> Vec<i64> {
        field(key)
            .split(',')
            .map(|n| n.parse().unwrap_or_else(|_| panic!("{key} in {line}")))
            .collect()
    };
    for counter in LIVE_OBJECTS {
        let (before, after) = (
            field(&format!("{counter}_before")),
            field(&format!("{counter}_after")),
        );
        if before != after {
            return Err(format!("live {counter} changed: {before} -> {after}"));
        }
    }
    for (name, key, unit, limit) in [
        ("the Rust heap", "heap_bytes", 1024, HEAP_LIMIT_BYTES),
        ("resident memory", "rss_kib", 1, RSS_LIMIT_KIB),
    ] {
        let samples = samples(key);
        let (growth, step) = trend(&samples);
        if growth > limit {
            return Err(format!(
                "{name}'s floor grew by {} KiB beyond its largest single step ({} KiB; limit {} \
                 KiB): {key} {samples:?}",
                growth / unit,
                step / unit,
                limit / unit
            ));
        }
    }
    Ok(())
}

/// How much the floor of the last third of `samples` lies above the floor of the first third,
/// less the largest single step between two samples (one block taken, not a leak); and that step.
fn trend(samples: &[i64]) -> (i64, i64) {
    let third = (samples.len() / 3).max(1);
    let floor = |part: &[i64]| part.iter().copied().min().unwrap_or(0);
    let growth = floor(&samples[samples.len() - third..]) - floor(&samples[..third]);
    let step = samples
        .windows(2)
        .map(|w| w[1] - w[0])
        .max()
        .unwrap_or(0)
        .max(0);
    (growth - step, step)
}

/// Run by the tests above in a process of its own.
#[test]
#[ignore = "run by the soak tests in a child process"]
fn soak_child() {
    if std::env::var_os("SOAK_CHILD").is_none() {
        return;
    }
    let number = |key: &str| std::env::var(key).ok().and_then(|n| n.parse::<u64>().ok());
    let total = number("SOAK_FRAMES").unwrap_or(1500);
    let leak = number("SOAK_LEAK_BYTES_PER_FRAME").unwrap_or(0) as usize;
    let warm_up = (total / 20).max(500).min(total / 2);
    let mut request = Request::new::<two_mirrors::TwoMirrors>(&["depth=6"]).unwrap();
    (request.width, request.height) = (64, 36);
    let headless = Headless::<two_mirrors::TwoMirrors>::new(&request).unwrap();
    headless.render_frames(warm_up).unwrap();
    let before = live_objects(&headless);
    let (mut rss, mut heap) = (Vec::new(), Vec::new());
    let mut done = warm_up;
    loop {
        rss.push(resident_kib().to_string());
        heap.push(crate::heap::live_bytes().to_string());
        if done >= total {
            break;
        }
        let frames = EVERY.min(total - done);
        headless.render_frames(frames).unwrap();
        for _ in 0..frames {
            // The mutant: a frame that keeps `leak` bytes, written so that they are resident
            // (`black_box`: an optimised build would otherwise drop the unused allocation).
            std::mem::forget(std::hint::black_box(vec![1u8; leak]));
        }
        done += frames;
    }
    let after = live_objects(&headless);
    println!(
        "soak: frames={total} measured_from={warm_up} every={EVERY} rss_kib={} heap_bytes={} {} {}",
        rss.join(","),
        heap.join(","),
        describe(&before, "before"),
        describe(&after, "after")
    );
}

/// Resident set size in KiB, from /proc (Linux; elsewhere the test has nothing to measure).
fn resident_kib() -> i64 {
    let statm = std::fs::read_to_string("/proc/self/statm").unwrap_or_default();
    let pages: i64 = statm
        .split_whitespace()
        .nth(1)
        .and_then(|p| p.parse().ok())
        .unwrap_or(0);
    pages * 4
}

/// The live objects counted, by wgpu's own counters (the `counters` feature, on for the tests).
const LIVE_OBJECTS: [&str; 5] = [
    "buffers",
    "textures",
    "texture_views",
    "bind_groups",
    "pipelines",
];

fn live_objects<L: workbook::Lesson>(headless: &Headless<L>) -> [isize; 5] {
    let counters: wgpu::InternalCounters = headless.device().get_internal_counters();
    let hal = counters.hal;
    [
        hal.buffers.read(),
        hal.textures.read(),
        hal.texture_views.read(),
        hal.bind_groups.read(),
        hal.render_pipelines.read(),
    ]
}

fn describe(objects: &[isize; 5], when: &str) -> String {
    LIVE_OBJECTS
        .iter()
        .zip(objects)
        .map(|(name, count)| format!("{name}_{when}={count}"))
        .collect::<Vec<_>>()
        .join(" ")
}
