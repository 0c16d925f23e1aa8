//! One pixel's story, read from the GPU: `--pixel X,Y`, a right-click in the window, a click on the
//! book page's canvas.
//!
//! The frame is recorded again and again with a [`Probe`] on the pixel, every pass kept to it by a
//! 1×1 scissor (so each run costs little more than its vertices): once as the lesson draws it, the
//! pixel read back after every step and each draw in an occlusion query (did it pass?); then, for
//! each draw, once up to and with that draw (the pixel after it), and once with that draw as its
//! twin (what its fragment brought, and whether it covers the pixel at all). All runs go into one
//! submission; [`crate::lesson::story`] writes out the tests with the numbers read back.
//!
//! The story is read in three rounds (each needs the numbers of the one before), each waiting for
//! its readback: natively by blocking ([`story`]), in the page by awaiting ([`tell`]).

use anyhow::{Result, bail};

use crate::app::runner::Runner;
use crate::gpu::pass::{Draw, Probe, Probing};
use crate::gpu::readback::read_buffer;
use crate::gpu::views::{DEPTH_COPY_FORMAT, STENCIL_VALUES_FORMAT};
use crate::lesson::Lesson;
use crate::lesson::story::{DrawStory, Fragment, StepStory, Story, Texel};

/// Where one read pixel lies in the readback buffer: a slot each, colour at 0, depth at 4, stencil
/// at 8.
const SLOT: u64 = 256;

/// The story of `pixel` in the frame `runner` draws into `color` (a texture of the frame's size),
/// waiting for the GPU; every wgpu error in it fails it.
#[cfg(not(target_arch = "wasm32"))]
pub fn story<L: Lesson>(
    runner: &Runner<L>,
    color: &wgpu::Texture,
    pixel: (u32, u32),
    settings: String,
) -> Result<Story> {
    runner
        .gpu
        .scoped(|| pollster::block_on(tell(runner, color, pixel, settings)))
}

/// Every draw of the frame `runner` draws into `color`, as a pixel's story meets them (recorded,
/// not submitted): its step, its recipe (where the workbook baked its pipeline) and its object.
pub fn draws<L: Lesson>(runner: &Runner<L>, color: &wgpu::Texture) -> Vec<Draw> {
    let mut probe = Probe::new(&runner.gpu.device, (0, 0), 0);
    probe.start(Probing::Until(0));
    let color_view = color.create_view(&Default::default());
    drop(runner.record_probed(&color_view, &mut probe, &mut |_, _, _| {}));
    probe.draws
}

