//! The one command line every lesson shares.

use std::path::PathBuf;

use anyhow::Result;
use clap::Parser;

use crate::lesson::Lesson;
use crate::lesson::steps::{Show, Stop};
use crate::room::camera::Camera;
use crate::room::scene::{DEFAULT_ANISOTROPY, SceneOptions, default_assets};

/// The largest width or height `--size` accepts before asking the GPU.
pub const MAX_SIZE: u32 = 16384;

#[derive(Debug, Parser)]
#[command(
    after_help = "Keys in the window: 1-9 cycle the knobs (Shift+digit goes back), [ and ] step \
                  back and forward through the frame, Tab cycles color/depth/stencil, drag to \
                  orbit, wheel to zoom, right-click a pixel to tell its story in the panel, C prints the camera pose, H hides or shows the side panel, R \
                  switches between half and full resolution, Esc quits."
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
    /// List the numbered steps of the frame (with the knobs as set), then exit.
    #[arg(long)]
    pub list_steps: bool,
    /// Stop the frame after step N (from 1; see --list-steps), or `last`: the whole frame.
    #[arg(long, value_name = "N", default_value = "last", value_parser = Stop::parse)]
    pub step: Stop,
    /// Which buffer the window or screenshot shows [default: the lesson's own, mostly color].
    #[arg(long, value_name = "BUFFER", value_enum)]
    pub show: Option<Show>,
    /// With --show tests: the draw of the step whose fragments' fates are shown (from 1, in the
    /// order the step draws; see --pixel for their names). Without it, every draw of the step.
    #[arg(long, value_name = "N", value_parser = parse_draw)]
    pub draw: Option<usize>,
    /// Write every step's colour, depth and stencil buffers and its depth complexity into this
    /// folder as NN-<step>-{color,depth,stencil,complexity}.png, at --size.
    #[arg(long, value_name = "DIR")]
    pub film: Option<PathBuf>,
    /// Tell one pixel's story: for every step and every draw, its colour, depth and stencil, and the
    /// depth and stencil tests written out with its numbers (X,Y from the top left, at --size).
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel)]
    pub pixel: Option<(u32, u32)>,
    /// Camera pose YAW,PITCH,DISTANCE in degrees, degrees, metres (the window title shows the current one).
    /// A negative yaw needs no `=`: `--camera -20,15,10`.
    #[arg(long, value_name = "YAW,PITCH,DIST", allow_hyphen_values = true)]
    pub camera: Option<String>,
    /// Show this OBJ model instead of the skull (placed and scaled to fit).
    #[arg(long, value_name = "PATH")]
    pub model: Option<PathBuf>,
    /// Close the window by itself after this many frames; with --screenshot, render this many frames
    /// and write the last (a soak test).
    #[arg(long, value_name = "N")]
    pub frames: Option<u64>,
    /// GPU backend: vulkan or gl (also metal, dx12); overrides WGPU_BACKEND.
    #[arg(long, value_name = "NAME")]
    pub backend: Option<String>,
    /// Anisotropic filtering of the textures: 1 (plain trilinear), 2, 4, 8 or 16. A software GPU
    /// draws about 1.5 times faster with 1; the floor far away blurs.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_ANISOTROPY, value_parser = parse_anisotropy)]
    pub anisotropy: u16,
    /// Folder with the textures and the skull.
    #[arg(long, value_name = "DIR")]
    pub assets: Option<PathBuf>,
    /// Render every screenshot the book shows of this lesson, with the lesson as it is built now, and
    /// say for each whether it matches the book's picture (FLIP); differences go into `check/`.
    /// `--set` values change every picture (to see what a change would break).
    #[arg(long)]
    pub check: bool,
    /// Open the window without its side panel (H shows it).
    #[arg(long)]
    pub no_panel: bool,
    /// Scale the side panel's text and controls, e.g. 1.5 on a projector.
    #[arg(long, value_name = "FACTOR", default_value = "1", value_parser = parse_scale)]
    pub ui_scale: f32,
    /// How many pixels the window draws the lesson with: `auto` draws at half resolution (a
    /// quarter of the pixels, scaled up) on a software GPU, where full resolution is not smooth,
    /// and at full resolution on any other; R in the window switches. Screenshots always draw at
    /// full resolution.
    #[arg(long, value_name = "WHICH", default_value = "auto")]
    pub resolution: Resolution,
    /// Say which GPU adapter was taken, and how long things took.
    #[arg(short, long)]
    pub verbose: bool,
}

/// `--resolution`: how many pixels the window draws the lesson with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Resolution {
    /// Half on a software GPU (a CPU adapter), full on any other.
    Auto,
    Full,
    Half,
}

