//! GPU time per step, from timestamp queries: every step of a frame is one render pass, and the
//! pass writes a timestamp when it begins and one when it ends. Written once, for the benchmark
//! (`cargo bench-lessons`) and the window's panel. Adapters without `Features::TIMESTAMP_QUERY` get
//! no timer, and callers say so ("CPU time only").

use anyhow::{Context, Result};

use crate::Gpu;

/// The most steps a frame may time (two-mirrors at depth 6 has 21).
pub const MAX_STEPS: u32 = 64;

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
        let count = steps.min(MAX_STEPS as usize);
        if count == 0 {
            return Ok(Vec::new());
        }
        let slice = self.readback.slice(..(count * 2 * 8) as u64);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .context("waiting for the GPU failed")?;
        let times = {
            let bytes = slice
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
