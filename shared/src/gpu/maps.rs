//! The whole frame seen as maps, made by replaying its draws as their twins
//! ([`crate::gpu::pipelines::Twin`]): `--show complexity`, each pixel's count of fragments in the
//! stencil painted as heat ([`crate::gpu::views::Palette::Heat`]), and `--show tests`, a step's
//! draw painted by what became of its fragments (this module: the test map and how it is shown).

use std::sync::OnceLock;

use wgpu::util::DeviceExt;

use crate::gpu::fullscreen::{self, Over};
use crate::gpu::pipelines::Fate;

// ANCHOR: fate_colours
/// The colour a pixel of the test map takes (sRGB; Okabe and Ito's colours, told apart by the
/// colour-blind): the best fate any of the draw's fragments met there.
pub fn fate_colour(fate: Fate) -> [u8; 3] {
    match fate {
        Fate::Passes => [0, 158, 115],
        Fate::DepthFails => [240, 228, 66],
        Fate::StencilFails => [213, 94, 0],
        Fate::Culled => [204, 121, 167],
    }
}

/// How much of the picture shows through where the draw has no fragment (the rest is black).
pub const UNTOUCHED: f32 = 0.1;
// ANCHOR_END: fate_colours

/// The fates from best to worst: the order the map's shader tries them in.
pub const BEST_FIRST: [Fate; 4] = [
    Fate::Passes,
    Fate::DepthFails,
    Fate::StencilFails,
    Fate::Culled,
];

/// The format of the test map: the frame's own colour format, so that every draw's twin draws
/// into it unchanged; only the written channel differs.
pub fn map_texture(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    size: (u32, u32),
) -> wgpu::TextureView {
    let usage = wgpu::TextureUsages::TEXTURE_BINDING;
    let texture = crate::gpu::target_texture(device, "test map", format, size, usage);
    texture.create_view(&Default::default())
}

/// What `--show tests` paints the picture with; its pipeline is baked the first time it is asked
/// for (most frames never are).
pub struct TestMapView {
    color_format: wgpu::TextureFormat,
    baked: OnceLock<Baked>,
}

struct Baked {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    colours: wgpu::Buffer,
}

impl TestMapView {
    pub fn new(color_format: wgpu::TextureFormat) -> Self {
        Self {
            color_format,
            baked: OnceLock::new(),
        }
    }

    /// Paints `color` (the picture as the step found it) with the fates `map` holds, dimming the
    /// pixels the draw did not reach.
    pub fn paint(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        map: &wgpu::TextureView,
        color: &wgpu::TextureView,
    ) {
        let baked = self.baked.get_or_init(|| bake(device, self.color_format));
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("test map bind group"),
            layout: &baked.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(map),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: baked.colours.as_entire_binding(),
                },
            ],
        });
        let pipeline = (&baked.pipeline, &bind_group);
        fullscreen::draw(encoder, "paint the test map", pipeline, color, Over::Kept);
    }
}

fn bake(device: &wgpu::Device, color_format: wgpu::TextureFormat) -> Baked {
    let source = include_str!("../shaders/test_map.wgsl");
    let shader = fullscreen::shader(device, "test_map.wgsl", source);
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("test map bind group layout"),
        entries: &[crate::gpu::texel_entry(0), crate::gpu::uniform_entry(1)],
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("test map pipeline layout"),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    // The fates replace the picture; elsewhere black at 1 - UNTOUCHED dims it.
    let target = wgpu::ColorTargetState {
        format: color_format,
        blend: Some(wgpu::BlendState::ALPHA_BLENDING),
        write_mask: wgpu::ColorWrites::ALL,
    };
    let pipeline = fullscreen::pipeline(
        device,
        "TEST_MAP",
        &pipeline_layout,
        (&shader, "fs_fates"),
        target,
    );
    let colours: Vec<[f32; 4]> = BEST_FIRST
        .map(|fate| {
            let [r, g, b] = fate_colour(fate).map(crate::gpu::srgb_to_linear);
            [r, g, b, 1.0]
        })
        .into_iter()
        .chain([[0.0, 0.0, 0.0, 1.0 - UNTOUCHED]])
        .collect();
    let colours = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("test map colours"),
        contents: bytemuck::cast_slice(&colours),
        usage: wgpu::BufferUsages::UNIFORM,
    });
    Baked {
        pipeline,
        layout,
        colours,
    }
}
