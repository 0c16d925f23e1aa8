//! The `depth-test` binary as a learner runs it: a screenshot without a display, one clear line and
//! exit code 1 for every kind of bad input, and a real window under a display (CI runs it under Xvfb).

use std::path::{Path, PathBuf};

use workbook::app::testing::{run, run_with};

const EXE: &str = env!("CARGO_BIN_EXE_depth-test");

fn exe() -> &'static Path {
    Path::new(EXE)
}

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("depth-test-cli");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

#[test]
fn screenshot_without_a_display_writes_a_1280x720_png() {
    let out = scratch("default.png");
    let _ = std::fs::remove_file(&out);
    run(exe(), &["--screenshot", out.to_str().unwrap()]).assert_clean_success();
    let image = image::open(&out).unwrap();
    assert_eq!((image.width(), image.height()), (1280, 720));
}

/// What every lesson binary is checked for: knobs, a screenshot, the frame's steps, the film, a
/// window.
#[test]
fn the_binary_lists_renders_steps_films_and_opens_a_window() {
    workbook::app::testing::check_lesson_binary(exe(), &scratch("common"));
}

#[test]
fn steps_and_buffers_are_checked() {
    run(exe(), &["--step", "0", "--screenshot", "x.png"]).assert_one_line_error("count from 1");
    run(exe(), &["--step", "two", "--screenshot", "x.png"]).assert_one_line_error("step number");
    run(exe(), &["--show", "blue", "--screenshot", "x.png"]).assert_one_line_error("stencil");
    let file = scratch("a-file");
    std::fs::write(&file, b"").unwrap();
    let inside = file.join("film");
    run(exe(), &["--film", inside.to_str().unwrap()])
        .assert_one_line_error("cannot write the film");
}

/// `--pixel` tells a pixel's story; a pixel outside the picture or malformed is one line.
#[test]
fn a_pixel_story_is_told_and_bad_pixels_are_refused() {
    let told = run(exe(), &["--size", "64x36", "--pixel", "32,20"]);
    told.assert_clean_success();
    assert!(
        told.stdout
            .contains("Pixel (32, 20) of depth-test at 64×36")
    );
    assert!(told.stdout.contains("depth test"), "{}", told.stdout);
    run(exe(), &["--size", "64x36", "--pixel", "64,0"]).assert_one_line_error("outside the 64x36");
    run(exe(), &["--pixel", "400"]).assert_one_line_error("expected X,Y");
    run(exe(), &["--pixel", "x,2"]).assert_one_line_error("expected X,Y");
    run(exe(), &["--pixel", "1,2", "--step", "2"]).assert_one_line_error("leave out");
}

#[test]
fn knobs_are_listed_and_checked() {
    let listed = run(exe(), &["--list-knobs"]);
    listed.assert_clean_success();
    for name in ["depth", "depth-write", "order"] {
        assert!(
            listed.stdout.contains(&format!("] {name}:")),
            "{}",
            listed.stdout
        );
    }
    run(exe(), &["--set", "colour=red"]).assert_one_line_error("unknown knob `colour`");
    run(exe(), &["--set", "depth=sometimes"]).assert_one_line_error("choose one of never");
    run(exe(), &["--set", "depth"]).assert_one_line_error("NAME=VALUE");
    run(exe(), &["--frobnicate"]).assert_one_line_error("unexpected argument");
}

#[test]
fn bad_sizes_and_cameras_are_refused() {
    for size in ["0x0", "100000x100000", "12", "axb", "-5x10"] {
        let size = format!("--size={size}");
        run(exe(), &[&size, "--screenshot", "x.png"]).assert_one_line_error("--size");
    }
    run(exe(), &["--camera", "1,2", "--screenshot", "x.png"]).assert_one_line_error("--camera");
}

