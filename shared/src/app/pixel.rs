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

use crate::app::runner::{FrameRequest, Recorded, Runner};
use crate::gpu::pass::{Draw, Probe, Probing};
use crate::gpu::readback::read_buffer;
use crate::gpu::views::{DEPTH_COPY_FORMAT, STENCIL_VALUES_FORMAT};
use crate::lesson::Lesson;
use crate::lesson::story::{self, DrawStory, Fragment, StepStory, Story, Texel};

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

/// Every draw of the frame `runner` draws into `color` (a view of the frame's size), as a pixel's
/// story meets them (recorded, not submitted): its step, its recipe (where the workbook baked its
/// pipeline) and its object.
pub fn draws<L: Lesson>(runner: &Runner<L>, color: &wgpu::TextureView) -> Vec<Draw> {
    let mut probe = Probe::new(&runner.gpu.device, (0, 0), 0);
    probe.start(Probing::Until(0));
    let request = FrameRequest::to(color).probed(&mut probe);
    drop(runner.record(request));
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
    check_pixel(runner, pixel)?;
    let mut teller = Teller::new(runner, color, pixel)?;

    // 1. The frame as the lesson draws it, the pixel read after every step and each draw in an
    // occlusion query (did it pass?); then every draw silent in a query (does it reach the pixel?).
    let watched = teller.watch().await?;

    // 2. Each draw that reaches the pixel: the frame up to and with it (the pixel after it), and
    // with it as its twins (its first fragment there, and how many it has).
    let reaching: Vec<usize> = (0..teller.draw_count)
        .filter(|&k| watched.covers[k] > 0)
        .collect();
    let mut runs: Vec<Probing> = reaching
        .iter()
        .flat_map(|&k| [Probing::Until(k), Probing::Twin(k, 0)])
        .collect();
    let first = teller.read(&runs).await?;
    // 3. The other fragments of draws whose triangles overlap at the pixel; and for a draw whose
    // faces have stencil states of their own, which face each fragment lies on.
    let draws = &watched.draws;
    let two_sided = |k: usize| draws[k].recipe.as_ref().is_some_and(story::two_sided);
    let more: Vec<Probing> = reaching
        .iter()
        .enumerate()
        .flat_map(|(slot, &k)| {
            let count = first[2 * slot + 1].stencil.min(MAX_FRAGMENTS) as u32;
            let facing = (0..count).filter(move |_| two_sided(k));
            (1..count)
                .map(move |fragment| Probing::Twin(k, fragment))
                .chain(facing.map(move |fragment| Probing::Facing(k, fragment)))
        })
        .collect();
    let others = teller.read(&more).await?;
    runs.extend(more);
    let reads = Reads {
        runs,
        read: first.into_iter().chain(others).collect(),
    };

    Ok(Story {
        lesson: L::NAME,
        pixel,
        size: runner.depth_stencil.size(),
        settings,
        steps: story_steps(watched, &reads, &teller.reader),
    })
}

/// Refuses a pixel outside the picture, and a backend whose shaders cannot read the depth buffer.
fn check_pixel<L: Lesson>(runner: &Runner<L>, pixel: (u32, u32)) -> Result<()> {
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
    Ok(())
}

/// The frame, recorded again and again with a probe on one pixel: the runs that tell its story.
struct Teller<'r, L: Lesson> {
    runner: &'r Runner<L>,
    reader: Reader<'r, L>,
    color_view: wgpu::TextureView,
    /// With room for a query per draw and one per draw's silent twin.
    probe: Probe,
    draw_count: usize,
}

/// What the first round saw: the frame's steps and draws as the lesson drew them, the pixel after
/// each step, and each draw's occlusion counts.
struct Watched {
    steps: Vec<&'static str>,
    /// Whether each step drew into a target of the lesson's own.
    own_targets: Vec<bool>,
    draws: Vec<Draw>,
    /// The pixel after each step, a slot each (see [`Reader::texel`]).
    step_bytes: Vec<u8>,
    /// Each draw's count of fragments that passed both tests.
    passed: Vec<u64>,
    /// Each draw's silent twin's count: does the draw reach the pixel at all?
    covers: Vec<u64>,
}

/// What the second and third rounds read: each run, and the pixel after it.
struct Reads {
    runs: Vec<Probing>,
    read: Vec<Texel>,
}

impl<'r, L: Lesson> Teller<'r, L> {
    fn new(runner: &'r Runner<L>, color: &'r wgpu::Texture, pixel: (u32, u32)) -> Result<Self> {
        let device = &runner.gpu.device;
        let color_view = color.create_view(&Default::default());
        let reader = Reader::new(runner, color, pixel);
        let mut teller = Self {
            runner,
            reader,
            color_view,
            probe: Probe::new(device, pixel, 0),
            draw_count: 0,
        };

        // Count the draws first: the queries need room for them.
        drop(teller.record(Probing::Until(0))?);
        let draw_count = teller.probe.draws.len();
        if 2 * draw_count > wgpu::QUERY_SET_MAX_QUERIES as usize {
            bail!("this frame has {draw_count} draws: too many for a pixel's story");
        }
        teller.probe = Probe::new(device, pixel, draw_count);
        teller.draw_count = draw_count;
        Ok(teller)
    }

