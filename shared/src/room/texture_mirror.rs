//! A mirror made the other way (Rastertek's tutorial 27): the room is rendered from a reflected
//! camera into a texture, and the mirror's surface looks the texture up with projective texture
//! coordinates and mixes it over its own colour. Lesson 9 compares it with the stencil mirror.

use glam::{Mat4, Vec4};

use crate::Gpu;
use crate::gpu::Offscreen;
use crate::gpu::pass::Pass;
use crate::gpu::states::Recipe;
use crate::room::camera::View;
use crate::room::scene::Scene;

/// The mirror's surface pipeline and what it reads (group 2): the texture, a sampler, and the
/// reflected camera's view-projection with the blend.
pub struct TextureMirror {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    uniform: wgpu::Buffer,
}

impl TextureMirror {
    /// The surface drawn with `recipe`'s states and the texture-mirror shader.
    pub fn new(gpu: &Gpu, scene: &Scene, recipe: &Recipe) -> Self {
        let device = &gpu.device;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("texture mirror bind group layout"),
            entries: &[
                crate::gpu::texture_entry(0),
                crate::gpu::sampler_entry(1),
                crate::gpu::uniform_entry(2),
            ],
        });
        let extra = include_str!("../shaders/texture_mirror.wgsl");
        let pipeline =
            scene.extended_pipeline(device, recipe, (&layout, extra, "fs_texture_mirror"));
        // Clamped at the edges: a point of the mirror the reflected camera did not see takes the
        // nearest texel, not one from the other side.
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("reflection texture sampler"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("texture mirror uniforms"),
            size: std::mem::size_of::<[Mat4; 2]>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Self {
            pipeline,
            layout,
            sampler,
            uniform,
        }
    }

    /// Writes the camera that drew the texture and how much of it to mix in.
    pub fn update(&self, queue: &wgpu::Queue, reflected_view: &View, blend: f32) {
        let data = (reflected_view.view_projection(), Vec4::splat(blend));
        let bytes = [
            bytemuck::bytes_of(&data.0).to_vec(),
            bytemuck::bytes_of(&data.1).to_vec(),
        ]
        .concat();
        queue.write_buffer(&self.uniform, 0, &bytes);
    }

    /// Sets the surface's pipeline and binds `texture`'s colours (group 2); draw the surface next.
    pub fn bind(&self, device: &wgpu::Device, pass: &mut Pass<'_, '_>, texture: &Offscreen) {
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("texture mirror bind group"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&texture.color_view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&self.sampler),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: self.uniform.as_entire_binding(),
                },
            ],
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(2, &bind_group, &[]);
    }
}
