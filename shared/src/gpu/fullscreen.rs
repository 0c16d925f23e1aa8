//! One triangle over the whole target, the way every picture of a buffer is painted (the depth
//! and stencil views, the test map, a blit): the vertex entry the shaders share, the pipeline, and
//! the pass with one colour target and no depth.

/// The shared vertex entry `vs_fullscreen`, put before a full-screen shader's own source.
pub const VERTEX: &str = include_str!("../shaders/fullscreen.wgsl");

/// A shader module of `source` with `vs_fullscreen` before it.
pub fn shader(device: &wgpu::Device, label: &str, source: &str) -> wgpu::ShaderModule {
    device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(format!("{VERTEX}{source}").into()),
    })
}

/// A pipeline that draws the full-screen triangle (`vs_fullscreen`) with fragment entry `entry`
/// into `target` (a format, blended or not), with no depth or stencil.
pub fn pipeline(
    device: &wgpu::Device,
    label: &str,
    layout: &wgpu::PipelineLayout,
    (shader, entry): (&wgpu::ShaderModule, &str),
    target: wgpu::ColorTargetState,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module: shader,
            entry_point: Some("vs_fullscreen"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        fragment: Some(wgpu::FragmentState {
            module: shader,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            targets: &[Some(target)],
        }),
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: None,
        multisample: wgpu::MultisampleState::default(),
        multiview_mask: None,
        cache: None,
    })
}

/// A render pass on one colour target, no depth, loaded as `load` says.
pub fn color_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    label: &str,
    target: &wgpu::TextureView,
    load: wgpu::LoadOp<wgpu::Color>,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: target,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load,
                store: wgpu::StoreOp::Store,
            },
        })],
        depth_stencil_attachment: None,
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    })
}

/// Where a full-screen pass draws: over the whole target, kept or cleared to black first, or into a
/// viewport (x, y, width, height in pixels) with the rest cleared.
#[derive(Debug, Clone, Copy)]
pub enum Over {
    Cleared,
    Kept,
    Viewport([f32; 4]),
}

/// One full-screen triangle into `target`, with `pipeline` and `bind_group`.
pub fn draw(
    encoder: &mut wgpu::CommandEncoder,
    label: &str,
    (pipeline, bind_group): (&wgpu::RenderPipeline, &wgpu::BindGroup),
    target: &wgpu::TextureView,
    over: Over,
) {
    let load = match over {
        Over::Kept => wgpu::LoadOp::Load,
        Over::Cleared | Over::Viewport(_) => wgpu::LoadOp::Clear(wgpu::Color::BLACK),
    };
    let mut pass = color_pass(encoder, label, target, load);
    if let Over::Viewport([x, y, width, height]) = over {
        pass.set_viewport(x, y, width, height, 0.0, 1.0);
    }
    pass.set_pipeline(pipeline);
    pass.set_bind_group(0, bind_group, &[]);
    pass.draw(0..3, 0..1);
}
