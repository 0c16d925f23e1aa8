//! The other way to outline (way=screen-space): no grown copy and no stencil test for the band. The
//! skull and its image are drawn into a mask of their own (red, green), and a triangle over the
//! screen paints amber every pixel outside the mask with a pixel of the mask within the outline's
//! width. The mirror still keeps the image's band to its glass, by the stencil.

use std::cell::{Ref, RefCell};

use workbook::gpu::pipelines::Stages;
use workbook::gpu::states::KEEP_IF_EQUAL;
use workbook::gpu::{Offscreen, states, texture_entry};
use workbook::wgpu::{self, ColorWrites, CompareFunction};
use workbook::{Frame, Gpu, Pass, Recipe, Scene};

use crate::{MIRROR_BIT, SELECTION_BIT, SHADER};

// ANCHOR: recipes
/// The mask: the skull's silhouette, whatever stands in front of it (depth `Always`), into red.
pub const MASK_SKULL: Recipe = Recipe {
    name: "MASK_SKULL",
    depth_write: false,
    depth_compare: CompareFunction::Always,
    color_writes: ColorWrites::RED,
    ..states::OPAQUE
};

/// The image's silhouette into green (a mirror image: its front faces are clockwise).
pub const MASK_IMAGE: Recipe = Recipe {
    name: "MASK_IMAGE",
    color_writes: ColorWrites::GREEN,
    front_face: wgpu::FrontFace::Cw,
    ..MASK_SKULL
};

/// The band around the mask's red: a triangle over the screen, no stencil test; the shader decides.
pub const EDGE: Recipe = Recipe {
    name: "EDGE",
    depth_write: false,
    depth_compare: CompareFunction::Always,
    cull_mode: None,
    ..states::OPAQUE
};

/// The band around the mask's green, kept to the mirror by the stencil: where the value is 0b01.
pub const EDGE_IN_MIRROR: Recipe = Recipe {
    name: "EDGE_IN_MIRROR",
    stencil: wgpu::StencilState {
        front: KEEP_IF_EQUAL,
        back: KEEP_IF_EQUAL,
        read_mask: MIRROR_BIT | SELECTION_BIT,
        write_mask: 0,
    },
    ..EDGE
};

// ANCHOR_END: recipes

pub struct ScreenSpace {
    mask_skull: wgpu::RenderPipeline,
    mask_image: wgpu::RenderPipeline,
    edge_skull: wgpu::RenderPipeline,
    edge_image: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    /// The mask, at the frame's size, made again when that changes, and its bind group.
    mask: RefCell<Option<(Offscreen, wgpu::BindGroup)>>,
}

impl ScreenSpace {
    pub fn new(gpu: &Gpu, scene: &Scene) -> Self {
        let device = &gpu.device;
        let shader = scene.shader_with(device, "outline.wgsl", SHADER);
        let mask = |recipe| scene.pipeline_in(device, recipe, (&shader, "vs_main", "fs_mask"));
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("outline mask bind group layout"),
            entries: &[texture_entry(0)],
        });
        let stages = Stages {
            layout: device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("outline edge pipeline layout"),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            }),
            module: device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("screen_space.wgsl"),
                source: wgpu::ShaderSource::Wgsl(include_str!("screen_space.wgsl").into()),
            }),
            vertex: "vs_screen",
            fragment: "fs_edge_skull",
            buffers: &[],
            color_format: scene.color_format,
        };
        let edge = |recipe, fragment| {
            let stages = Stages {
                fragment,
                ..stages.clone()
            };
            scene.pipelines.bake(device, recipe, &stages)
        };
        Self {
            mask_skull: mask(&MASK_SKULL),
            mask_image: mask(&MASK_IMAGE),
            edge_skull: edge(&EDGE, "fs_edge_skull"),
            edge_image: edge(&EDGE_IN_MIRROR, "fs_edge_image"),
            layout,
            mask: RefCell::new(None),
        }
    }

    /// The step that draws the mask: the skull in red, its image in green.
    pub fn draw_mask(&self, frame: &mut Frame<'_>) {
        let mask = self.mask(frame);
        let Some((mask, _)) = mask.as_ref() else {
            return;
        };
        let scene = frame.scene;
        frame.step_into("draw the selection mask", mask, |pass| {
            pass.set_pipeline(&self.mask_skull);
            scene.skull.draw(pass);
            pass.set_pipeline(&self.mask_image);
            scene.bind_reflected_frame(pass);
            scene.skull.draw_reflected(pass);
        });
    }

    /// Draws the band around the skull's mask (or, `image`, its image's, where the stencil holds
    /// the mirror alone).
    pub fn draw_edge(&self, pass: &mut Pass<'_, '_>, image: bool) {
        let mask = self.mask.borrow();
        let Some((_, bind_group)) = mask.as_ref() else {
            return;
        };
        let (pipeline, reference) = match image {
            false => (&self.edge_skull, 0),
            true => (&self.edge_image, MIRROR_BIT),
        };
        pass.set_pipeline(pipeline);
        pass.set_stencil_reference(reference);
        pass.set_bind_group(0, bind_group, &[]);
        pass.object("a triangle over the screen");
        pass.draw(0..3, 0..1);
    }

    /// The mask at the frame's size, with its bind group.
    fn mask(&self, frame: &Frame<'_>) -> Ref<'_, Option<(Offscreen, wgpu::BindGroup)>> {
        let size = frame.size();
        let current = self.mask.borrow().as_ref().map(|(mask, _)| mask.size());
        if current != Some(size) {
            let device = &frame.gpu.device;
            let mask = Offscreen::new(device, "outline mask", frame.scene.color_format, size);
            let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("outline mask bind group"),
                layout: &self.layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&mask.color_view),
                }],
            });
            *self.mask.borrow_mut() = Some((mask, bind_group));
        }
        self.mask.borrow()
    }
}
