//! The headless runner: one frame at W×H into a texture, read back as an image, and on request the
//! stencil and depth buffers too (where the backend can copy them; the GL backend cannot).

use anyhow::{Context, Result, bail};
use image::RgbaImage;

use crate::camera::Camera;
use crate::gpu::{Gpu, HEADLESS_FORMAT};
use crate::knobs::Knobs;
use crate::lesson::Lesson;
use crate::runner::Runner;
use crate::scene::SceneOptions;
use crate::views::DEPTH_COPY_FORMAT;

/// What to render.
#[derive(Debug, Clone)]
pub struct Request {
    pub width: u32,
    pub height: u32,
    pub knobs: Knobs,
    pub camera: Camera,
    pub scene: SceneOptions,
    /// Also read back the stencil buffer.
    pub read_stencil: bool,
    /// Also read back the depth buffer.
    pub read_depth: bool,
    pub backend: Option<String>,
    pub verbose: bool,
}

impl Request {
    /// The default picture of lesson `L` at 1280×720, changed by `name=value` knob settings.
    pub fn new<L: Lesson>(settings: &[impl AsRef<str>]) -> Result<Self> {
        Ok(Self {
            width: 1280,
            height: 720,
            knobs: Knobs::from_settings(L::KNOBS, settings)?,
            camera: Camera::default(),
            scene: SceneOptions::default(),
            read_stencil: false,
            read_depth: false,
            backend: None,
            verbose: false,
        })
    }
}

/// What came back.
#[derive(Debug, Clone)]
pub struct Capture {
    /// The colours, alpha set to opaque as a window shows them.
    pub color: RgbaImage,
    /// One stencil value per pixel, rows top to bottom.
    pub stencil: Option<Vec<u8>>,
    /// One depth value per pixel (0 near .. 1 far), rows top to bottom.
    pub depth: Option<Vec<f32>>,
}

impl Capture {
    pub fn width(&self) -> u32 {
        self.color.width()
    }
    pub fn stencil_at(&self, x: u32, y: u32) -> Option<u8> {
        let stencil = self.stencil.as_ref()?;
        Some(stencil[(y * self.width() + x) as usize])
    }
    pub fn depth_at(&self, x: u32, y: u32) -> Option<f32> {
        let depth = self.depth.as_ref()?;
        Some(depth[(y * self.width() + x) as usize])
    }
}

/// Renders one frame of lesson `L`.
pub fn render<L: Lesson>(request: &Request) -> Result<Capture> {
    Headless::<L>::new(request)?.capture()
}

/// A lesson ready to render headless, again and again: tests step through knob values with
/// [`Headless::set_knobs`] without building the GPU and the room each time.
pub struct Headless<L: Lesson> {
    runner: Runner<L>,
    color: wgpu::Texture,
    read_stencil: bool,
    read_depth: bool,
}

impl<L: Lesson> Headless<L> {
    pub fn new(request: &Request) -> Result<Self> {
        let gpu = Gpu::shared_headless(request.backend.as_deref(), request.verbose)?;
        check_size(&gpu, request.width, request.height)?;
        if (request.read_stencil || request.read_depth) && !gpu.can_copy_depth_stencil() {
            bail!(
                "this backend ({:?}) cannot copy depth or stencil to a buffer; use Vulkan",
                gpu.adapter.get_info().backend
            );
        }
        let size = (request.width, request.height);
        gpu.clone().scoped(|| {
            let runner = Runner::<L>::new(
                gpu,
                HEADLESS_FORMAT,
                &request.scene,
                request.knobs.clone(),
                request.camera,
                size,
            )?;
            let device = &runner.gpu.device;
            let color = target(device, "headless colour target", HEADLESS_FORMAT, size);
            Ok(Self {
                runner,
                color,
                read_stencil: request.read_stencil,
                read_depth: request.read_depth,
            })
        })
    }

    /// Rebuilds the lesson for other knob values.
    pub fn set_knobs(&mut self, knobs: Knobs) -> Result<()> {
        let gpu = self.runner.gpu.clone();
        gpu.scoped(|| self.runner.set_knobs(knobs))
    }

    /// Renders a frame and reads back what the request asked for.
    pub fn capture(&self) -> Result<Capture> {
        self.runner.gpu.scoped(|| self.capture_unscoped())
    }

