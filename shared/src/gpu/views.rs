//! Looking inside the buffers: the depth buffer drawn as grey levels (`--show depth`), the stencil
//! buffer in false colour (`--show stencil`), and the copy of depth into a readable colour texture
//! that tests use (a depth aspect of `Depth24PlusStencil8` cannot be copied to a buffer directly).

use wgpu::util::DeviceExt;

use crate::gpu::DepthStencil;
use crate::gpu::fullscreen::{self, Over};

/// The format depth is copied into for readback.
pub const DEPTH_COPY_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// Pipelines that read the depth buffer; built once with the scene.
pub struct DepthViewPipelines {
    layout: wgpu::BindGroupLayout,
    planes: wgpu::Buffer,
    show: wgpu::RenderPipeline,
    show_raw: wgpu::RenderPipeline,
    copy: wgpu::RenderPipeline,
}

impl DepthViewPipelines {
    /// Whether shaders can read the depth buffer and R32Float can be rendered to: not on the GL
    /// backend (`textureLoad` from depth textures has no GLSL translation there).
    pub fn supported(adapter: &wgpu::Adapter) -> bool {
        adapter.get_info().backend != wgpu::Backend::Gl
    }

    /// What to tell someone who asks for the depth buffer where it cannot be read.
    pub const UNSUPPORTED: &str =
        "the GL backend cannot read the depth buffer in a shader: use Vulkan (--backend vulkan)";

    /// The pipelines for targets of `color_format`, linearising between the camera's `near` and
    /// `far` planes.
    pub fn new(
        device: &wgpu::Device,
        color_format: wgpu::TextureFormat,
        (near, far): (f32, f32),
    ) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("depth view bind group layout"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Depth,
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
                crate::gpu::uniform_entry(1),
            ],
        });
        let planes = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("depth view planes"),
            contents: bytemuck::cast_slice(&[near, far]),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("depth view pipeline layout"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let source = include_str!("../shaders/depth_view.wgsl");
        let shader = fullscreen::shader(device, "depth_view.wgsl", source);
        let pipeline = |label: &str, entry: &str, format: wgpu::TextureFormat| {
            let target = format.into();
            fullscreen::pipeline(device, label, &pipeline_layout, (&shader, entry), target)
        };
        Self {
            show: pipeline("SHOW_DEPTH", "fs_depth", color_format),
            show_raw: pipeline("SHOW_RAW_DEPTH", "fs_raw_depth", color_format),
            copy: pipeline("COPY_DEPTH", "fs_copy_depth", DEPTH_COPY_FORMAT),
            layout,
            planes,
        }
    }

    /// The bind group that reads this depth buffer; made again when the buffer is resized.
    pub fn bind_group(&self, device: &wgpu::Device, target: &DepthStencil) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("depth view bind group"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&target.depth_only),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: self.planes.as_entire_binding(),
                },
            ],
        })
    }

    /// Paints `color` with the depth buffer as grey: linearised, or with `raw` the stored values.
    pub fn show(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        color: &wgpu::TextureView,
        bind_group: &wgpu::BindGroup,
        raw: bool,
    ) {
        let (label, pipeline) = match raw {
            false => ("show depth", &self.show),
            true => ("show raw depth", &self.show_raw),
        };
        fullscreen::draw(encoder, label, (pipeline, bind_group), color, Over::Cleared);
    }

    /// Copies one pixel of the depth buffer into the same pixel of `target` (R32Float, the same
    /// size); the rest of `target` is left as it was.
    pub fn copy_pixel(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        bind_group: &wgpu::BindGroup,
        (x, y): (u32, u32),
    ) {
        let label = "copy a pixel's depth";
        let mut pass = fullscreen::color_pass(encoder, label, target, wgpu::LoadOp::Load);
        pass.set_scissor_rect(x, y, 1, 1);
        pass.set_pipeline(&self.copy);
        pass.set_bind_group(0, bind_group, &[]);
        pass.draw(0..3, 0..1);
    }

    /// Copies the depth buffer into `target`, an R32Float texture of the same size.
    pub fn copy(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        bind_group: &wgpu::BindGroup,
    ) {
        let pipeline = (&self.copy, bind_group);
        fullscreen::draw(encoder, "copy depth", pipeline, target, Over::Cleared);
    }
}