/// The story of `pixel` in the frame `runner` draws into `color` (a texture of the frame's size),
/// awaiting each readback.
pub async fn tell<L: Lesson>(
    runner: &Runner<L>,
    color: &wgpu::Texture,
    pixel: (u32, u32),
    settings: String,
) -> Result<Story> {
    let (width, height) = runner.depth_stencil.size();
    let (x, y) = pixel;
    if x >= width || y >= height {
        bail!(
            "pixel {x},{y} lies outside the {width}x{height} picture (columns 0 to {}, rows 0 to {})",
            width - 1,
            height - 1
        );
    }
    if !runner.can_show(crate::lesson::steps::Show::Depth) {
        bail!(
            "a pixel's story reads the depth buffer in a shader, which the GL backends (GL, WebGL2) \
             cannot: use Vulkan, Metal, DirectX 12 or WebGPU"
        );
    }
    let (gpu, device) = (&runner.gpu, &runner.gpu.device);
    let color_view = color.create_view(&Default::default());
    let reader = Reader::new(runner, color, pixel);
    let frame = |probe: &mut Probe, probing| {
        probe.start(probing);
        runner
            .record_probed(&color_view, probe, &mut |_, _, _| {})
            .0
    };

    // Count the draws first: the queries need room for them.
    let mut probe = Probe::new(device, pixel, 0);
    drop(frame(&mut probe, Probing::Until(0)));
    let draw_count = probe.draws.len();
    if 2 * draw_count > wgpu::QUERY_SET_MAX_QUERIES as usize {
        bail!("this frame has {draw_count} draws: too many for a pixel's story");
    }
    let mut probe = Probe::new(device, pixel, draw_count);

    // 1. The frame as the lesson draws it, the pixel read after every step and each draw in an
    // occlusion query (did it pass?); then every draw silent in a query (does it reach the pixel?).
    let step_count = runner.steps().len();
    let step_readback = readback_buffer(device, step_count);
    let (mut own_targets, mut failure) = (Vec::new(), None);
    probe.start(Probing::Watch);
    let (watched, steps) =
        runner.record_probed(&color_view, &mut probe, &mut |encoder, index, offscreen| {
            own_targets.push(offscreen.is_some());
            if let Err(error) = reader.copy(encoder, &step_readback, index) {
                failure.get_or_insert(error);
            }
        });
    if let Some(error) = failure {
        return Err(error);
    }
    let draws = std::mem::take(&mut probe.draws);
    if steps.len() != step_count || draws.len() != draw_count {
        bail!("the lesson drew another frame the second time: a pixel's story needs the same one");
    }
    let mut covered = frame(&mut probe, Probing::Cover);
    let queries = 2 * draw_count as u32;
    let query_bytes = queries.max(1) as u64 * 8;
    let resolved = buffer(
        device,
        query_bytes,
        wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
    );
    let counts = buffer(
        device,
        query_bytes,
        wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
    );
    if queries > 0 {
        covered.resolve_query_set(&probe.queries, 0..queries, &resolved, 0);
        covered.copy_buffer_to_buffer(&resolved, 0, &counts, 0, query_bytes);
    }
    // Each recording ends its passes before the next begins: one submission keeps their order.
    gpu.queue.submit([watched.finish(), covered.finish()]);
    let step_bytes = read_buffer(device, &step_readback).await?;
    let counts: Vec<u64> = bytemuck::pod_collect_to_vec(&read_buffer(device, &counts).await?);
    let (passed, covers) = counts.split_at(draw_count);

    // 2. Each draw that reaches the pixel: the frame up to and with it (the pixel after it), and
    // with it as its twins (its first fragment there, and how many it has).
    let reaching: Vec<usize> = (0..draw_count).filter(|&k| covers[k] > 0).collect();
    let mut runs: Vec<Probing> = reaching
        .iter()
        .flat_map(|&k| [Probing::Until(k), Probing::Twin(k, 0)])
        .collect();
    let first = read(runner, &reader, &mut probe, &color_view, &runs).await?;
    // 3. The other fragments of draws whose triangles overlap at the pixel.
    let more: Vec<Probing> = reaching
        .iter()
        .enumerate()
        .flat_map(|(slot, &k)| {
            let count = first[2 * slot + 1].stencil.min(MAX_FRAGMENTS) as u32;
            (1..count).map(move |fragment| Probing::Twin(k, fragment))
        })
        .collect();
    let others = read(runner, &reader, &mut probe, &color_view, &more).await?;
    runs.extend(more);
    let read: Vec<Texel> = first.into_iter().chain(others).collect();
    let fragments = |k: usize| -> Vec<Fragment> {
        let mut twins: Vec<(u32, Texel)> = runs
            .iter()
            .zip(&read)
            .filter_map(|(probing, texel)| match probing {
                Probing::Twin(draw, fragment) if *draw == k => Some((*fragment, *texel)),
                _ => None,
            })
            .collect();
        twins.sort_by_key(|(fragment, _)| *fragment);
        twins
            .into_iter()
            .map(|(_, texel)| Fragment {
                color: texel.color,
                depth: texel.depth,
            })
            .collect()
    };
    let after = |k: usize| {
        let found = runs.iter().position(|p| *p == Probing::Until(k));
        found.map(|index| read[index])
    };

    let mut story_steps: Vec<StepStory> = steps
        .iter()
        .enumerate()
        .map(|(index, name)| StepStory {
            name,
            after: reader.texel(&step_bytes, index),
            into_own_target: own_targets.get(index).copied().unwrap_or(false),
            draws: Vec::new(),
        })
        .collect();
    for (index, draw) in draws.into_iter().enumerate() {
        // The pixel before: after the draw before it in its step, or after the step before.
        let step = &story_steps[draw.step];
        let before = match step.draws.last() {
            Some(previous) => previous.after,
            None => story_steps[draw.step.saturating_sub(1)].after,
        };
        let (after, fragments) = match after(index) {
            Some(after) => (after, fragments(index)),
            None => (before, Vec::new()),
        };
        story_steps[draw.step].draws.push(DrawStory {
            recipe: draw.recipe,
            object: draw.object,
            reference: draw.reference,
            blend_constant: draw.blend_constant,
            before,
            after,
            fragments,
            passed: passed[index] > 0,
        });
    }
    Ok(Story {
        lesson: L::NAME,
        pixel,
        size: runner.depth_stencil.size(),
        settings,
        steps: story_steps,
    })
}

