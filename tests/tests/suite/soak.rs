//! A long run leaks nothing: the heaviest frame (two mirrors, six levels) rendered again and again
//! keeps the process's resident memory and its count of live wgpu objects flat.
//!
//! Resident memory is the process's, so the measuring runs in a child process of its own (this test
//! binary again, running only `soak_child`); the other tests' threads would blur it otherwise. The
//! quick form (CI) runs 1,500 frames and compares frame 500 with frame 1,500; `SOAK_FRAMES=20000`
//! runs the full one (frame 1,000 against frame 20,000; about six minutes on lavapipe).

use std::process::Command;

use workbook::app::headless::{Headless, Request};
use workbook::wgpu;

/// Growth allowed between the two measurements: what a leak of a few bytes a frame would pass
/// (1 MiB over 19,000 frames is 55 bytes a frame).
const ALLOWED_GROWTH_KIB: i64 = 1024;

#[test]
fn memory_and_wgpu_objects_stay_flat_over_many_frames() {
    let output = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "soak::soak_child",
            "--ignored",
            "--nocapture",
            "--test-threads=1",
        ])
        .env("SOAK_CHILD", "1")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "the soak child failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    // libtest prints "test soak::soak_child ... " before the child's own output, on the same line.
    let line = stdout
        .lines()
        .find_map(|line| line.find("soak: ").map(|at| &line[at..]))
        .unwrap_or_else(|| panic!("no soak report in:\n{stdout}"));
    let number = |key: &str| -> i64 {
        let field = line
            .split_whitespace()
            .find(|f| f.starts_with(&format!("{key}=")));
        field
            .and_then(|f| f.split('=').nth(1)?.parse().ok())
            .unwrap_or_else(|| panic!("{key} in {line}"))
    };
    let growth = number("rss_after_kib") - number("rss_before_kib");
    assert!(
        growth < ALLOWED_GROWTH_KIB,
        "resident memory grew by {growth} KiB: {line}"
    );
    for counter in [
        "buffers",
        "textures",
        "texture_views",
        "bind_groups",
        "pipelines",
    ] {
        assert_eq!(
            number(&format!("{counter}_before")),
            number(&format!("{counter}_after")),
            "live {counter} changed: {line}"
        );
    }
}

/// Run by the test above in a process of its own.
#[test]
#[ignore = "run by memory_and_wgpu_objects_stay_flat_over_many_frames in a child process"]
fn soak_child() {
    if std::env::var_os("SOAK_CHILD").is_none() {
        return;
    }
    let total: u64 = std::env::var("SOAK_FRAMES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(1500);
    let warm_up = (total / 20).max(500).min(total / 2);
    let mut request = Request::new::<two_mirrors::TwoMirrors>(&["depth=6"]).unwrap();
    (request.width, request.height) = (64, 36);
    let headless = Headless::<two_mirrors::TwoMirrors>::new(&request).unwrap();
    headless.render_frames(warm_up).unwrap();
    let before = (resident_kib(), live_objects(&headless));
    headless.render_frames(total - warm_up).unwrap();
    let after = (resident_kib(), live_objects(&headless));
    println!(
        "soak: frames={total} measured_from={warm_up} rss_before_kib={} rss_after_kib={} {} {}",
        before.0,
        after.0,
        describe(&before.1, "before"),
        describe(&after.1, "after")
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

/// wgpu's own counts of live objects (the `counters` feature, enabled for the tests).
fn live_objects<L: workbook::Lesson>(headless: &Headless<L>) -> [(&'static str, isize); 5] {
    let counters: wgpu::InternalCounters = headless.device().get_internal_counters();
    let hal = counters.hal;
    [
        ("buffers", hal.buffers.read()),
        ("textures", hal.textures.read()),
        ("texture_views", hal.texture_views.read()),
        ("bind_groups", hal.bind_groups.read()),
        ("pipelines", hal.render_pipelines.read()),
    ]
}

fn describe(objects: &[(&str, isize); 5], when: &str) -> String {
    objects
        .iter()
        .map(|(name, count)| format!("{name}_{when}={count}"))
        .collect::<Vec<_>>()
        .join(" ")
}