// ANCHOR: palette
/// The false colour of a stencil value in `--show stencil` (sRGB): 0 is near black, 1 white, the next
/// few strong distinct colours, 255 (all bits set: what `invert` and `decrement-wrap` make of 0)
/// magenta, and the rest hues spread by the golden ratio.
pub fn stencil_colour(value: u8) -> [u8; 3] {
    match value {
        0 => [24, 24, 32],
        1 => [255, 255, 255],
        2 => [255, 196, 0],
        3 => [0, 180, 255],
        4 => [235, 60, 50],
        5 => [60, 200, 80],
        255 => [255, 0, 255],
        v => {
            let hue = (v as f32 * 0.618_034).fract() * 6.0;
            let x = 1.0 - (hue % 2.0 - 1.0).abs();
            let (r, g, b) = match hue as u32 {
                0 => (1.0, x, 0.0),
                1 => (x, 1.0, 0.0),
                2 => (0.0, 1.0, x),
                3 => (0.0, x, 1.0),
                4 => (x, 0.0, 1.0),
                _ => (1.0, 0.0, x),
            };
            [r, g, b].map(|c| (64.0 + c * 191.0) as u8)
        }
    }
}
// ANCHOR_END: palette

// ANCHOR: heat
/// The colour of a count in `--show complexity` (sRGB): 0 black, then a ramp from dark blue
/// through cyan, green, yellow and red to pink, [`HEAT_LEVELS`] or more white. The picture carries
/// the scale: a box of each colour with its count, in the bottom-left corner.
pub fn heat_colour(count: u8) -> [u8; 3] {
    const RAMP: [[u8; 3]; HEAT_LEVELS as usize] = [
        [0, 0, 0],
        [40, 40, 150],
        [30, 110, 230],
        [20, 180, 200],
        [40, 190, 90],
        [170, 210, 40],
        [250, 220, 30],
        [250, 150, 20],
        [235, 70, 30],
        [200, 20, 60],
        [220, 40, 170],
        [255, 140, 230],
    ];
    RAMP.get(count as usize).copied().unwrap_or([255, 255, 255])
}

/// The first count the heat map paints white: "12+" on its scale.
pub const HEAT_LEVELS: u8 = 12;
// ANCHOR_END: heat

/// The format the stencil values are rebuilt in for `--show stencil`: value / 255 in one byte.
pub const STENCIL_VALUES_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R8Unorm;

/// The pipelines of `--show stencil` and `--show complexity` (the same stencil buffer, read in
/// another palette); built once with the scene.
pub struct StencilViewPipeline {
    /// One per bit i: passes where bit i of the stored value is set (read mask and reference 1 << i).
    bits: Vec<wgpu::RenderPipeline>,
    palette_pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    palette: wgpu::Buffer,
    heat: wgpu::Buffer,
}

/// How the stencil values are painted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Palette {
    /// `--show stencil`: each value its false colour ([`stencil_colour`]).
    Values,
    /// `--show complexity`: each count its heat ([`heat_colour`]), with the scale.
    Heat,
}