#[test]
fn bad_models_are_refused() {
    let png = scratch("not-a-model.png");
    std::fs::write(&png, b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR").unwrap();
    let empty = scratch("empty.obj");
    std::fs::write(&empty, b"").unwrap();
    let corrupt = scratch("corrupt.obj");
    std::fs::write(&corrupt, b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n").unwrap();
    let garbled = scratch("garbled.obj");
    std::fs::write(&garbled, b"v 0 zero 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let point = scratch("point.obj");
    std::fs::write(&point, b"v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n").unwrap();
    let shot = scratch("model.png");
    let shot = shot.to_str().unwrap();
    let cases = [
        ("/no/such/model.obj", "cannot read model"),
        (png.to_str().unwrap(), "OBJ is text"),
        (empty.to_str().unwrap(), "no triangles"),
        (corrupt.to_str().unwrap(), "model"),
        (garbled.to_str().unwrap(), "not a valid OBJ"),
        (point.to_str().unwrap(), "one point"),
    ];
    for (model, expected) in cases {
        run(exe(), &["--model", model, "--screenshot", shot]).assert_one_line_error(expected);
    }
}

/// What is not a model file is refused at once, before it is read: a device that never ends, a
/// FIFO that would block, a folder, and a file past the size limit (sparse: it costs no disk).
/// Measured (debug, lavapipe, `/usr/bin/time -v`): each of `/dev/zero`, a FIFO, a folder and a
/// sparse 3 GB file answers in 0.06-0.15 s with a peak resident size of 89-90 MB, what the process
/// holds once its GPU is set up, before it reads a model (a 64×36 screenshot of the skull peaks at
/// 124 MB); before, `/dev/zero` took 7.3 GB in 9 s before it was stopped.
#[test]
fn what_is_not_a_model_file_is_refused_at_once() {
    let shot = scratch("not-read.png");
    let shot = shot.to_str().unwrap();
    let big = scratch("three-gigabytes.obj");
    std::fs::File::create(&big)
        .unwrap()
        .set_len(3 << 30)
        .unwrap();
    let fifo = scratch("a-fifo.obj");
    let _ = std::fs::remove_file(&fifo);
    // A device and a FIFO on Linux only (`/dev/zero`, `mkfifo`); a folder and a size anywhere.
    let linux = cfg!(target_os = "linux");
    let made_fifo = linux
        && std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .is_ok_and(|status| status.success());
    let mut cases = vec![
        (scratch("").display().to_string(), "is a folder, not a file"),
        (big.display().to_string(), "larger than 256 MiB"),
    ];
    if linux {
        cases.push(("/dev/zero".to_string(), "is a device, not a file"));
    }
    if made_fifo {
        cases.push((fifo.display().to_string(), "is a FIFO (a pipe), not a file"));
    } else if !linux {
        eprintln!("skipped on {}: /dev/zero and mkfifo", std::env::consts::OS);
    } else {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must test a FIFO (mkfifo failed)"
        );
        eprintln!("skipped the FIFO: mkfifo failed here");
    }
    for (model, expected) in &cases {
        let started = std::time::Instant::now();
        run(exe(), &["--model", model, "--screenshot", shot]).assert_one_line_error(expected);
        let took = started.elapsed();
        assert!(took.as_secs() < 5, "--model {model} took {took:?}");
    }
    let _ = std::fs::remove_file(&big);
    let _ = std::fs::remove_file(&fifo);
}

#[test]
fn a_corrupt_texture_is_refused() {
    let assets = scratch("assets");
    std::fs::create_dir_all(&assets).unwrap();
    let real = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets");
    for entry in std::fs::read_dir(&real).unwrap().flatten() {
        if entry.path().is_file() {
            std::fs::copy(entry.path(), assets.join(entry.file_name())).unwrap();
        }
    }
    std::fs::write(
        assets.join("bricks.png"),
        b"\x89PNG\r\n\x1a\nthis is not a png",
    )
    .unwrap();
    let shot = scratch("texture.png");
    run(
        exe(),
        &[
            "--assets",
            assets.to_str().unwrap(),
            "--screenshot",
            shot.to_str().unwrap(),
        ],
    )
    .assert_one_line_error("bricks.png` is not a valid PNG");
}

/// A full disk: one clear line, and the screenshot that was there before is still whole (the PNG is
/// written beside it and renamed into place only when complete). Needs a small tmpfs, which only
/// root may mount: skipped with a message where it cannot be made, but not under CI.
#[test]
fn a_full_disk_gives_one_line_and_keeps_the_old_screenshot() {
    workbook::skip_unless_linux!("needs a tmpfs (mount -t tmpfs)");
    let disk = scratch("full-disk");
    std::fs::create_dir_all(&disk).unwrap();
    let mounted = std::process::Command::new("mount")
        .args(["-t", "tmpfs", "-o", "size=48k", "tmpfs"])
        .arg(&disk)
        .status()
        .is_ok_and(|status| status.success());
    if !mounted {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must run the full-disk test: it runs as root, and mounting a small tmpfs failed"
        );
        eprintln!("skipped: cannot mount a small tmpfs here (needs root)");
        return;
    }
    let shot = disk.join("shot.png");
    let shot_arg = shot.to_str().unwrap();
    run(exe(), &["--size", "64x36", "--screenshot", shot_arg]).assert_clean_success();
    let before = std::fs::read(&shot).unwrap();
    let full = run(exe(), &["--size", "1280x720", "--screenshot", shot_arg]);
    let after = std::fs::read(&shot).unwrap_or_default();
    let leftovers = std::fs::read_dir(&disk).unwrap().count();
    let _ = std::process::Command::new("umount").arg(&disk).status();
    full.assert_one_line_error("No space left on device");
    assert_eq!(before, after, "the old screenshot was damaged");
    assert_eq!(leftovers, 1, "a partial file was left behind");
}

#[test]
fn an_unwritable_screenshot_path_is_refused() {
    run(exe(), &["--screenshot", "/no/such/folder/out.png"])
        .assert_one_line_error("cannot write screenshot");
}

#[test]
fn no_adapter_and_no_display_say_what_to_do() {
    workbook::skip_unless_linux!("expects Linux: no DX12, no window without DISPLAY");
    // No DX12 on Linux: no adapter at all.
    run(exe(), &["--backend", "dx12", "--screenshot", "x.png"])
        .assert_one_line_error("mesa-vulkan-drivers");
    run(exe(), &["--backend", "glide", "--screenshot", "x.png"])
        .assert_one_line_error("unknown backend");
    // No Vulkan driver installed: the loader's own complaints stay quiet, our one line remains.
    let no_driver = [
        ("VK_DRIVER_FILES", "/nonexistent"),
        ("VK_ICD_FILENAMES", "/nonexistent"),
    ];
    run_with(
        exe(),
        &["--backend", "vulkan", "--screenshot", "x.png"],
        &no_driver,
    )
    .assert_one_line_error("mesa-vulkan-drivers");
    // No DISPLAY and no WAYLAND_DISPLAY: no window.
    run(exe(), &[]).assert_one_line_error("--screenshot");
    // A DISPLAY with no server behind it.
    run_with(exe(), &[], &[("DISPLAY", ":987")]).assert_one_line_error("--screenshot");
}

/// A real window for 30 frames. Needs a display: CI runs the suite under `xvfb-run`.
#[test]
fn a_window_shows_thirty_frames_and_closes() {
    workbook::skip_unless_linux!("the window tests run under Xvfb");
    let Ok(display) = std::env::var("DISPLAY") else {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must run this test with a display (xvfb-run)"
        );
        eprintln!("skipped: no DISPLAY (run under xvfb-run to include it)");
        return;
    };
    let outcome = run_with(
        exe(),
        &["--frames", "30", "--size", "320x240"],
        &[("DISPLAY", &display)],
    );
    outcome.assert_clean_success();
}