/// Records the frame once per entry of `runs`, probed as it says, reads the pixel after each run,
/// and returns what was read, in order.
async fn read<L: Lesson>(
    runner: &Runner<L>,
    reader: &Reader<'_, L>,
    probe: &mut Probe,
    color_view: &wgpu::TextureView,
    runs: &[Probing],
) -> Result<Vec<Texel>> {
    if runs.is_empty() {
        return Ok(Vec::new());
    }
    let device = &runner.gpu.device;
    let readback = readback_buffer(device, runs.len());
    let mut buffers = Vec::with_capacity(runs.len());
    for (slot, &probing) in runs.iter().enumerate() {
        probe.start(probing);
        let (mut encoder, _) = runner.record_probed(color_view, probe, &mut |_, _, _| {});
        reader.copy(&mut encoder, &readback, slot)?;
        buffers.push(encoder.finish());
    }
    runner.gpu.queue.submit(buffers);
    let bytes = read_buffer(device, &readback).await?;
    Ok((0..runs.len())
        .map(|slot| reader.texel(&bytes, slot))
        .collect())
}

/// The most fragments of one draw a story reads at its pixel.
const MAX_FRAGMENTS: u8 = 16;

/// Reads the pixel's three values into a slot of a buffer: the colour as it is, the depth and
/// the stencil through textures every backend can copy (see [`Runner::copy_depth_pixel`] and
/// [`Runner::copy_stencil_pixel`]).
struct Reader<'r, L: Lesson> {
    runner: &'r Runner<L>,
    color: &'r wgpu::Texture,
    pixel: (u32, u32),
    depth: (wgpu::Texture, wgpu::TextureView),
    stencil: (wgpu::Texture, wgpu::TextureView),
}

impl<'r, L: Lesson> Reader<'r, L> {
    fn new(runner: &'r Runner<L>, color: &'r wgpu::Texture, pixel: (u32, u32)) -> Self {
        let size = runner.depth_stencil.size();
        let target = |label, format| {
            let usage = wgpu::TextureUsages::COPY_SRC;
            let texture =
                crate::gpu::target_texture(&runner.gpu.device, label, format, size, usage);
            let view = texture.create_view(&Default::default());
            (texture, view)
        };
        Self {
            runner,
            color,
            pixel,
            depth: target("a pixel's depth", DEPTH_COPY_FORMAT),
            stencil: target("a pixel's stencil", STENCIL_VALUES_FORMAT),
        }
    }

    fn copy(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        buffer: &wgpu::Buffer,
        slot: usize,
    ) -> Result<()> {
        let (runner, pixel) = (self.runner, self.pixel);
        runner.copy_depth_pixel(encoder, &self.depth.1, pixel)?;
        runner.copy_stencil_pixel(encoder, &self.stencil.1, pixel);
        let origin = wgpu::Origin3d {
            x: pixel.0,
            y: pixel.1,
            z: 0,
        };
        let texel = wgpu::Extent3d {
            width: 1,
            height: 1,
            depth_or_array_layers: 1,
        };
        let sources = [(self.color, 0), (&self.depth.0, 4), (&self.stencil.0, 8)];
        for (texture, offset) in sources {
            encoder.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo {
                    texture,
                    mip_level: 0,
                    origin,
                    aspect: wgpu::TextureAspect::All,
                },
                wgpu::TexelCopyBufferInfo {
                    buffer,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: slot as u64 * SLOT + offset,
                        bytes_per_row: None,
                        rows_per_image: None,
                    },
                },
                texel,
            );
        }
        Ok(())
    }
}

impl<L: Lesson> Reader<'_, L> {
    /// The pixel read into `slot` of `bytes`, its colour as red, green, blue, alpha (a window's
    /// surface format may hold blue first).
    fn texel(&self, bytes: &[u8], slot: usize) -> Texel {
        let at = &bytes[slot * SLOT as usize..];
        let blue_first = matches!(
            self.color.format(),
            wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
        );
        let color = match blue_first {
            true => [at[2], at[1], at[0], at[3]],
            false => [at[0], at[1], at[2], at[3]],
        };
        Texel {
            color,
            depth: f32::from_le_bytes([at[4], at[5], at[6], at[7]]),
            stencil: at[8],
        }
    }
}

/// A buffer with `slots` slots for read pixels.
fn readback_buffer(device: &wgpu::Device, slots: usize) -> wgpu::Buffer {
    let usage = wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ;
    buffer(device, slots.max(1) as u64 * SLOT, usage)
}

fn buffer(device: &wgpu::Device, size: u64, usage: wgpu::BufferUsages) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("a pixel's story"),
        size,
        usage,
        mapped_at_creation: false,
    })
}