impl StencilViewPipeline {
    pub fn new(device: &wgpu::Device, color_format: wgpu::TextureFormat) -> Self {
        let palette = palette_buffer(device, "stencil palette", stencil_colour, 0);
        let boxes = HEAT_LEVELS as u32 + 1;
        let heat = palette_buffer(device, "heat palette", heat_colour, boxes);
        let source = include_str!("../shaders/stencil_view.wgsl");
        let shader = fullscreen::shader(device, "stencil_view.wgsl", source);
        let bits_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("stencil bits pipeline layout"),
            bind_group_layouts: &[],
            immediate_size: 0,
        });
        let bits = (0..8)
            .map(|bit| stencil_bit_pipeline(device, &bits_layout, &shader, bit))
            .collect();
        let layout = stencil_palette_layout(device);
        let palette_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("stencil palette pipeline layout"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let palette_pipeline = fullscreen::pipeline(
            device,
            "STENCIL_PALETTE",
            &palette_layout,
            (&shader, "fs_palette"),
            color_format.into(),
        );
        Self {
            bits,
            palette_pipeline,
            layout,
            palette,
            heat,
        }
    }

    // ANCHOR: show_stencil
    /// Paints every pixel of `color` with the colour of its stencil value in `palette`.
    pub fn show(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        (color, palette): (&wgpu::TextureView, Palette),
        target: &DepthStencil,
    ) {
        // 1. Rebuild the values bit by bit: draw i passes where (1 << i) & stored == 1 << i.
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("stencil bits"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &target.stencil_values,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &target.view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Load,
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Load,
                    store: wgpu::StoreOp::Store,
                }),
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        for (bit, pipeline) in self.bits.iter().enumerate() {
            pass.set_pipeline(pipeline);
            pass.set_stencil_reference(1 << bit);
            pass.draw(0..3, bit as u32..bit as u32 + 1);
        }
        drop(pass);
        // ANCHOR_END: show_stencil

        // 2. Look each value up in the palette.
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("stencil palette bind group"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&target.stencil_values),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: match palette {
                        Palette::Values => self.palette.as_entire_binding(),
                        Palette::Heat => self.heat.as_entire_binding(),
                    },
                },
            ],
        });
        let palette = (&self.palette_pipeline, &bind_group);
        fullscreen::draw(encoder, "stencil palette", palette, color, Over::Cleared);
    }

    /// Rebuilds one pixel's stencil value, bit by bit as [`StencilViewPipeline::show`] does, into
    /// the same pixel of `values` (a [`STENCIL_VALUES_FORMAT`] texture of the frame's size, cleared
    /// first: the bits add up): every backend can copy that to a buffer, where a depth-stencil texture
    /// can be copied only whole, and on some backends not at all.
    pub fn rebuild_pixel(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        values: &wgpu::TextureView,
        target: &DepthStencil,
        (x, y): (u32, u32),
    ) {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("a pixel's stencil bits"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: values,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &target.view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Load,
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Load,
                    store: wgpu::StoreOp::Store,
                }),
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_scissor_rect(x, y, 1, 1);
        for (bit, pipeline) in self.bits.iter().enumerate() {
            pass.set_pipeline(pipeline);
            pass.set_stencil_reference(1 << bit);
            pass.draw(0..3, bit as u32..bit as u32 + 1);
        }
    }
}

/// A palette on the GPU: every stencil value's colour, linear, then how many boxes its scale has
/// in the picture's corner (0: no scale).
fn palette_buffer(
    device: &wgpu::Device,
    label: &str,
    colour: fn(u8) -> [u8; 3],
    boxes: u32,
) -> wgpu::Buffer {
    let colours = (0..=255u8).map(|v| {
        let [r, g, b] = colour(v).map(crate::gpu::srgb_to_linear);
        [r, g, b, 1.0]
    });
    let scale = [boxes as f32, 0.0, 0.0, 0.0];
    let contents: Vec<[f32; 4]> = colours.chain([scale]).collect();
    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(label),
        contents: bytemuck::cast_slice(&contents),
        usage: wgpu::BufferUsages::UNIFORM,
    })
}

