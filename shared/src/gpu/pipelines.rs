//! Pipelines baked from named recipes, and remembered: which recipe a pipeline was baked from, and
//! how to bake it again with other states. A pixel's story ([`crate::gpu::pass`]) names the recipe
//! of every draw that reaches its pixel and draws *twins* of it, pipelines with the same shaders
//! but other tests and writes (see [`Twin`]), to read what each fragment brought before the real
//! tests judged it.

use std::collections::HashMap;
use std::sync::Mutex;

use crate::gpu::states::Recipe;

/// Everything of a pipeline that is not its recipe: layout, shaders, vertex buffers, target format.
#[derive(Clone)]
pub struct Stages {
    pub layout: wgpu::PipelineLayout,
    pub module: wgpu::ShaderModule,
    pub vertex: &'static str,
    pub fragment: &'static str,
    pub buffers: &'static [Option<wgpu::VertexBufferLayout<'static>>],
    pub color_format: wgpu::TextureFormat,
}

/// One baked pipeline, with what it was baked from.
struct Baked {
    pipeline: wgpu::RenderPipeline,
    recipe: Recipe,
    stages: Stages,
}

/// The kinds of twin a pixel's story draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Twin {
    /// Writes nothing: in an occlusion query, it says whether the draw reaches the pixel.
    Silent,
    /// Writes the reference (0) into the stencil, nothing else: the count starts there.
    Zero,
    /// Counts the draw's fragments in the stencil (each increments it) and writes the colour and
    /// depth of the one that finds the stencil equal to the reference: fragment `reference`, in
    /// the order the GPU meets them.
    Select,
}

/// Every pipeline baked through [`Pipelines::bake`] since the lesson was last built, and the twins
/// baked of them so far (a window tells a story again and again: a software GPU takes tens of
/// milliseconds to bake one).
#[derive(Default)]
pub struct Pipelines {
    baked: Mutex<Vec<Baked>>,
    twins: Mutex<HashMap<(wgpu::RenderPipeline, Twin), wgpu::RenderPipeline>>,
}

impl Pipelines {
    /// Bakes `recipe` into a pipeline with these stages, labelled with the recipe's name.
    pub fn bake(
        &self,
        device: &wgpu::Device,
        recipe: &Recipe,
        stages: &Stages,
    ) -> wgpu::RenderPipeline {
        let pipeline = create(device, recipe.name, recipe, stages);
        self.lock().push(Baked {
            pipeline: pipeline.clone(),
            recipe: recipe.clone(),
            stages: stages.clone(),
        });
        pipeline
    }

    /// The recipe `pipeline` was baked from, if it was baked here.
    pub fn recipe(&self, pipeline: &wgpu::RenderPipeline) -> Option<Recipe> {
        let baked = self.lock();
        let found = baked.iter().rev().find(|b| &b.pipeline == pipeline);
        found.map(|b| b.recipe.clone())
    }

    /// The pipeline's twin: the same shaders, culling, clipping and depth bias, with no depth test
    /// (`Always`) and the stencil and writes of its [`Twin`] kind.
    pub fn twin(
        &self,
        device: &wgpu::Device,
        pipeline: &wgpu::RenderPipeline,
        kind: Twin,
    ) -> Option<wgpu::RenderPipeline> {
        let key = (pipeline.clone(), kind);
        let twins = || self.twins.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(twin) = twins().get(&key) {
            return Some(twin.clone());
        }
        let (recipe, stages) = {
            let baked = self.lock();
            let found = baked.iter().rev().find(|b| &b.pipeline == pipeline)?;
            (found.recipe.clone(), found.stages.clone())
        };
        let face = |compare, operation| wgpu::StencilFaceState {
            compare,
            fail_op: operation,
            depth_fail_op: operation,
            pass_op: operation,
        };
        let stencil = |face: wgpu::StencilFaceState| wgpu::StencilState {
            front: face,
            back: face,
            read_mask: 0xff,
            write_mask: 0xff,
        };
        use wgpu::{CompareFunction::*, StencilOperation::*};
        let (stencil, writes) = match kind {
            Twin::Silent => (crate::gpu::states::NO_STENCIL, false),
            Twin::Zero => (stencil(face(Always, Replace)), false),
            Twin::Select => (stencil(face(Equal, IncrementClamp)), true),
        };
        let twin = Recipe {
            depth_write: writes,
            depth_compare: Always,
            stencil,
            blend: None,
            color_writes: match writes {
                true => wgpu::ColorWrites::ALL,
                false => wgpu::ColorWrites::empty(),
            },
            ..recipe
        };
        let twin = create(device, "twin of a probed draw", &twin, &stages);
        twins().insert(key, twin.clone());
        Some(twin)
    }

    /// Forgets every pipeline (before the lesson is built again for new knob values).
    pub fn forget(&self) {
        self.lock().clear();
        self.twins.lock().unwrap_or_else(|p| p.into_inner()).clear();
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Vec<Baked>> {
        self.baked
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner())
    }
}

fn create(
    device: &wgpu::Device,
    label: &str,
    recipe: &Recipe,
    stages: &Stages,
) -> wgpu::RenderPipeline {
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(&stages.layout),
        vertex: wgpu::VertexState {
            module: &stages.module,
            entry_point: Some(stages.vertex),
            compilation_options: Default::default(),
            buffers: stages.buffers,
        },
        fragment: Some(wgpu::FragmentState {
            module: &stages.module,
            entry_point: Some(stages.fragment),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format: stages.color_format,
                blend: recipe.blend,
                write_mask: recipe.color_writes,
            })],
        }),
        primitive: wgpu::PrimitiveState {
            topology: wgpu::PrimitiveTopology::TriangleList,
            front_face: recipe.front_face,
            cull_mode: recipe.cull_mode,
            ..Default::default()
        },
        depth_stencil: Some(recipe.depth_stencil()),
        multisample: wgpu::MultisampleState::default(),
        multiview_mask: None,
        cache: None,
    })
}
