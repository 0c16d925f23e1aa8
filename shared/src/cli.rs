//! The one command line every lesson shares, and the `main` of every lesson binary.

use std::ffi::OsString;
use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, Result, bail};
use clap::{CommandFactory, FromArgMatches, Parser};

use crate::camera::Camera;
use crate::headless::{self, Request};
use crate::knobs::{self, Knobs};
use crate::lesson::Lesson;
use crate::scene::{SceneOptions, default_assets};

/// The largest width or height `--size` accepts before asking the GPU.
pub const MAX_SIZE: u32 = 16384;

#[derive(Debug, Parser)]
#[command(
    after_help = "Keys in the window: 1-9 cycle the knobs (Shift+digit goes back), drag to orbit, \
                  wheel to zoom, C prints the camera pose, Esc quits."
)]
pub struct Args {
    /// Render one frame without a window and write it to this PNG file.
    #[arg(long, value_name = "PATH")]
    pub screenshot: Option<PathBuf>,
    /// Size of the window or screenshot, WIDTHxHEIGHT.
    #[arg(long, value_name = "WxH", default_value = "1280x720", value_parser = parse_size)]
    pub size: (u32, u32),
    /// Set a knob, e.g. --set depth=always (repeatable; see --list-knobs).
    #[arg(long = "set", value_name = "KNOB=VALUE")]
    pub settings: Vec<String>,
    /// List this lesson's knobs, their values and what they mean, then exit.
    #[arg(long)]
    pub list_knobs: bool,
    /// Camera pose YAW,PITCH,DISTANCE in degrees, degrees, metres (the window title shows the current one).
    #[arg(long, value_name = "YAW,PITCH,DIST")]
    pub camera: Option<String>,
    /// Show this OBJ model instead of the skull (placed and scaled to fit).
    #[arg(long, value_name = "PATH")]
    pub model: Option<PathBuf>,
    /// Close the window by itself after this many frames (for smoke tests).
    #[arg(long, value_name = "N")]
    pub frames: Option<u64>,
    /// GPU backend: vulkan or gl (also metal, dx12); overrides WGPU_BACKEND.
    #[arg(long, value_name = "NAME")]
    pub backend: Option<String>,
    /// Folder with the textures and the skull.
    #[arg(long, value_name = "DIR")]
    pub assets: Option<PathBuf>,
    /// Say which GPU adapter was taken, and how long things took.
    #[arg(short, long)]
    pub verbose: bool,
}

fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let parsed = text
        .split_once(['x', 'X'])
        .and_then(|(w, h)| Some((w.trim().parse::<u32>().ok()?, h.trim().parse::<u32>().ok()?)));
    match parsed {
        Some((w, h)) if (1..=MAX_SIZE).contains(&w) && (1..=MAX_SIZE).contains(&h) => Ok((w, h)),
        Some(_) => Err(format!("each side must be 1 to {MAX_SIZE} pixels")),
        None => Err("expected WIDTHxHEIGHT, e.g. 1280x720".to_string()),
    }
}

impl Args {
    pub fn scene(&self) -> SceneOptions {
        SceneOptions {
            assets: self.assets.clone().unwrap_or_else(default_assets),
            model: self.model.clone(),
        }
    }

    pub fn camera(&self) -> Result<Camera> {
        self.camera
            .as_deref()
            .map(Camera::parse)
            .unwrap_or(Ok(Camera::default()))
    }
}

/// The whole `main` of a lesson binary: parse, run, and turn any error into one line and exit code 1.
pub fn main<L: Lesson>() -> ExitCode {
    quiet_mesa();
    init_logging();
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
            bail!("{} (see --help)", first.trim_start_matches("error: "));
        }
    };
    if args.list_knobs {
        print!("{}", knobs::describe(L::KNOBS));
        return Ok(());
    }
    let knobs = Knobs::from_settings(L::KNOBS, &args.settings)?;
    let camera = args.camera()?;
    if let Some(path) = &args.screenshot {
        if args.frames.is_some() {
            bail!("--frames counts window frames; --screenshot renders one frame without a window");
        }
        let start = std::time::Instant::now();
        let request = Request {
            width: args.size.0,
            height: args.size.1,
            knobs,
            camera,
            scene: args.scene(),
            read_stencil: false,
            read_depth: false,
            backend: args.backend.clone(),
            verbose: args.verbose,
        };
        let capture = headless::render::<L>(&request)?;
        save_png(&capture.color, path)?;
        if args.verbose {
            eprintln!("wrote {} in {:.0?}", path.display(), start.elapsed());
        }
        return Ok(());
    }
    crate::window::run::<L>(&args, knobs, camera)
}

/// Writes a PNG, saying which file could not be written and why.
pub fn save_png(image: &image::RgbaImage, path: &std::path::Path) -> Result<()> {
    let file = std::fs::File::create(path)
        .with_context(|| format!("cannot write screenshot `{}`", path.display()))?;
    let writer = std::io::BufWriter::new(file);
    image
        .write_with_encoder(image::codecs::png::PngEncoder::new(writer))
        .with_context(|| format!("cannot write screenshot `{}`", path.display()))
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

/// Logs go to stderr; `RUST_LOG` picks the level (default: errors only, as wgpu warns a lot, and not
/// the EGL probe's complaints on machines without GL).
fn init_logging() {
    let default = "error,wgpu_hal::gles::egl=off";
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