/// STENCIL_BIT_i: adds 2^i / 255 to the red channel where bit i of the stored stencil value is set
/// (read mask 1 << i; the reference, 1 << i too, is set when it draws).
fn stencil_bit_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    shader: &wgpu::ShaderModule,
    bit: u32,
) -> wgpu::RenderPipeline {
    // Adds the fragment's value to what is there: the bits sum up to the stored value.
    let add = wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::One,
        operation: wgpu::BlendOperation::Add,
    };
    let equal = wgpu::StencilFaceState {
        compare: wgpu::CompareFunction::Equal,
        fail_op: wgpu::StencilOperation::Keep,
        depth_fail_op: wgpu::StencilOperation::Keep,
        pass_op: wgpu::StencilOperation::Keep,
    };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(&format!("STENCIL_BIT_{bit}")),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module: shader,
            entry_point: Some("vs_bit"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        fragment: Some(wgpu::FragmentState {
            module: shader,
            entry_point: Some("fs_bit"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format: STENCIL_VALUES_FORMAT,
                blend: Some(wgpu::BlendState {
                    color: add,
                    alpha: add,
                }),
                write_mask: wgpu::ColorWrites::RED,
            })],
        }),
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format: crate::gpu::DEPTH_STENCIL_FORMAT,
            depth_write_enabled: Some(false),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: wgpu::StencilState {
                front: equal,
                back: equal,
                read_mask: 1 << bit,
                write_mask: 0,
            },
            bias: wgpu::DepthBiasState::default(),
        }),
        multisample: wgpu::MultisampleState::default(),
        multiview_mask: None,
        cache: None,
    })
}

/// The layout of the palette look-up: the rebuilt stencil values and the palette.
fn stencil_palette_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("stencil palette bind group layout"),
        entries: &[crate::gpu::texel_entry(0), crate::gpu::uniform_entry(1)],
    })
}

/// SHOW_TEXTURE: draws a texture over a whole target of another size, filtered (a lesson's own
/// target in the film) or each texel made a block of pixels (the window at half resolution, whose
/// every pixel is then one of the lesson's, as a picked pixel is).
pub struct Blit {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    linear: wgpu::Sampler,
    nearest: wgpu::Sampler,
}

impl Blit {
    pub fn new(device: &wgpu::Device, color_format: wgpu::TextureFormat) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("blit bind group layout"),
            entries: &[crate::gpu::texture_entry(0), crate::gpu::sampler_entry(1)],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("blit pipeline layout"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("blit.wgsl"),
            source: wgpu::ShaderSource::Wgsl(include_str!("../shaders/blit.wgsl").into()),
        });
        let pipeline = fullscreen::pipeline(
            device,
            "SHOW_TEXTURE",
            &pipeline_layout,
            (&shader, "fs_texture"),
            color_format.into(),
        );
        let sampler = |label, filter| {
            device.create_sampler(&wgpu::SamplerDescriptor {
                label: Some(label),
                mag_filter: filter,
                min_filter: filter,
                ..Default::default()
            })
        };
        Self {
            pipeline,
            layout,
            linear: sampler("blit sampler, filtered", wgpu::FilterMode::Linear),
            nearest: sampler("blit sampler, pixelated", wgpu::FilterMode::Nearest),
        }
    }

    /// Draws `source` over all of `target`, filtered.
    pub fn draw(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        source: &wgpu::TextureView,
        target: &wgpu::TextureView,
    ) {
        let filter = wgpu::FilterMode::Linear;
        self.draw_in(device, encoder, source, target, None, filter);
    }

    /// Draws `source` into the `viewport` (x, y, width, height in pixels) of `target`, or all of
    /// it, clearing the rest to black, sampled with `filter`. A source of the viewport's size is
    /// copied pixel for pixel (the window's view beside its panel); one of half its size, with
    /// `Nearest`, each of its pixels made four.
    pub fn draw_in(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        source: &wgpu::TextureView,
        target: &wgpu::TextureView,
        viewport: Option<[f32; 4]>,
        filter: wgpu::FilterMode,
    ) {
        let sampler = match filter {
            wgpu::FilterMode::Nearest => &self.nearest,
            wgpu::FilterMode::Linear => &self.linear,
        };
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("blit bind group"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(source),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(sampler),
                },
            ],
        });
        let over = viewport.map_or(Over::Cleared, Over::Viewport);
        let pipeline = (&self.pipeline, &bind_group);
        fullscreen::draw(encoder, "show texture", pipeline, target, over);
    }
}
