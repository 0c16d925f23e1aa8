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

/// The kinds of twin: those a pixel's story draws, and those the whole-picture maps draw
/// (`--show complexity`, `--show tests`).
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
    /// [`Twin::Select`] with a fragment shader that writes which side of its triangle the
    /// selected fragment is on: white for the front face, black for the back. A recipe with a
    /// stencil state for each face (a shadow volume's count) needs it to tell the fragment's story.
    Facing,
    /// Counts every fragment the draw makes, whatever the tests would say: the stencil
    /// incremented (clamped at 255), no depth test, nothing else written. `--show complexity`
    /// replays the frame's draws as these.
    Count,
    /// The draw as the lesson records it, with no colour written: the draws of a step before the
    /// one its test map shows.
    Quiet,
    /// Clears one channel of the test map where the draw has a fragment of this fate (see [`Fate`]).
    Fate(Fate),
}

// ANCHOR: fate
/// What became of a draw's fragment, as `--show tests` paints it. Each fate has a twin that
/// draws exactly the fragments of that fate and writes 0 into the fate's channel of a map cleared
/// to white (blend factors `Zero`, `Zero`: the shader's colour does not matter, and what it
/// discards stays discarded). The tests are met against the buffers as the draw found them; only
/// [`Fate::Passes`] writes depth and stencil, as the draw does, and it is drawn last.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Fate {
    /// On a triangle the draw culls (drawn with the other face culled instead, by a fragment
    /// shader that discards nothing: a culled triangle never reaches the draw's own): red.
    Culled,
    /// Failed the stencil test (drawn with the stencil comparison inverted): green.
    StencilFails,
    /// Passed the stencil test and failed the depth test (the depth comparison inverted): blue.
    DepthFails,
    /// Passed both (the draw's own states): alpha.
    Passes,
}
// ANCHOR_END: fate

impl Fate {
    /// Every fate, in the order their twins are drawn (the last one writes, as the draw does).
    pub const ALL: [Fate; 4] = [
        Fate::Culled,
        Fate::StencilFails,
        Fate::DepthFails,
        Fate::Passes,
    ];

    /// The channel of the test map this fate clears.
    pub fn channel(self) -> wgpu::ColorWrites {
        match self {
            Fate::Culled => wgpu::ColorWrites::RED,
            Fate::StencilFails => wgpu::ColorWrites::GREEN,
            Fate::DepthFails => wgpu::ColorWrites::BLUE,
            Fate::Passes => wgpu::ColorWrites::ALPHA,
        }
    }
}

/// Every pipeline baked through [`Pipelines::bake`] since the lesson was last built, and the twins
/// baked of them so far (a window tells a story again and again: a software GPU takes tens of
/// milliseconds to bake one).
#[derive(Default)]
pub struct Pipelines {
    baked: Mutex<Vec<Baked>>,
    twins: Mutex<HashMap<(wgpu::RenderPipeline, Twin), wgpu::RenderPipeline>>,
    /// The fragment shaders of the culled fate's twins (see [`Fate::Culled`]) and of the facing
    /// twins ([`Twin::Facing`]), made once.
    own_fragments: std::sync::OnceLock<wgpu::ShaderModule>,
}

impl Pipelines {
    /// Bakes `recipe` into a pipeline with these stages, labelled with the recipe's name.
    pub fn bake(
        &self,
        device: &wgpu::Device,
        recipe: &Recipe,
        stages: &Stages,
    ) -> wgpu::RenderPipeline {
        let pipeline = create(device, recipe.name, recipe, (stages, None));
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

    /// The pipeline's twin of that kind (see [`twin_recipe`]): the same shaders and vertex
    /// buffers; `None` for a pipeline not baked here, or a twin that would draw nothing.
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
        let twin = twin_recipe(&recipe, kind)?;
        // A culled triangle never reaches the fragment shader: its twin's shader does nothing
        // (the lesson's could discard, as a clip plane does, and leave holes in the culled area).
        let fragment = match kind {
            Twin::Fate(Fate::Culled) => Some((self.own_fragments(device), "fs_culled")),
            Twin::Facing => Some((self.own_fragments(device), "fs_facing")),
            _ => None,
        };
        let twin = create(device, twin_label(kind), &twin, (&stages, fragment));
        twins().insert(key, twin.clone());
        Some(twin)
    }

    fn own_fragments(&self, device: &wgpu::Device) -> &wgpu::ShaderModule {
        self.own_fragments.get_or_init(|| {
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("the twins' own fragment shaders"),
                source: wgpu::ShaderSource::Wgsl(OWN_FRAGMENTS.into()),
            })
        })
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

/// The twin's label, as a debugger lists it.
fn twin_label(kind: Twin) -> &'static str {
    match kind {
        Twin::Silent | Twin::Zero | Twin::Select => "twin of a probed draw",
        Twin::Facing => "facing twin of a probed draw",
        Twin::Count => "COUNT_EVERY_FRAGMENT twin",
        Twin::Quiet => "QUIET twin (no colour)",
        Twin::Fate(Fate::Culled) => "CULLED twin",
        Twin::Fate(Fate::StencilFails) => "STENCIL_FAILS twin",
        Twin::Fate(Fate::DepthFails) => "DEPTH_FAILS twin",
        Twin::Fate(Fate::Passes) => "PASSES twin",
    }
}

