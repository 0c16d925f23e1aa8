//! The `main` of every lesson binary: parse the one command line ([`Args`]), then list, render
//! headless, film, or open the window — and turn any error into one line.

use std::ffi::OsString;
use std::process::ExitCode;

use anyhow::{Result, bail};

use crate::app::args::Args;
use crate::lesson::Lesson;
use crate::lesson::knobs::{self, Knobs};

// Printing lives in a leaf module of its own, so that the headless runner and the book's check
// print without reaching back up into the command line.
use crate::app::output::say;

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
    let args = match Args::parse_for::<L>(args) {
        Ok(args) => args,
        Err(error) if !error.use_stderr() => {
            // --help and --version: not errors.
            return say(error);
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
        return say(knobs::describe(L::KNOBS));
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
    let headless =
        args.list_steps || args.screenshot.is_some() || args.film.is_some() || args.pixel.is_some();
    if !headless {
        return crate::app::window::run::<L>(&args, knobs, camera);
    }
    crate::app::headless::run::<L>(&args, knobs, camera)
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
/// warnings, and how long each phase of the start-up took.
fn init_logging(verbose: bool) {
    let default = match verbose {
        true => "warn,start-up=info,wgpu_hal::gles::egl=off",
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
