//! The `main` of every lesson binary: parse the one command line ([`Args`]), then list, render
//! headless, film, or open the window — and turn any error into one line.

use std::ffi::OsString;
use std::process::ExitCode;

use anyhow::{Context, Result, bail};
use clap::{CommandFactory, FromArgMatches};

use crate::app::args::Args;
use crate::app::headless::{Headless, Request, Still};
use crate::lesson::Lesson;
use crate::lesson::knobs::{self, Knobs};
use crate::lesson::steps::{self, Show};

/// Where `--check` writes the renders that differ from the book, and their difference images.
pub const CHECK_OUTPUT: &str = "check";

/// The whole `main` of a lesson binary: parse, run, and turn any error into one line and exit code 1.
pub fn main<L: Lesson>() -> ExitCode {
    quiet_mesa();
    quiet_panics(L::NAME);
    match run::<L>(std::env::args_os()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("{}: error: {error:#}", L::NAME);
            ExitCode::FAILURE
        }
    }
}

/// Runs a lesson with these command-line arguments (the first is the program name).
pub fn run<L: Lesson>(args: impl IntoIterator<Item = OsString>) -> Result<()> {
    let command = Args::command().name(L::NAME).about(L::TITLE);
    let args = match command
        .try_get_matches_from(args)
        .and_then(|matches| Args::from_arg_matches(&matches))
    {
        Ok(args) => args,
        Err(error) if !error.use_stderr() => {
            // --help and --version: not errors.
            print!("{error}");
            return Ok(());
        }
        Err(error) => {
            let text = error.to_string();
            let first = text.lines().next().unwrap_or("bad arguments");
            let first = first.trim_start_matches("error: ");
            // clap names the allowed values on a line of their own: keep them on ours.
            match text
                .lines()
                .find_map(|l| l.trim().strip_prefix("[possible values: "))
            {
                Some(values) => bail!("{first}: choose one of {}", values.trim_end_matches(']')),
                None => bail!("{first} (see --help)"),
            }
        }
    };
    init_logging(args.verbose);
    if args.list_knobs {
        print!("{}", knobs::describe(L::KNOBS));
        return Ok(());
    }
    let knobs = Knobs::from_settings(L::KNOBS, &args.settings)?;
    if args.check {
        let (scene, backend) = (args.scene(), args.backend.as_deref());
        return crate::book::check::check::<L>(
            &args.settings,
            &scene,
            backend,
            CHECK_OUTPUT.as_ref(),
        );
    }
    let camera = args.camera::<L>()?;
    let headless = args.list_steps || args.screenshot.is_some() || args.film.is_some();
    if !headless {
        return crate::app::window::run::<L>(&args, knobs, camera);
    }
    if args.frames == Some(0) {
        bail!("--frames must be at least 1");
    }
    if args.frames.is_some() && args.film.is_some() {
        bail!("--film records one frame step by step; --frames counts whole frames");
    }
    let start = std::time::Instant::now();
    let mut request = Request {
        width: args.size.0,
        height: args.size.1,
        knobs,
        camera,
        scene: args.scene(),
        read_stencil: false,
        read_depth: false,
        stop: args.step,
        show: args.show::<L>(),
        backend: args.backend.clone(),
        verbose: args.verbose,
    };
    if args.list_steps {
        // The steps depend on the knobs, not on the size: list them from a small frame.
        (request.width, request.height) = (16, 16);
        print!(
            "{}",
            steps::describe(&Headless::<L>::new(&request)?.steps())
        );
        return Ok(());
    }
    let headless = Headless::<L>::new(&request)?;
    if args.verbose {
        eprintln!("ready to render in {:.0?}", start.elapsed());
    }
    if let Some(path) = &args.screenshot {
        let frames = args.frames.unwrap_or(1);
        headless.render_frames(frames.saturating_sub(1))?;
        save_png(&headless.capture()?.color, path)?;
        if args.verbose {
            eprintln!("wrote {} in {:.0?}", path.display(), start.elapsed());
        }
    }
    if let Some(dir) = &args.film {
        let stills = headless.film()?;
        if args.verbose {
            eprintln!(
                "rendered {} steps in {} ms",
                stills.len(),
                start.elapsed().as_millis()
            );
        }
        save_film(&stills, dir)?;
        if args.verbose {
            let count = stills.len() * Show::BUFFERS.len();
            eprintln!(
                "wrote {count} images into {} in {} ms",
                dir.display(),
                start.elapsed().as_millis()
            );
        }
    }
    Ok(())
}

