//! The GPU: setup of instance, adapter and device (honouring `WGPU_BACKEND` and `--backend`), the
//! capture of every wgpu error, and the render targets the framework owns; the named pipeline
//! recipes ([`states`]), the pipelines baked from them ([`pipelines`]), the pass a step draws with
//! ([`pass`]), the pictures of the depth and stencil buffers ([`views`]), the frame replayed as maps
//! of its depth complexity and its draws' tests ([`maps`]) and reading buffers back ([`readback`]).

pub mod fullscreen;
pub mod maps;
pub mod pass;
pub mod pipelines;
pub mod readback;
pub mod states;
pub mod timing;
pub mod views;

use std::sync::{Arc, Mutex};

use anyhow::{Context, Result, bail};

/// The log target of the start-up's phases (`-v` prints them).
pub const STARTUP: &str = "start-up";

/// The depth-stencil format of every lesson: 24 bits of depth and 8 bits of stencil, D3D's D24S8.
pub const DEPTH_STENCIL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth24PlusStencil8;

/// Features the workbook uses where the adapter has them: user clip distances (lesson 8's first
/// clip method) and timestamp queries (GPU time per step). Lessons check before use.
pub const OPTIONAL_FEATURES: wgpu::Features =
    wgpu::Features::CLIP_DISTANCES.union(wgpu::Features::TIMESTAMP_QUERY);

/// The colour format of headless renders and screenshots: 8 bits per channel, sRGB-encoded.
pub const HEADLESS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// The device and queue, and the errors wgpu reported on them.
pub struct Gpu {
    pub instance: wgpu::Instance,
    pub adapter: wgpu::Adapter,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    errors: Arc<Mutex<Vec<String>>>,
}

/// The limits the device is opened with: the adapter's own natively; in the browser WebGL2's, which
/// WebGPU's adapters also meet, with the adapter's largest texture size.
fn required_limits(adapter: &wgpu::Adapter) -> wgpu::Limits {
    if cfg!(target_arch = "wasm32") {
        wgpu::Limits::downlevel_webgl2_defaults().using_resolution(adapter.limits())
    } else {
        adapter.limits()
    }
}

/// The backends to try, in turn: `--backend` if given, else `WGPU_BACKEND`; else first the primary
/// ones (Vulkan, Metal, DX12), and only if none has an adapter, OpenGL (asking GL first would print
/// EGL errors on machines that have no GL driver, and GL cannot read depth or stencil back).
pub fn backend_choices(backend: Option<&str>) -> Result<Vec<wgpu::Backends>> {
    let (source, list) = match backend {
        Some(list) => ("--backend", list.to_string()),
        None => match std::env::var("WGPU_BACKEND") {
            Ok(list) => ("WGPU_BACKEND", list),
            Err(_) => return Ok(vec![wgpu::Backends::PRIMARY, wgpu::Backends::GL]),
        },
    };
    let mut backends = wgpu::Backends::empty();
    for name in list.split(',').map(|name| name.trim().to_lowercase()) {
        backends |= match name.as_str() {
            "vulkan" | "vk" => wgpu::Backends::VULKAN,
            "gl" | "gles" | "opengl" => wgpu::Backends::GL,
            "metal" | "mtl" => wgpu::Backends::METAL,
            "dx12" | "d3d12" => wgpu::Backends::DX12,
            _ => bail!("{source}: unknown backend `{name}`: choose vulkan, gl, metal or dx12"),
        };
    }
    Ok(vec![backends])
}

/// A new instance for the chosen backends. A window passes its display handle (the GL backend needs it).
pub fn instance(
    backends: wgpu::Backends,
    display: Option<Box<dyn wgpu::wgt::WgpuHasDisplayHandle>>,
) -> wgpu::Instance {
    let descriptor = match display {
        Some(display) => wgpu::InstanceDescriptor::new_with_display_handle_from_env(display),
        None => wgpu::InstanceDescriptor::new_without_display_handle_from_env(),
    };
    wgpu::Instance::new(wgpu::InstanceDescriptor {
        backends,
        ..descriptor
    })
}

