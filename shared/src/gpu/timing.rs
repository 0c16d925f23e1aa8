//! GPU time per step, from timestamp queries: every step of a timed frame is one render pass (an
//! untimed one may record its steps into one pass: see `lesson::Passes`), and the pass writes a
//! timestamp when it begins and one when it ends. Written once, for the benchmark
//! (`cargo bench-lessons`) and the window's panel. Adapters without `Features::TIMESTAMP_QUERY` get
//! no timer, and callers say so ("CPU time only").

use std::sync::Arc;
use std::sync::atomic::{AtomicU8, Ordering};

use anyhow::{Context, Result};

use crate::Gpu;

/// The most steps a frame may time (two-mirrors at depth 6 has 21).
pub const MAX_STEPS: u32 = 64;

/// Where the read-back of a frame's timestamps stands.
const PENDING: u8 = 0;
const MAPPED: u8 = 1;
const FAILED: u8 = 2;

/// A query set of two timestamps per step, and the buffers they are read back through.
pub struct StepTimer {
    queries: wgpu::QuerySet,
    resolved: wgpu::Buffer,
    readback: wgpu::Buffer,
    /// Nanoseconds per timestamp tick.
    period_ns: f64,
}

impl StepTimer {
    /// A timer, where the device can write timestamps.
    pub fn new(gpu: &Gpu) -> Option<Self> {
        let device = &gpu.device;
        if !device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return None;
        }
        let size = (MAX_STEPS * 2) as u64 * wgpu::QUERY_SIZE as u64;
        let buffer = |label: &str, usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage,
                mapped_at_creation: false,
            })
        };
        Some(Self {
            queries: device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("step timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: MAX_STEPS * 2,
            }),
            resolved: buffer(
                "step timestamps resolved",
                wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            ),
            readback: buffer(
                "step timestamps readback",
                wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            ),
            period_ns: gpu.queue.get_timestamp_period() as f64,
        })
    }

    /// The timestamps the pass of step `index` (from 0) writes; none past [`MAX_STEPS`].
    pub fn writes(&self, index: usize) -> Option<wgpu::RenderPassTimestampWrites<'_>> {
        let index = u32::try_from(index).ok().filter(|&i| i < MAX_STEPS)?;
        Some(wgpu::RenderPassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(2 * index),
            end_of_pass_write_index: Some(2 * index + 1),
        })
    }

    /// Copies the timestamps of the first `steps` steps where [`StepTimer::read`] finds them.
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder, steps: usize) {
        let count = (steps as u32).min(MAX_STEPS) * 2;
        if count == 0 {
            return;
        }
        encoder.resolve_query_set(&self.queries, 0..count, &self.resolved, 0);
        let bytes = count as u64 * wgpu::QUERY_SIZE as u64;
        encoder.copy_buffer_to_buffer(&self.resolved, 0, &self.readback, 0, bytes);
    }

    /// Each step's GPU time in milliseconds, once the frame's commands have run (this waits).
    pub fn read(&self, device: &wgpu::Device, steps: usize) -> Result<Vec<f64>> {
        let ready = self.start_reading(steps);
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .context("waiting for the GPU failed")?;
        self.finish_reading(steps, &ready)
    }

    /// Asks for the times of the first `steps` steps, once the submitted frame has run; the flag
    /// says when they can be read.
    fn start_reading(&self, steps: usize) -> Arc<AtomicU8> {
        let ready = Arc::new(AtomicU8::new(PENDING));
        let count = steps.min(MAX_STEPS as usize);
        if count == 0 {
            ready.store(MAPPED, Ordering::Release);
            return ready;
        }
        let flag = ready.clone();
        self.readback.slice(..(count * 2 * 8) as u64).map_async(
            wgpu::MapMode::Read,
            move |result| {
                let state = if result.is_ok() { MAPPED } else { FAILED };
                flag.store(state, Ordering::Release);
            },
        );
        ready
    }

    /// The times [`StepTimer::start_reading`] asked for, once `ready`.
    fn finish_reading(&self, steps: usize, ready: &AtomicU8) -> Result<Vec<f64>> {
        let count = steps.min(MAX_STEPS as usize);
        if count == 0 {
            return Ok(Vec::new());
        }
        anyhow::ensure!(
            ready.load(Ordering::Acquire) == MAPPED,
            "the timestamps could not be read back"
        );
        let times = {
            let bytes = self
                .readback
                .slice(..(count * 2 * 8) as u64)
                .get_mapped_range()
                .context("reading the timestamps failed")?;
            let ticks: &[u64] = bytemuck::cast_slice(&bytes);
            ticks
                .chunks(2)
                .map(|pair| pair[1].saturating_sub(pair[0]) as f64 * self.period_ns / 1e6)
                .collect()
        };
        self.readback.unmap();
        Ok(times)
    }
}