    /// The frame recorded once, probed as `probing` says.
    fn record(&mut self, probing: Probing) -> Result<wgpu::CommandEncoder> {
        self.probe.start(probing);
        let request = FrameRequest::to(&self.color_view).probed(&mut self.probe);
        Ok(self.runner.record(request)?.encoder)
    }

    /// The first round: the frame watched, the pixel read after every step, and then covered.
    async fn watch(&mut self) -> Result<Watched> {
        let (runner, device) = (self.runner, &self.runner.gpu.device);
        let step_count = runner.steps().len();
        let step_readback = readback_buffer(device, step_count);
        let (mut own_targets, mut failure) = (Vec::new(), None);
        self.probe.start(Probing::Watch);
        let reader = &self.reader;
        let request = FrameRequest::to(&self.color_view).probed(&mut self.probe);
        let Recorded {
            encoder: watched,
            steps,
        } = runner.record(request.each_step(&mut |encoder, index, offscreen| {
            own_targets.push(offscreen.is_some());
            if let Err(error) = reader.copy(encoder, &step_readback, index) {
                failure.get_or_insert(error);
            }
        }))?;
        if let Some(error) = failure {
            return Err(error);
        }
        let draws = std::mem::take(&mut self.probe.draws);
        if steps.len() != step_count || draws.len() != self.draw_count {
            bail!(
                "the lesson drew another frame the second time: a pixel's story needs the same one"
            );
        }
        let mut covered = self.record(Probing::Cover)?;
        let (_resolved, counts) = self.copy_counts(&mut covered);
        // Each recording ends its passes before the next begins: one submission keeps their order.
        runner
            .gpu
            .queue
            .submit([watched.finish(), covered.finish()]);
        let step_bytes = read_buffer(device, &step_readback).await?;
        let counts: Vec<u64> = bytemuck::pod_collect_to_vec(&read_buffer(device, &counts).await?);
        let (passed, covers) = counts.split_at(self.draw_count);
        Ok(Watched {
            steps,
            own_targets,
            draws,
            step_bytes,
            passed: passed.to_vec(),
            covers: covers.to_vec(),
        })
    }

    /// At the end of `encoder`, resolves the probe's occlusion queries (every draw watched, then
    /// every draw covered) and copies them into a buffer to read. Returns the buffer they resolve
    /// into (kept until the submission) and the one to read.
    fn copy_counts(&self, encoder: &mut wgpu::CommandEncoder) -> (wgpu::Buffer, wgpu::Buffer) {
        let device = &self.runner.gpu.device;
        let queries = 2 * self.draw_count as u32;
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
            encoder.resolve_query_set(&self.probe.queries, 0..queries, &resolved, 0);
            encoder.copy_buffer_to_buffer(&resolved, 0, &counts, 0, query_bytes);
        }
        (resolved, counts)
    }

    /// Records the frame once per entry of `runs`, probed as it says, reads the pixel after each run,
    /// and returns what was read, in order.
    async fn read(&mut self, runs: &[Probing]) -> Result<Vec<Texel>> {
        if runs.is_empty() {
            return Ok(Vec::new());
        }
        let device = &self.runner.gpu.device;
        let readback = readback_buffer(device, runs.len());
        let mut buffers = Vec::with_capacity(runs.len());
        for (slot, &probing) in runs.iter().enumerate() {
            let mut encoder = self.record(probing)?;
            self.reader.copy(&mut encoder, &readback, slot)?;
            buffers.push(encoder.finish());
        }
        self.runner.gpu.queue.submit(buffers);
        let bytes = read_buffer(device, &readback).await?;
        Ok((0..runs.len())
            .map(|slot| self.reader.texel(&bytes, slot))
            .collect())
    }
}

impl Reads {
    /// What each of draw `k`'s fragments at the pixel brought (read from its twins), in the order
    /// the GPU met them.
    fn fragments(&self, k: usize) -> Vec<Fragment> {
        let mut twins: Vec<(u32, Texel)> = self
            .runs
            .iter()
            .zip(&self.read)
            .filter_map(|(probing, texel)| match probing {
                Probing::Twin(draw, fragment) if *draw == k => Some((*fragment, *texel)),
                _ => None,
            })
            .collect();
        twins.sort_by_key(|(fragment, _)| *fragment);
        let facing = |f: u32| {
            (self.runs.iter().zip(&self.read))
                .find(|(probing, _)| **probing == Probing::Facing(k, f))
                .map(|(_, texel)| texel.color[0] > 127)
        };
        twins
            .into_iter()
            .map(|(f, texel)| Fragment {
                color: texel.color,
                depth: texel.depth,
                front: facing(f),
            })
            .collect()
    }

    /// The pixel after draw `k`; none where the draw does not reach the pixel.
    fn after(&self, k: usize) -> Option<Texel> {
        let found = self.runs.iter().position(|p| *p == Probing::Until(k));
        found.map(|index| self.read[index])
    }
}

/// The story's steps: the pixel after each, and each draw's part in it.
fn story_steps<L: Lesson>(
    watched: Watched,
    reads: &Reads,
    reader: &Reader<'_, L>,
) -> Vec<StepStory> {
    let Watched {
        steps,
        own_targets,
        draws,
        step_bytes,
        passed,
        ..
    } = watched;
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
        let (after, fragments) = match reads.after(index) {
            Some(after) => (after, reads.fragments(index)),
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
            outside_scissor: draw.outside_scissor,
            passed: passed[index] > 0,
        });
    }
    story_steps
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