impl Resolution {
    /// Whether to draw at half resolution on this adapter.
    pub fn half(self, adapter: &wgpu::AdapterInfo) -> bool {
        match self {
            Self::Auto => adapter.device_type == wgpu::DeviceType::Cpu,
            Self::Full => false,
            Self::Half => true,
        }
    }
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

/// Parses `X,Y`: a pixel's column and row from the top left.
/// Parses `--draw`: a draw's number in its step, from 1; kept as its index, from 0.
fn parse_draw(text: &str) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(0) => Err("draws count from 1, in the order the step draws".into()),
        Ok(n) => Ok(n - 1),
        Err(_) => Err("expected a draw's number in its step, from 1".into()),
    }
}

fn parse_pixel(text: &str) -> Result<(u32, u32), String> {
    text.split_once(',')
        .and_then(|(x, y)| Some((x.trim().parse().ok()?, y.trim().parse().ok()?)))
        .ok_or_else(|| {
            "expected X,Y: the pixel's column and row from the top left, e.g. 400,200".into()
        })
}

fn parse_anisotropy(text: &str) -> Result<u16, String> {
    match text.trim().parse::<u16>() {
        Ok(n @ (1 | 2 | 4 | 8 | 16)) => Ok(n),
        _ => Err("expected 1, 2, 4, 8 or 16".to_string()),
    }
}

fn parse_scale(text: &str) -> Result<f32, String> {
    match text.trim().parse::<f32>() {
        Ok(scale) if (0.5..=4.0).contains(&scale) => Ok(scale),
        Ok(_) => Err("the scale must lie between 0.5 and 4".to_string()),
        Err(_) => Err("expected a number, e.g. 1.5".to_string()),
    }
}

impl Args {
    /// The command line of lesson `L` (the first argument is the program's name), as its binary
    /// parses it.
    pub fn parse_for<L: Lesson>(
        args: impl IntoIterator<Item = impl Into<std::ffi::OsString> + Clone>,
    ) -> Result<Self, clap::Error> {
        use clap::{CommandFactory, FromArgMatches};
        let command = Self::command().name(L::NAME).about(L::TITLE);
        Self::from_arg_matches(&command.try_get_matches_from(args)?)
    }

    pub fn scene(&self) -> SceneOptions {
        SceneOptions {
            assets: self.assets.clone().unwrap_or_else(default_assets),
            model: self.model.clone(),
            anisotropy: self.anisotropy,
        }
    }

    /// The arguments that give `scene` (those that differ from the defaults), for a command line
    /// that renders what this one shows.
    pub fn scene_arguments(scene: &SceneOptions) -> Vec<String> {
        let mut arguments = Vec::new();
        if scene.assets != default_assets() {
            arguments.extend(["--assets".to_string(), scene.assets.display().to_string()]);
        }
        if let Some(model) = &scene.model {
            arguments.extend(["--model".to_string(), model.display().to_string()]);
        }
        if scene.anisotropy != DEFAULT_ANISOTROPY {
            arguments.extend(["--anisotropy".to_string(), scene.anisotropy.to_string()]);
        }
        arguments
    }

    /// The buffer to show: `--show`, or the lesson's own.
    pub fn show<L: Lesson>(&self) -> Show {
        self.show.unwrap_or(L::SHOWS)
    }

    /// The camera pose: `--camera`, or the lesson's own.
    pub fn camera<L: Lesson>(&self) -> Result<Camera> {
        self.camera
            .as_deref()
            .map(Camera::parse)
            .unwrap_or(Ok(L::CAMERA))
    }
}

#[cfg(test)]
mod tests {
    use super::Resolution;

    /// Adapter information as two real adapters report it: lavapipe and an NVIDIA H100.
    fn adapter(name: &str, device_type: wgpu::DeviceType) -> wgpu::AdapterInfo {
        wgpu::AdapterInfo {
            name: name.into(),
            ..wgpu::AdapterInfo::new(device_type, wgpu::Backend::Vulkan)
        }
    }

    #[test]
    fn auto_draws_at_half_resolution_on_a_software_gpu_only() {
        let software = adapter("llvmpipe (LLVM 15.0.6, 256 bits)", wgpu::DeviceType::Cpu);
        let discrete = adapter("NVIDIA H100 80GB HBM3", wgpu::DeviceType::DiscreteGpu);
        let integrated = adapter("Intel(R) UHD Graphics 620", wgpu::DeviceType::IntegratedGpu);
        assert!(Resolution::Auto.half(&software));
        assert!(!Resolution::Auto.half(&discrete));
        assert!(!Resolution::Auto.half(&integrated));
        for adapter in [&software, &discrete] {
            assert!(Resolution::Half.half(adapter));
            assert!(!Resolution::Full.half(adapter));
        }
    }
}