/// Step timers for a window, whose frames must not wait for the GPU to report a statistic: each
/// frame's times are read when the GPU has finished it, usually by the next frame. Three timers
/// are taken in turn, so that a frame never writes into one still being read.
pub struct LateTimer {
    timers: Vec<(StepTimer, Option<Reading>)>,
    next: usize,
    latest: Option<Vec<f64>>,
}

/// A frame's times on their way back.
struct Reading {
    steps: usize,
    ready: Arc<AtomicU8>,
}

impl LateTimer {
    /// Timers, where the device can write timestamps.
    pub fn new(gpu: &Gpu) -> Option<Self> {
        let timers = (0..3)
            .map(|_| StepTimer::new(gpu).map(|timer| (timer, None)))
            .collect::<Option<Vec<_>>>()?;
        Some(Self {
            timers,
            next: 0,
            latest: None,
        })
    }

    /// The timer for the next frame to write its timestamps into (what it held before is read
    /// first, waiting for the GPU only if that frame is still running).
    pub fn for_next_frame(&mut self, device: &wgpu::Device) -> Result<&StepTimer> {
        self.collect(device)?;
        let index = self.next;
        if let (timer, Some(reading)) = &mut self.timers[index] {
            let (steps, ready) = (reading.steps, reading.ready.clone());
            while ready.load(Ordering::Acquire) == PENDING {
                device
                    .poll(wgpu::PollType::wait_indefinitely())
                    .context("waiting for the GPU failed")?;
            }
            self.latest = Some(timer.finish_reading(steps, &ready)?);
            self.timers[index].1 = None;
        }
        Ok(&self.timers[index].0)
    }

    /// Says that the frame written into the timer [`LateTimer::for_next_frame`] gave was
    /// submitted, with `steps` steps timed: its times are read when the GPU has them.
    pub fn submitted(&mut self, steps: usize) {
        let (timer, reading) = &mut self.timers[self.next];
        let ready = timer.start_reading(steps);
        *reading = Some(Reading { steps, ready });
        self.next = (self.next + 1) % self.timers.len();
    }

    /// The times of the latest frame the GPU has finished (without waiting).
    pub fn latest(&mut self, device: &wgpu::Device) -> Result<Option<&[f64]>> {
        self.collect(device)?;
        Ok(self.latest.as_deref())
    }

    /// Reads every frame whose times arrived, oldest first.
    fn collect(&mut self, device: &wgpu::Device) -> Result<()> {
        device
            .poll(wgpu::PollType::Poll)
            .context("asking the GPU failed")?;
        let count = self.timers.len();
        for offset in 0..count {
            let (timer, reading) = &mut self.timers[(self.next + offset) % count];
            if let Some(Reading { steps, ready }) = reading
                && ready.load(Ordering::Acquire) != PENDING
            {
                self.latest = Some(timer.finish_reading(*steps, ready)?);
                *reading = None;
            }
        }
        Ok(())
    }
}
