//! The scene's pipelines: its shader (with user clip distances where the device has them), the
//! pipeline layout its objects are drawn with, and the recipes baked with them.

use super::Scene;
use super::lights::{LIGHTS, Light};
use crate::gpu::pipelines::Stages;
use crate::gpu::states::{Clip, Recipe};
use crate::math::shadow::LightSource;
use crate::room::mesh::Vertex;

/// The layout of every scene pipeline: the frame (group 0), then the object (group 1).
pub(super) fn pipeline_layout(
    device: &wgpu::Device,
    frame_layout: &wgpu::BindGroupLayout,
    object_layout: &wgpu::BindGroupLayout,
) -> wgpu::PipelineLayout {
    device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("scene pipeline layout"),
        bind_group_layouts: &[Some(frame_layout), Some(object_layout)],
        immediate_size: 0,
    })
}

/// The scene's shader, and the same with user clip distances where the device has them
/// (`Features::CLIP_DISTANCES`).
pub(super) fn shaders(device: &wgpu::Device) -> (wgpu::ShaderModule, Option<wgpu::ShaderModule>) {
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("scene.wgsl"),
        source: wgpu::ShaderSource::Wgsl(include_str!("../../shaders/scene.wgsl").into()),
    });
    // The same shader with a user clip distance (its `enable` must come first).
    let clip_distances_shader = device
        .features()
        .contains(wgpu::Features::CLIP_DISTANCES)
        .then(|| {
            let source = format!(
                "enable clip_distances;\n{}\n{}",
                include_str!("../../shaders/scene.wgsl"),
                include_str!("../../shaders/clip_distances.wgsl")
            );
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("scene.wgsl with clip distances"),
                source: wgpu::ShaderSource::Wgsl(source.into()),
            })
        });
    (shader, clip_distances_shader)
}

impl Scene {
    /// Whether this device can clip with user clip distances ([`Clip::Distances`]).
    pub fn has_clip_distances(&self) -> bool {
        self.clip_distances_shader.is_some()
    }

    /// Bakes a recipe into a pipeline that draws the room's objects lit by directional lights:
    /// Luna's three ([`LIGHTS`]), or their mirror images. A recipe that clips with
    /// [`Clip::Distances`] on a device without them falls back to the unclipped shader: check
    /// [`Scene::has_clip_distances`] first.
    pub fn pipeline(&self, device: &wgpu::Device, recipe: &Recipe) -> wgpu::RenderPipeline {
        self.pipeline_lit_by(device, recipe, &LIGHTS)
    }

    /// [`Scene::pipeline`] for a frame lit by `lights`: where one of them is a point or a spot
    /// light, the shader that lights by those too (it costs a software GPU a seventh of its frame
    /// more: [`Scene::pipeline`] leaves that code out). Clipping by discarding
    /// ([`Clip::Discard`]) shades by directional lights only.
    pub fn pipeline_lit_by(
        &self,
        device: &wgpu::Device,
        recipe: &Recipe,
        lights: &[Light; 3],
    ) -> wgpu::RenderPipeline {
        let directional = |light: &Light| {
            matches!(light.source, LightSource::Directional { .. }) && light.spot.is_none()
        };
        let shade = match lights.iter().all(directional) {
            true => "fs_main",
            false => "fs_any_light",
        };
        let (module, vertex, fragment) = match (recipe.clip, &self.clip_distances_shader) {
            (Clip::Distances, Some(clipping)) => (clipping, "vs_clip_distances", shade),
            (Clip::Discard, _) => (&self.shader, "vs_main", "fs_discard"),
            _ => (&self.shader, "vs_main", shade),
        };
        let stages = (module, vertex, fragment);
        self.pipeline_from(device, recipe, &self.pipeline_layout, stages)
    }

    /// The scene's shader with `extra` WGSL of a lesson's own appended: entry points that use the
    /// scene's structs, bindings and functions (`transform`, `shade`). Bake pipelines with it by
    /// [`Scene::pipeline_in`]. Made once for each `extra`: a lesson that asks again (for another
    /// recipe, or rebuilt for new knob values) gets the module it got before.
    pub fn shader_with(
        &self,
        device: &wgpu::Device,
        label: &str,
        extra: &str,
    ) -> wgpu::ShaderModule {
        let mut made = self
            .lesson_shaders
            .lock()
            .unwrap_or_else(|p| p.into_inner());
        let module = made.entry(extra.to_string()).or_insert_with(|| {
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(label),
                source: wgpu::ShaderSource::Wgsl(
                    format!("{}\n{extra}", include_str!("../../shaders/scene.wgsl")).into(),
                ),
            })
        });
        module.clone()
    }

    /// Bakes a recipe into a pipeline that draws the room's objects (the scene's bindings and
    /// vertex layout) with entry points `vertex` and `fragment` of a module made by
    /// [`Scene::shader_with`]. The recipe's `clip` is the lesson's to honour in its own entries.
    pub fn pipeline_in(
        &self,
        device: &wgpu::Device,
        recipe: &Recipe,
        stages: (&wgpu::ShaderModule, &'static str, &'static str),
    ) -> wgpu::RenderPipeline {
        self.pipeline_from(device, recipe, &self.pipeline_layout, stages)
    }

    /// Bakes a recipe into a pipeline that draws geometry of a lesson's own, not the room's objects:
    /// vertices laid out as `buffers`, drawn by entries of a module made by [`Scene::shader_with`]
    /// that read the frame (group 0, the camera and lights) and no object.
    pub fn pipeline_for_vertices(
        &self,
        device: &wgpu::Device,
        recipe: &Recipe,
        (module, vertex, fragment): (&wgpu::ShaderModule, &'static str, &'static str),
        buffers: &'static [Option<wgpu::VertexBufferLayout<'static>>],
    ) -> wgpu::RenderPipeline {
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("frame-only pipeline layout"),
            bind_group_layouts: &[Some(&self.frame_layout)],
            immediate_size: 0,
        });
        let stages = Stages {
            layout,
            module: module.clone(),
            vertex,
            fragment,
            buffers,
            color_format: self.color_format,
        };
        self.pipelines.bake(device, recipe, &stages)
    }

    /// A pipeline for the room's objects with a bind group of the caller's own (group 2) and
    /// fragment entry `fragment` of the scene's shader with `extra` WGSL appended.
    pub(crate) fn extended_pipeline(
        &self,
        device: &wgpu::Device,
        recipe: &Recipe,
        (group, extra, fragment): (&wgpu::BindGroupLayout, &str, &'static str),
    ) -> wgpu::RenderPipeline {
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(&format!("{} pipeline layout", recipe.name)),
            bind_group_layouts: &[
                Some(&self.frame_layout),
                Some(&self.object_layout),
                Some(group),
            ],
            immediate_size: 0,
        });
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(&format!("scene.wgsl for {}", recipe.name)),
            source: wgpu::ShaderSource::Wgsl(
                format!("{}\n{extra}", include_str!("../../shaders/scene.wgsl")).into(),
            ),
        });
        self.pipeline_from(device, recipe, &layout, (&module, "vs_main", fragment))
    }

    fn pipeline_from(
        &self,
        device: &wgpu::Device,
        recipe: &Recipe,
        layout: &wgpu::PipelineLayout,
        (module, vertex, fragment): (&wgpu::ShaderModule, &'static str, &'static str),
    ) -> wgpu::RenderPipeline {
        let stages = Stages {
            layout: layout.clone(),
            module: module.clone(),
            vertex,
            fragment,
            buffers: &[Some(Vertex::LAYOUT)],
            color_format: self.color_format,
        };
        self.pipelines.bake(device, recipe, &stages)
    }
}