// ANCHOR: twin_recipe
/// The recipe of a draw's twin: the same culling, winding, clipping and depth bias unless the kind
/// says otherwise. `None` where the twin would draw nothing (no culled face to draw).
pub fn twin_recipe(recipe: &Recipe, kind: Twin) -> Option<Recipe> {
    use wgpu::{CompareFunction::*, StencilOperation::*};
    let every = |compare, operation| {
        let face = wgpu::StencilFaceState {
            compare,
            fail_op: operation,
            depth_fail_op: operation,
            pass_op: operation,
        };
        wgpu::StencilState {
            front: face,
            back: face,
            read_mask: 0xff,
            write_mask: 0xff,
        }
    };
    let nothing = wgpu::ColorWrites::empty();
    let untested = Recipe {
        depth_write: false,
        depth_compare: Always,
        stencil: crate::gpu::states::NO_STENCIL,
        blend: None,
        color_writes: nothing,
        ..recipe.clone()
    };
    Some(match kind {
        Twin::Silent => untested,
        Twin::Zero => Recipe {
            stencil: every(Always, Replace),
            ..untested
        },
        Twin::Select | Twin::Facing => Recipe {
            depth_write: true,
            stencil: every(Equal, IncrementClamp),
            color_writes: wgpu::ColorWrites::ALL,
            ..untested
        },
        Twin::Count => Recipe {
            stencil: every(Always, IncrementClamp),
            ..untested
        },
        Twin::Quiet => Recipe {
            color_writes: nothing,
            ..recipe.clone()
        },
        Twin::Fate(fate) => fate_recipe(recipe, fate)?,
    })
}

/// The recipe of a fate's twin: the fragments of that fate write 0 into its channel.
fn fate_recipe(recipe: &Recipe, fate: Fate) -> Option<Recipe> {
    // The draw's own stencil test, writing nothing; or the test turned inside out.
    let tested = |invert: bool| {
        let face = |face: wgpu::StencilFaceState| wgpu::StencilFaceState {
            compare: match invert {
                true => inverse(face.compare),
                false => face.compare,
            },
            ..wgpu::StencilFaceState::IGNORE
        };
        let state = &recipe.stencil;
        wgpu::StencilState {
            front: face(state.front),
            back: face(state.back),
            read_mask: state.read_mask,
            write_mask: 0,
        }
    };
    // Whatever the shader says, 0 is written: (colour × 0) + (map × 0).
    let zero = wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::Zero,
        dst_factor: wgpu::BlendFactor::Zero,
        operation: wgpu::BlendOperation::Add,
    };
    let marks = Recipe {
        blend: Some(wgpu::BlendState {
            color: zero,
            alpha: zero,
        }),
        color_writes: fate.channel(),
        ..recipe.clone()
    };
    Some(match fate {
        Fate::Culled => Recipe {
            cull_mode: Some(match recipe.cull_mode? {
                wgpu::Face::Front => wgpu::Face::Back,
                wgpu::Face::Back => wgpu::Face::Front,
            }),
            ..untested_marks(&marks)
        },
        Fate::StencilFails => Recipe {
            stencil: tested(true),
            ..untested_marks(&marks)
        },
        Fate::DepthFails => Recipe {
            depth_write: false,
            depth_compare: inverse(recipe.depth_compare),
            stencil: tested(false),
            ..marks
        },
        Fate::Passes => marks,
    })
}
// ANCHOR_END: twin_recipe

/// A fate's marks with no depth or stencil test and nothing written but the mark.
fn untested_marks(marks: &Recipe) -> Recipe {
    Recipe {
        depth_write: false,
        depth_compare: wgpu::CompareFunction::Always,
        stencil: crate::gpu::states::NO_STENCIL,
        ..marks.clone()
    }
}

/// The comparison that passes exactly where `compare` fails.
pub fn inverse(compare: wgpu::CompareFunction) -> wgpu::CompareFunction {
    use wgpu::CompareFunction::*;
    match compare {
        Never => Always,
        Always => Never,
        Less => GreaterEqual,
        GreaterEqual => Less,
        LessEqual => Greater,
        Greater => LessEqual,
        Equal => NotEqual,
        NotEqual => Equal,
    }
}

/// The fragment entries of the twins that do not run the lesson's: the culled fate's (any colour,
/// as the blend writes 0; nothing discarded), and the facing twin's (white on a front face, black
/// on a back face).
const OWN_FRAGMENTS: &str = "@fragment
fn fs_culled() -> @location(0) vec4<f32> {
    return vec4<f32>(0.0);
}

@fragment
fn fs_facing(@builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    return select(vec4<f32>(0.0, 0.0, 0.0, 1.0), vec4<f32>(1.0), front);
}
";

/// A pipeline of `recipe` with these stages; its fragment entry from another module where one is
/// given.
fn create(
    device: &wgpu::Device,
    label: &str,
    recipe: &Recipe,
    (stages, fragment): (&Stages, Option<(&wgpu::ShaderModule, &str)>),
) -> wgpu::RenderPipeline {
    let (fragment_module, fragment_entry) = fragment.unwrap_or((&stages.module, stages.fragment));
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
            module: fragment_module,
            entry_point: Some(fragment_entry),
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