    fn capture_unscoped(&self) -> Result<Capture> {
        let (runner, size) = (&self.runner, (self.color.width(), self.color.height()));
        let device = &runner.gpu.device;
        let color_view = self.color.create_view(&Default::default());
        let mut encoder = runner.record(&color_view)?;

        let all = wgpu::TextureAspect::All;
        let mut readbacks = vec![Readback::new(device, &mut encoder, &self.color, all, 4)];
        if self.read_stencil {
            let stencil = &runner.depth_stencil.texture;
            let aspect = wgpu::TextureAspect::StencilOnly;
            readbacks.push(Readback::new(device, &mut encoder, stencil, aspect, 1));
        }
        if self.read_depth {
            let depth_copy = target(device, "depth copy", DEPTH_COPY_FORMAT, size);
            runner.copy_depth(&mut encoder, &depth_copy.create_view(&Default::default()))?;
            readbacks.push(Readback::new(device, &mut encoder, &depth_copy, all, 4));
        }
        runner.gpu.queue.submit([encoder.finish()]);
        let mut bytes = readbacks
            .into_iter()
            .map(|readback| readback.read(device))
            .collect::<Result<Vec<_>>>()?
            .into_iter();

        let mut color = RgbaImage::from_raw(size.0, size.1, bytes.next().unwrap())
            .context("colour readback has the wrong size")?;
        for pixel in color.pixels_mut() {
            pixel.0[3] = 255;
        }
        let stencil = self.read_stencil.then(|| bytes.next().unwrap());
        let depth = self
            .read_depth
            .then(|| bytemuck::pod_collect_to_vec(&bytes.next().unwrap()));
        Ok(Capture {
            color,
            stencil,
            depth,
        })
    }
}

/// Refuses sizes the device cannot make.
pub fn check_size(gpu: &Gpu, width: u32, height: u32) -> Result<()> {
    let max = gpu.max_size();
    if width > max || height > max {
        bail!("size {width}x{height} is larger than this GPU allows ({max} pixels a side)");
    }
    Ok(())
}

/// A target the readback can copy from.
fn target(
    device: &wgpu::Device,
    label: &str,
    format: wgpu::TextureFormat,
    size: (u32, u32),
) -> wgpu::Texture {
    crate::gpu::target_texture(device, label, format, size, wgpu::TextureUsages::COPY_SRC)
}

/// Copies one aspect of a texture (mip 0) to the CPU and waits for it: rows top to bottom, without
/// padding. Tests use it for textures of their own.
pub fn read_texture(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    aspect: wgpu::TextureAspect,
    bytes_per_texel: u32,
) -> Result<Vec<u8>> {
    gpu.scoped(|| read_texture_unscoped(gpu, texture, aspect, bytes_per_texel))
}

fn read_texture_unscoped(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    aspect: wgpu::TextureAspect,
    bytes_per_texel: u32,
) -> Result<Vec<u8>> {
    let mut encoder = gpu
        .device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("readback"),
        });
    let readback = Readback::new(&gpu.device, &mut encoder, texture, aspect, bytes_per_texel);
    gpu.queue.submit([encoder.finish()]);
    readback.read(&gpu.device)
}

/// A texture copied into a mappable buffer, rows padded to 256 bytes as wgpu requires.
struct Readback {
    buffer: wgpu::Buffer,
    row_bytes: u32,
    padded_row_bytes: u32,
    height: u32,
}

impl Readback {
    fn new(
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        texture: &wgpu::Texture,
        aspect: wgpu::TextureAspect,
        bytes_per_texel: u32,
    ) -> Self {
        let (width, height) = (texture.width(), texture.height());
        let row_bytes = width * bytes_per_texel;
        let padded_row_bytes = row_bytes.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback buffer"),
            size: (padded_row_bytes * height) as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded_row_bytes),
                    rows_per_image: Some(height),
                },
            },
            texture.size(),
        );
        Self {
            buffer,
            row_bytes,
            padded_row_bytes,
            height,
        }
    }

    /// Waits for the copy and returns the rows without their padding.
    fn read(self, device: &wgpu::Device) -> Result<Vec<u8>> {
        let slice = self.buffer.slice(..);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .context("waiting for the GPU failed")?;
        let mapped = slice
            .get_mapped_range()
            .context("reading back from the GPU failed")?;
        let mut bytes = Vec::with_capacity((self.row_bytes * self.height) as usize);
        for row in mapped.chunks(self.padded_row_bytes as usize) {
            bytes.extend_from_slice(&row[..self.row_bytes as usize]);
        }
        Ok(bytes)
    }
}