/// Writes a film into `dir` (made if missing): `NN-<step>-{color,depth,stencil}.png` for every
/// step, encoded on all cores.
pub fn save_film(stills: &[Still], dir: &std::path::Path) -> Result<()> {
    std::fs::create_dir_all(dir)
        .with_context(|| format!("cannot write the film into `{}`", dir.display()))?;
    let files: Vec<_> = stills
        .iter()
        .enumerate()
        .flat_map(|(index, still)| {
            Show::BUFFERS.map(|show| {
                let path = dir.join(steps::film_file(index + 1, still.step, show));
                (still.image(show), path)
            })
        })
        .collect();
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    std::thread::scope(|scope| {
        let workers: Vec<_> = files
            .chunks(files.len().div_ceil(threads).max(1))
            .map(|chunk| {
                scope.spawn(move || {
                    chunk
                        .iter()
                        .try_for_each(|(image, path)| save_png(image, path))
                })
            })
            .collect();
        workers
            .into_iter()
            .try_for_each(|worker| worker.join().expect("a PNG encoder panicked"))
    })
}

/// Writes a PNG, saying which file could not be written and why. The image goes to a temporary file
/// beside `path` first and is renamed into place, so an interrupted run never leaves half a PNG
/// where a good one was.
pub fn save_png(image: &image::RgbaImage, path: &std::path::Path) -> Result<()> {
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    let partial = path.with_file_name(format!(".{name}.partial"));
    let written = (|| {
        let file = std::fs::File::create(&partial)?;
        let mut writer = std::io::BufWriter::new(file);
        image.write_with_encoder(image::codecs::png::PngEncoder::new(&mut writer))?;
        std::io::Write::flush(&mut writer)?;
        std::fs::rename(&partial, path)?;
        anyhow::Ok(())
    })();
    if written.is_err() {
        let _ = std::fs::remove_file(&partial);
    }
    written.with_context(|| format!("cannot write screenshot `{}`", path.display()))
}

/// Mesa's drivers print "error: XDG_RUNTIME_DIR is invalid or not set" to stderr when that variable is
/// missing (in containers and CI): harmless, but it reads like our error. Give them a private folder.
/// Call it first thing in `main`, before any thread starts (it sets an environment variable).
#[allow(unsafe_code)]
pub fn quiet_mesa() {
    #[cfg(unix)]
    if std::env::var_os("XDG_RUNTIME_DIR").is_none() {
        use std::os::unix::fs::{DirBuilderExt, MetadataExt};
        let user = std::env::var("USER").unwrap_or_else(|_| "user".into());
        let dir = std::env::temp_dir().join(format!("workbook-runtime-{user}"));
        let _ = std::fs::DirBuilder::new().mode(0o700).create(&dir);
        // Ours (the owner of /proc/self is this process's user) and closed to everyone else.
        let me = std::fs::metadata("/proc/self").map(|m| m.uid()).ok();
        let private = std::fs::metadata(&dir)
            .is_ok_and(|m| m.is_dir() && m.mode() & 0o077 == 0 && Some(m.uid()) == me);
        if !private {
            return;
        }
        // SAFETY: called first thing in `main`, before any other thread exists.
        unsafe { std::env::set_var("XDG_RUNTIME_DIR", &dir) };
    }
}

/// Logs go to stderr; `RUST_LOG` picks the level. By default there are none: every failure the
/// lesson knows of becomes its one line, and wgpu's own (the Vulkan loader's complaints on a machine
/// without a driver, the EGL probe's without GL) would only bury it. `-v` shows wgpu's errors and
/// warnings.
fn init_logging(verbose: bool) {
    let default = match verbose {
        true => "warn,wgpu_hal::gles::egl=off",
        false => "off",
    };
    let _ = env_logger::Builder::from_env(env_logger::Env::default().default_filter_or(default))
        .format_timestamp(None)
        .try_init();
}

/// A bug that panics still prints one line (with `RUST_BACKTRACE=1`, the full trace).
fn quiet_panics(name: &'static str) {
    if std::env::var_os("RUST_BACKTRACE").is_some() {
        return;
    }
    std::panic::set_hook(Box::new(move |info| {
        let location = info
            .location()
            .map(|l| format!(" at {}:{}", l.file(), l.line()))
            .unwrap_or_default();
        let message = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        let message = message.split_whitespace().collect::<Vec<_>>().join(" ");
        eprintln!("{name}: internal error: {message}{location} (a bug: please report it)");
    }));
}
