//! The workbench's own pictures: the view's three buffers, painted to be seen (egui shows them as
//! thumbnails and the view is one of them), and the panel as last painted.

/// The three buffers of the view and its depth complexity, painted to be seen, each an egui
/// texture.
pub(super) struct Buffers {
    pub(super) size: (u32, u32),
    /// Colour, depth, stencil and complexity pictures (copied into the window, and a pixel's story
    /// reads the colours through the first).
    pub(super) textures: [wgpu::Texture; 4],
    /// Views of the same.
    pub(super) views: [wgpu::TextureView; 4],
    /// The same, as egui samples them (sRGB-encoded values, not decoded).
    pub(super) encoded: [wgpu::TextureView; 4],
}

/// The panel as last painted, to be copied into frames in which it did not change.
pub(super) struct PanelPicture {
    pub(super) texture: wgpu::Texture,
    pub(super) view: wgpu::TextureView,
    pub(super) size: (u32, u32),
    pub(super) pixels_per_point: f32,
    /// What egui painted into it.
    pub(super) shapes: Vec<egui::epaint::ClippedShape>,
}

impl PanelPicture {
    /// A picture of the whole target's size (egui's coordinates are the target's).
    pub(super) fn new(
        device: &wgpu::Device,
        format: wgpu::TextureFormat,
        size: (u32, u32),
    ) -> Self {
        let texture = crate::gpu::target_texture(
            device,
            "workbench panel picture",
            format,
            size,
            wgpu::TextureUsages::COPY_SRC,
        );
        Self {
            view: texture.create_view(&Default::default()),
            texture,
            size,
            pixels_per_point: 0.0,
            shapes: Vec::new(),
        }
    }

    /// Copies the panel's part, from `left` to the right edge, into the same place of `target`.
    pub(super) fn copy(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::Texture,
        left: u32,
    ) {
        let at = |texture| wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d {
                x: left,
                y: 0,
                z: 0,
            },
            aspect: wgpu::TextureAspect::All,
        };
        let extent = wgpu::Extent3d {
            width: self.size.0.saturating_sub(left),
            height: self.size.1,
            depth_or_array_layers: 1,
        };
        if extent.width > 0 {
            encoder.copy_texture_to_texture(at(&self.texture), at(target), extent);
        }
    }
}

impl Buffers {
    pub(super) fn new(gpu: &crate::Gpu, format: wgpu::TextureFormat, size: (u32, u32)) -> Self {
        // egui samples its textures as sRGB-encoded values: it gets views of the same texels
        // without the sRGB decoding (through an sRGB view the thumbnails came out too dark).
        let encoded = format.remove_srgb_suffix();
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let texture = |label, usage| {
            gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width: size.0,
                    height: size.1,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[encoded],
            })
        };
        let textures = [
            texture("workbench colour", usage),
            texture("workbench depth picture", usage),
            texture("workbench stencil picture", usage),
            texture("workbench complexity picture", usage),
        ];
        Self {
            size,
            views: textures
                .each_ref()
                .map(|t| t.create_view(&Default::default())),
            encoded: textures.each_ref().map(|t| {
                t.create_view(&wgpu::TextureViewDescriptor {
                    label: Some("workbench picture for egui"),
                    format: Some(encoded),
                    ..Default::default()
                })
            }),
            textures,
        }
    }
}
