//! Flat shapes drawn straight onto the screen, for writing patterns into the stencil buffer: a disc
//! drawn as a fan of triangles in screen units that keep it round whatever the window's shape.

use glam::Vec2;
use wgpu::util::DeviceExt;

use crate::gpu::pass::Pass;
use crate::gpu::pipelines::Stages;
use crate::gpu::states::Recipe;
use crate::room::scene::Scene;

/// A shape on the GPU.
pub struct Shape {
    /// What the shape is, e.g. `porthole` (a pixel's story names it).
    pub name: &'static str,
    vertices: wgpu::Buffer,
    count: u32,
}

impl Shape {
    /// A disc around `centre` (screen units: the screen is 2 high) with `radius`.
    pub fn disc(device: &wgpu::Device, name: &'static str, centre: Vec2, radius: f32) -> Self {
        const SEGMENTS: usize = 96;
        let point = |i: usize| {
            let angle = i as f32 / SEGMENTS as f32 * std::f32::consts::TAU;
            centre + radius * Vec2::new(angle.cos(), angle.sin())
        };
        let triangles: Vec<[f32; 2]> = (0..SEGMENTS)
            .flat_map(|i| [centre, point(i), point(i + 1)])
            .map(|p| p.to_array())
            .collect();
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(name),
            contents: bytemuck::cast_slice(&triangles),
            usage: wgpu::BufferUsages::VERTEX,
        });
        Self {
            name,
            vertices,
            count: triangles.len() as u32,
        }
    }

    pub fn draw(&self, pass: &mut Pass<'_, '_>) {
        pass.object(self.name);
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.draw(0..self.count, 0..1);
    }
}

/// Bakes a recipe into a pipeline that draws [`Shape`]s.
pub fn pipeline(device: &wgpu::Device, scene: &Scene, recipe: &Recipe) -> wgpu::RenderPipeline {
    let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("shape pipeline layout"),
        bind_group_layouts: &[Some(&scene.frame_layout)],
        immediate_size: 0,
    });
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("shape.wgsl"),
        source: wgpu::ShaderSource::Wgsl(include_str!("../shaders/shape.wgsl").into()),
    });
    let stages = Stages {
        layout,
        module: shader,
        vertex: "vs_shape",
        fragment: "fs_shape",
        buffers: &[Some(wgpu::VertexBufferLayout {
            array_stride: 8,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &ATTRIBUTES,
        })],
        color_format: scene.color_format,
    };
    scene.pipelines.bake(device, recipe, &stages)
}

/// A shape's vertex: its position on the screen.
const ATTRIBUTES: [wgpu::VertexAttribute; 1] = wgpu::vertex_attr_array![0 => Float32x2];