impl Gpu {
    /// Takes an adapter (one that can present to `surface`, if given) and opens its device.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn new(
        instance: wgpu::Instance,
        backends: wgpu::Backends,
        surface: Option<&wgpu::Surface<'_>>,
        verbose: bool,
    ) -> Result<Self> {
        pollster::block_on(Self::open(instance, backends, surface, verbose))
    }

    /// [`Gpu::new`], awaited: the browser answers the requests for an adapter and a device later,
    /// and a page must not block waiting for them.
    pub async fn open(
        instance: wgpu::Instance,
        backends: wgpu::Backends,
        surface: Option<&wgpu::Surface<'_>>,
        verbose: bool,
    ) -> Result<Self> {
        let adapter = instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                force_fallback_adapter: false,
                compatible_surface: surface,
                apply_limit_buckets: false,
            })
            .await
            .map_err(|_| {
                anyhow::anyhow!(
                    "no GPU adapter found (tried {:?}); on Linux without a GPU install Mesa's software \
                     Vulkan driver (`sudo apt-get install mesa-vulkan-drivers`), or pick another \
                     backend with --backend or WGPU_BACKEND",
                    backends
                )
            })?;
        let info = adapter.get_info();
        if verbose {
            eprintln!(
                "adapter: {} ({:?}, {:?} backend, driver {} {})",
                info.name, info.device_type, info.backend, info.driver, info.driver_info
            );
        }
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("workbook device"),
                required_features: adapter.features() & OPTIONAL_FEATURES,
                required_limits: required_limits(&adapter),
                experimental_features: wgpu::ExperimentalFeatures::disabled(),
                memory_hints: wgpu::MemoryHints::MemoryUsage,
                trace: wgpu::Trace::Off,
            })
            .await
            .with_context(|| format!("could not open the device of adapter `{}`", info.name))?;
        let errors = Arc::new(Mutex::new(Vec::new()));
        let sink = errors.clone();
        device.on_uncaptured_error(Arc::new(move |error: wgpu::Error| {
            let line = one_line(&error.to_string());
            log::error!("wgpu: {line}");
            sink.lock().unwrap_or_else(|e| e.into_inner()).push(line);
        }));
        Ok(Self {
            instance,
            adapter,
            device,
            queue,
            errors,
        })
    }

    /// A device for headless work: no window, no surface.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn headless(backend: Option<&str>, verbose: bool) -> Result<Self> {
        let start = std::time::Instant::now();
        let mut result = Err(anyhow::anyhow!("no backend to try"));
        for backends in backend_choices(backend)? {
            result = Self::new(instance(backends, None), backends, None, verbose);
            if result.is_ok() {
                break;
            }
        }
        log::info!(target: STARTUP, "GPU opened in {:.0?}", start.elapsed());
        result
    }

    /// The device for headless work, one per process and backend choice, shared by every headless
    /// render in it. A test run renders hundreds of frames in one process, and a driver may refuse
    /// new devices after a few dozen: NVIDIA's did on an H200 (measured: "no adapter" after 18
    /// tests in a row, a crash with 4 threads). Creating one also costs about 30 ms. (Not in the
    /// browser: there a device belongs to the page's one thread, and nothing runs headless.)
    #[cfg(not(target_arch = "wasm32"))]
    pub fn shared_headless(backend: Option<&str>, verbose: bool) -> Result<Arc<Gpu>> {
        type Shared = Vec<(Option<String>, Arc<Gpu>)>;
        static SHARED: Mutex<Shared> = Mutex::new(Vec::new());
        let mut shared = SHARED.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((_, gpu)) = shared.iter().find(|(b, _)| b.as_deref() == backend) {
            return Ok(gpu.clone());
        }
        let gpu = Arc::new(Self::headless(backend, verbose)?);
        shared.push((backend.map(str::to_string), gpu.clone()));
        Ok(gpu)
    }

    /// Runs `work` and fails with the first wgpu error it caused. Error scopes are thread-local,
    /// so renders on other threads that share the device keep their errors to themselves. (Native
    /// only: it waits for the scopes' answers, which a browser gives later.)
    #[cfg(not(target_arch = "wasm32"))]
    pub fn scoped<T>(&self, work: impl FnOnce() -> Result<T>) -> Result<T> {
        let scopes = [
            wgpu::ErrorFilter::Validation,
            wgpu::ErrorFilter::OutOfMemory,
            wgpu::ErrorFilter::Internal,
        ]
        .map(|filter| self.device.push_error_scope(filter));
        let result = work();
        let mut first = None;
        for scope in scopes.into_iter().rev() {
            if let Some(error) = pollster::block_on(scope.pop()) {
                first.get_or_insert(error);
            }
        }
        match first {
            Some(error) => bail!("wgpu reported an error: {}", one_line(&error.to_string())),
            None => result,
        }
    }

    /// Fails with the first wgpu error reported so far (validation errors above all), if any.
    pub fn check_errors(&self) -> Result<()> {
        let errors = std::mem::take(&mut *self.errors.lock().unwrap_or_else(|e| e.into_inner()));
        match errors.first() {
            None => Ok(()),
            Some(first) if errors.len() == 1 => bail!("wgpu reported an error: {first}"),
            Some(first) => bail!("wgpu reported {} errors, the first: {first}", errors.len()),
        }
    }

    /// Whether depth and stencil contents can be copied to a buffer (not on the GL backend).
    pub fn can_copy_depth_stencil(&self) -> bool {
        self.adapter
            .get_downlevel_capabilities()
            .flags
            .contains(wgpu::DownlevelFlags::DEPTH_TEXTURE_AND_BUFFER_COPIES)
    }

    /// The largest width or height a target may have on this device.
    pub fn max_size(&self) -> u32 {
        self.device.limits().max_texture_dimension_2d
    }
}

