//! egui's side of the GPU: its textures (fonts, the FLIP difference, the three buffers as
//! thumbnails) and its triangles. The order of a frame is egui-wgpu's own
//! (`Painter::paint_and_update_textures`): textures made or changed before anything paints with
//! them, the frame submitted, and only then the textures egui let go of destroyed — a texture
//! created and dropped within one frame is still painted by that frame's commands, and destroying
//! it before they are submitted invalidates them.

use crate::Gpu;

/// egui's renderer, with the frame's texture work in its order.
pub struct PanelPainter {
    renderer: egui_wgpu::Renderer,
}

impl PanelPainter {
    /// A painter for targets of `format`.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        // No dithering: the view must show the lesson's pixels as they are.
        let options = egui_wgpu::RendererOptions {
            dithering: false,
            ..Default::default()
        };
        Self {
            renderer: egui_wgpu::Renderer::new(device, format, options),
        }
    }

    /// Lets egui paint `view` (sampled nearest) under a new id.
    pub fn register(&mut self, device: &wgpu::Device, view: &wgpu::TextureView) -> egui::TextureId {
        self.renderer
            .register_native_texture(device, view, wgpu::FilterMode::Nearest)
    }

    /// Points `id` at `view` (the same buffers made again at a new size).
    pub fn replace(
        &mut self,
        device: &wgpu::Device,
        id: egui::TextureId,
        view: &wgpu::TextureView,
    ) {
        let nearest = wgpu::FilterMode::Nearest;
        self.renderer
            .update_egui_texture_from_wgpu_texture(device, view, nearest, id);
    }

    /// Gives the renderer the textures egui made or changed, before anything paints with them.
    pub fn update_textures(&mut self, gpu: &Gpu, textures: &egui::TexturesDelta) {
        for (id, deltas) in &textures.set {
            for delta in deltas {
                let renderer = &mut self.renderer;
                renderer.update_texture(&gpu.device, &gpu.queue, *id, delta);
            }
        }
    }

    /// egui's triangles (tessellated by `ctx`) drawn over `target` of `(width, height)` pixels.
    pub fn paint(
        &mut self,
        gpu: &Gpu,
        ctx: &egui::Context,
        encoder: &mut wgpu::CommandEncoder,
        shapes: Vec<egui::epaint::ClippedShape>,
        pixels_per_point: f32,
        (target, (width, height)): (&wgpu::TextureView, (u32, u32)),
    ) {
        let jobs = ctx.tessellate(shapes, pixels_per_point);
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [width, height],
            pixels_per_point,
        };
        let (device, queue) = (&gpu.device, &gpu.queue);
        let commands = self
            .renderer
            .update_buffers(device, queue, encoder, &jobs, &screen);
        queue.submit(commands);
        let load = wgpu::LoadOp::Load;
        let pass = crate::gpu::fullscreen::color_pass(encoder, "workbench panel", target, load);
        let mut pass = pass.forget_lifetime();
        self.renderer.render(&mut pass, &jobs, &screen);
    }

    /// Submits the frame, then frees the textures egui let go of (see the module's comment).
    pub fn submit(
        &mut self,
        gpu: &Gpu,
        encoder: wgpu::CommandEncoder,
        mut textures: egui::TexturesDelta,
    ) {
        gpu.queue.submit([encoder.finish()]);
        for id in &textures.free {
            self.renderer.free_texture(id);
        }
        // Applied: egui checks that no delta is dropped unapplied.
        textures.clear();
    }
}
