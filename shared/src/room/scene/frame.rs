//! A frame's camera and lights on the GPU (bind group 0): their uniforms, the bind group that holds
//! them, and its layout.

use glam::{Mat4, Vec4};

use super::lights::Light;
use crate::gpu::pass::Pass;
use crate::math::shadow::LightSource;
use crate::room::camera::View;

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct LightUniform {
    /// w = 0: xyz is the direction the light travels; w = 1: xyz is where it is.
    position: Vec4,
    ambient: Vec4,
    diffuse: Vec4,
    specular: Vec4,
    /// A spot's axis (xyz) and the cosine of its cut-off angle (w); w = -2: no spot.
    spot: Vec4,
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct FrameUniform {
    view_projection: Mat4,
    eye: Vec4,
    lights: [LightUniform; 3],
    /// (n, d) of the plane that clipping recipes keep the front of (zero: none).
    clip_plane: Vec4,
}

/// A frame's camera and lights on the GPU (bind group 0): the scene's own, and one for each world
/// a lesson sees differently (reflected lights, a reflected camera, a clip plane).
pub struct FrameBinding {
    buffer: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

impl FrameBinding {
    /// The layout of every frame binding: one uniform buffer.
    pub(super) fn layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
        device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("frame bind group layout"),
            entries: &[crate::gpu::uniform_entry(0)],
        })
    }

    /// A binding of its own, its buffer and bind group labelled after `label`.
    pub(super) fn new(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, label: &str) -> Self {
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(&format!("{label} uniforms")),
            size: std::mem::size_of::<FrameUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(&format!("{label} bind group")),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: buffer.as_entire_binding(),
            }],
        });
        Self { buffer, bind_group }
    }

    /// Writes what this frame sees through `view`, lit by `lights`, clipped by `clip_plane`.
    pub fn write(&self, queue: &wgpu::Queue, view: &View, lights: &[Light; 3], clip_plane: Vec4) {
        let uniform = FrameUniform {
            view_projection: view.view_projection(),
            eye: view.eye.extend(view.aspect()),
            lights: lights.map(|light| LightUniform {
                position: match light.source {
                    LightSource::Directional { direction } => direction.extend(0.0),
                    LightSource::Point { position } => position.extend(1.0),
                },
                ambient: light.ambient.extend(1.0),
                diffuse: light.diffuse.extend(1.0),
                specular: light.specular.extend(1.0),
                spot: light.spot.map_or(Vec4::new(0.0, 0.0, 0.0, -2.0), |s| {
                    s.axis.extend(s.cos_cutoff)
                }),
            }),
            clip_plane,
        };
        queue.write_buffer(&self.buffer, 0, bytemuck::bytes_of(&uniform));
    }

    /// Binds it as group 0.
    pub fn bind(&self, pass: &mut Pass<'_, '_>) {
        pass.set_bind_group(0, &self.bind_group, &[]);
    }
}
