//! Geometry of a lesson's own, not the room's: triangles of points in homogeneous coordinates
//! (w = 1 for a point, w = 0 for a direction: a point at infinity) in a vertex buffer, drawn by
//! pipelines baked with [`Scene::pipeline_for_vertices`](super::Scene::pipeline_for_vertices) and
//! [`POINTS`]. A shadow volume is such geometry; so is a cap over a cut solid.

use std::ops::Range;

use glam::Vec4;
use wgpu::util::DeviceExt;

use crate::gpu::pass::Pass;

/// How the points lie in their vertex buffer: one `vec4<f32>` each, at location 0.
pub static POINTS: [Option<wgpu::VertexBufferLayout<'static>>; 1] =
    [Some(wgpu::VertexBufferLayout {
        array_stride: 16,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &[wgpu::VertexAttribute {
            format: wgpu::VertexFormat::Float32x4,
            offset: 0,
            shader_location: 0,
        }],
    })];

/// Triangles of homogeneous points in a vertex buffer, named as a pixel's story names the draw.
pub struct Points {
    name: &'static str,
    buffer: wgpu::Buffer,
    count: u32,
}

impl Points {
    /// The points, three to a triangle, in a buffer labelled `name`.
    pub fn new(device: &wgpu::Device, name: &'static str, points: &[Vec4]) -> Self {
        Self {
            name,
            buffer: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(name),
                contents: bytemuck::cast_slice(points),
                usage: wgpu::BufferUsages::VERTEX,
            }),
            count: points.len() as u32,
        }
    }

    /// How many points there are.
    pub fn len(&self) -> u32 {
        self.count
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// Draws the triangles of these points (all of them: `0..self.len()`).
    pub fn draw(&self, pass: &mut Pass<'_, '_>, points: Range<u32>) {
        pass.object(self.name);
        pass.set_vertex_buffer(0, self.buffer.slice(..));
        pass.draw(points, 0..1);
    }
}