/// wgpu's messages span several indented lines; errors here are one line.
fn one_line(message: &str) -> String {
    message.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The depth-stencil buffer the framework owns, with the views lessons use.
pub struct DepthStencil {
    pub texture: wgpu::Texture,
    /// Both aspects: the attachment of every render pass.
    pub view: wgpu::TextureView,
    /// The depth aspect alone, for shaders that read the depth buffer (`--show depth`).
    pub depth_only: wgpu::TextureView,
    /// Where `--show stencil` rebuilds the stencil values as colours (see `views`).
    pub stencil_values: wgpu::TextureView,
}

/// A 2-D render target: one mip level, one sample, rendered to and `usage` besides.
pub fn target_texture(
    device: &wgpu::Device,
    label: &str,
    format: wgpu::TextureFormat,
    (width, height): (u32, u32),
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | usage,
        view_formats: &[],
    })
}

/// A picture the lesson draws into before it is shown scaled (see
/// [`crate::app::runner::Runner::draw_through`]), made again when its size changes.
pub struct Picture {
    label: &'static str,
    format: wgpu::TextureFormat,
    made: Option<((u32, u32), wgpu::TextureView)>,
}

impl Picture {
    pub fn new(label: &'static str, format: wgpu::TextureFormat) -> Self {
        Self {
            label,
            format,
            made: None,
        }
    }

    /// The picture at `size`.
    pub fn at(&mut self, device: &wgpu::Device, size: (u32, u32)) -> wgpu::TextureView {
        if let Some((made, view)) = &self.made
            && *made == size
        {
            return view.clone();
        }
        let usage = wgpu::TextureUsages::TEXTURE_BINDING;
        let texture = target_texture(device, self.label, self.format, size, usage);
        let view = texture.create_view(&Default::default());
        self.made = Some((size, view.clone()));
        view
    }
}

impl DepthStencil {
    pub fn new(device: &wgpu::Device, width: u32, height: u32) -> Self {
        // Sampled by --show depth, copied by the tests' readbacks.
        let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC;
        let size = (width, height);
        let texture = target_texture(
            device,
            "depth-stencil buffer",
            DEPTH_STENCIL_FORMAT,
            size,
            usage,
        );
        let view = texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some("depth-stencil view"),
            ..Default::default()
        });
        let depth_only = texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some("depth-only view"),
            aspect: wgpu::TextureAspect::DepthOnly,
            ..Default::default()
        });
        let stencil_values = target_texture(
            device,
            "stencil values",
            crate::gpu::views::STENCIL_VALUES_FORMAT,
            size,
            wgpu::TextureUsages::TEXTURE_BINDING,
        )
        .create_view(&wgpu::TextureViewDescriptor {
            label: Some("stencil values view"),
            ..Default::default()
        });
        Self {
            texture,
            view,
            depth_only,
            stencil_values,
        }
    }

    pub fn size(&self) -> (u32, u32) {
        (self.texture.width(), self.texture.height())
    }
}

/// A render target of a lesson's own, at the size it chooses: a colour texture that shaders can
/// sample and its own depth-stencil buffer (lesson 9's reflection texture). Steps draw into it with
/// [`crate::Frame::step_into`].
pub struct Offscreen {
    pub color: wgpu::Texture,
    pub color_view: wgpu::TextureView,
    pub depth_stencil: DepthStencil,
}

impl Offscreen {
    pub fn new(
        device: &wgpu::Device,
        label: &str,
        format: wgpu::TextureFormat,
        size: (u32, u32),
    ) -> Self {
        let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC;
        let color = target_texture(device, label, format, size, usage);
        let color_view = color.create_view(&wgpu::TextureViewDescriptor {
            label: Some(&format!("{label} view")),
            ..Default::default()
        });
        Self {
            color,
            color_view,
            depth_stencil: DepthStencil::new(device, size.0, size.1),
        }
    }

    pub fn size(&self) -> (u32, u32) {
        (self.color.width(), self.color.height())
    }
}

/// A filterable 2-D texture at `binding`, read by fragment shaders.
pub fn texture_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: true },
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    }
}

/// A 2-D texture at `binding` that fragment shaders read texel by texel (`textureLoad`).
pub fn texel_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: false },
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    }
}

/// A filtering sampler at `binding`, used by fragment shaders.
pub fn sampler_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
        count: None,
    }
}

/// A uniform buffer at `binding`, read by vertex and fragment shaders.
pub fn uniform_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// An sRGB-encoded byte to linear light in 0..1.
pub fn srgb_to_linear(value: u8) -> f32 {
    let c = value as f32 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Linear light in 0..1 to an sRGB-encoded byte.
pub fn linear_to_srgb(value: f32) -> u8 {
    let c = value.clamp(0.0, 1.0);
    let s = if c <= 0.003_130_8 {
        c * 12.92
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0).round() as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_round_trips() {
        for value in 0..=255u8 {
            assert_eq!(linear_to_srgb(srgb_to_linear(value)), value);
        }
    }
}