/// `--anisotropy 1` filters the textures plainly trilinearly (the software GPU's cheaper picture):
/// the textured floor and wall change, the sky does not; a value the GPU has no mode for is refused
/// in one line.
#[test]
fn anisotropy_changes_the_textures_and_nothing_else() {
    run(exe(), &["--anisotropy", "3", "--screenshot", "x.png"])
        .assert_one_line_error("1, 2, 4, 8 or 16");
    let picture = |name: &str, anisotropy: &str| {
        let shot = scratch(name);
        let args = [
            "--size",
            "320x180",
            "--anisotropy",
            anisotropy,
            "--screenshot",
        ];
        run(exe(), &[&args[..], &[shot.to_str().unwrap()]].concat()).assert_clean_success();
        image::open(&shot).unwrap().to_rgb8()
    };
    let (sharp, plain) = (
        picture("anisotropy-8.png", "8"),
        picture("anisotropy-1.png", "1"),
    );
    let differs = |x: u32, y: u32| sharp.get_pixel(x, y) != plain.get_pixel(x, y);
    // The sky left of the wall is no texture.
    let sky = (0..55).flat_map(|x| (0..60).map(move |y| (x, y)));
    assert_eq!(sky.filter(|&(x, y)| differs(x, y)).count(), 0);
    // The floor seen at a grazing angle is where the filtering shows.
    let all = (0..320).flat_map(|x| (0..180).map(move |y| (x, y)));
    let changed = all.filter(|&(x, y)| differs(x, y)).count();
    assert!(changed > 320 * 180 / 100, "only {changed} pixels changed");
}
