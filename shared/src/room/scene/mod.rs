//! The room of Luna's Mirror demo, shared by every lesson: a checkered floor, a brick wall with the
//! mirror in it, the mirror, a crate standing partly in front of the mirror and the skull in front of
//! it, lit by three directional lights with Blinn-Phong materials.
//!
//! The room is right-handed with +y up. The mirror lies in the plane z = 0 and faces +z; the room and
//! the camera are on the +z side.
//!
//! This file assembles the [`Scene`]; what it is built from lives beside it: the room's layout,
//! meshes and textures (`room`), its `materials` and `lights`, the wall mirror's reflection
//! (`mirror`), a frame's uniforms (`frame`), the objects on the GPU (`drawables`), a lesson's own
//! geometry (`points`) and the scene's `pipelines`. All that is public is re-exported from here.

mod drawables;
mod frame;
mod lights;
mod materials;
mod mirror;
mod pipelines;
mod points;
mod room;

use std::path::{Path, PathBuf};

use glam::Vec4;

pub use drawables::{Drawable, Placed};
pub use frame::FrameBinding;
pub use lights::{LIGHTS, Light, Spot};
pub use materials::{
    FENCE_MATERIAL, FLOOR_MIRROR_MATERIAL, MIRROR_MATERIAL, Material, ROOM_MATERIAL,
    SHADOW_MATERIAL, SKULL_MATERIAL, WATER_MATERIAL,
};
pub use mirror::{mirror_plane, mirror_reflection, reflected_lights, reflected_world};
pub use points::{POINTS, Points};
pub use room::{
    CLEAR_SRGB, CRATE_CENTRE, CRATE_SIZE, FENCE_CENTRE, FENCE_SIZE, FLOOR_DEPTH, FLOOR_MIRROR_MAX,
    FLOOR_MIRROR_MIN, MIRROR_MAX, MIRROR_MIN, SKULL_CENTRE, SKULL_SIZE, SKULL_YAW_DEGREES,
    WALL_HALF_WIDTH, WALL_HEIGHT, WALL_THICKNESS, WATER_MAX, WATER_MIN, skull_world,
};

use crate::Gpu;
use crate::gpu::maps::TestMapView;
use crate::gpu::pass::Pass;
use crate::gpu::pipelines::Pipelines;
use crate::gpu::views::{Blit, DepthViewPipelines, StencilViewPipeline};
use crate::room::assets::Assets;
use crate::room::camera::{FAR, NEAR, View};
use drawables::DrawableMaker;
use room::{RoomObjects, RoomTextures};

/// What the scene is built from.
#[derive(Debug, Clone)]
pub struct SceneOptions {
    /// The folder with the textures and the skull (the workspace's `assets/` by default).
    pub assets: PathBuf,
    /// A model to show instead of the skull.
    pub model: Option<PathBuf>,
    /// How many samples the textures' sampler may take along a surface seen at a grazing angle (1:
    /// plain trilinear filtering). The floor far away stays sharp with 8, the default; a software
    /// GPU draws the room about 1.5 times faster with 1 (see the book's cost page).
    pub anisotropy: u16,
}

/// The textures' anisotropic filtering unless `--anisotropy` says otherwise.
pub const DEFAULT_ANISOTROPY: u16 = 8;

impl Default for SceneOptions {
    fn default() -> Self {
        Self {
            assets: default_assets(),
            model: None,
            anisotropy: DEFAULT_ANISOTROPY,
        }
    }
}

/// The workspace's `assets/` folder.
pub fn default_assets() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets")
}

/// The room on the GPU, and the layouts every lesson's pipelines share.
pub struct Scene {
    pub color_format: wgpu::TextureFormat,
    pub floor: Drawable,
    pub wall: Drawable,
    pub mirror: Drawable,
    pub crate_box: Drawable,
    pub skull: Drawable,
    /// The skull's mesh (or the model's) on the CPU, in its own coordinates (`skull.world()` places
    /// it): for lessons that compute from its shape, as a shadow volume does.
    pub skull_shape: std::sync::Arc<crate::room::mesh::MeshData>,
    /// Lesson 7's transparent objects.
    pub fence_box: Drawable,
    pub water: Drawable,
    /// Lesson 8's floor: the polished stone mirror, and the tiles around it.
    pub floor_mirror: Drawable,
    pub floor_around_mirror: Drawable,
    frame: FrameBinding,
    reflected_frame: FrameBinding,
    pipeline_layout: wgpu::PipelineLayout,
    pub(crate) frame_layout: wgpu::BindGroupLayout,
    object_layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    shader: wgpu::ShaderModule,
    /// The shader with user clip distances, where the device has them (`Features::CLIP_DISTANCES`).
    clip_distances_shader: Option<wgpu::ShaderModule>,
    /// `None` where shaders cannot read the depth buffer (the GL backend).
    pub(crate) depth_view: Option<DepthViewPipelines>,
    pub(crate) stencil_view: StencilViewPipeline,
    pub(crate) blit: Blit,
    pub(crate) test_map: TestMapView,
    /// Every pipeline baked for the lesson, with its recipe (a pixel's story names them).
    pub pipelines: Pipelines,
    /// The shaders made by [`Scene::shader_with`], by the lesson's own WGSL in them.
    lesson_shaders: std::sync::Mutex<std::collections::HashMap<String, wgpu::ShaderModule>>,
}

impl SceneOptions {
    /// Starts reading the assets on a thread of their own: call it before opening the GPU, and
    /// [`Scene::new`] builds the room once both are done.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn start_reading(&self) -> SceneReading {
        let (assets, model) = (self.assets.clone(), self.model.clone());
        let thread = std::thread::Builder::new()
            .name("assets".into())
            .spawn(move || {
                let start = std::time::Instant::now();
                let assets = Assets::load(&assets, model.as_deref());
                log::info!(
                    target: crate::gpu::STARTUP,
                    "model and textures read, mipmaps made, in {:.0?} (beside the GPU's opening)",
                    start.elapsed()
                );
                assets
            });
        SceneReading {
            assets: thread.map_err(Into::into),
            anisotropy: self.anisotropy,
        }
    }
}

/// A room whose assets are being read on a thread of their own ([`SceneOptions::start_reading`]).
/// Start-up's two longest phases run side by side: reading the assets (the skull's 1.7 MB of OBJ
/// text, six PNGs) and opening the GPU (mostly loading the Vulkan driver and, for a software GPU,
/// LLVM).
#[cfg(not(target_arch = "wasm32"))]
pub struct SceneReading {
    assets: anyhow::Result<std::thread::JoinHandle<anyhow::Result<Assets>>>,
    anisotropy: u16,
}

impl Scene {
    /// The room, once its assets are read.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn new(
        gpu: &Gpu,
        color_format: wgpu::TextureFormat,
        reading: SceneReading,
    ) -> anyhow::Result<Self> {
        let start = std::time::Instant::now();
        let assets = match reading.assets {
            Ok(thread) => thread
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic))?,
            Err(error) => {
                return Err(error.context("cannot start a thread to read the assets"));
            }
        };
        let waited = start.elapsed();
        log::info!(target: crate::gpu::STARTUP, "waited {waited:.0?} for the model and textures");
        let scene = Self::with_assets(gpu, color_format, &assets, reading.anisotropy);
        log::info!(
            target: crate::gpu::STARTUP,
            "room built (meshes and textures uploaded) in {:.0?}",
            start.elapsed() - waited
        );
        Ok(scene)
    }

    /// The room built from assets already read (the web page fetches them).
    pub fn with_assets(
        gpu: &Gpu,
        color_format: wgpu::TextureFormat,
        assets: &Assets,
        anisotropy: u16,
    ) -> Self {
        let (adapter, device, queue) = (&gpu.adapter, &gpu.device, &gpu.queue);
        let frame_layout = FrameBinding::layout(device);
        let object_layout = drawables::object_layout(device);
        let pipeline_layout = pipelines::pipeline_layout(device, &frame_layout, &object_layout);
        let (shader, clip_distances_shader) = pipelines::shaders(device);
        let frame = FrameBinding::new(device, &frame_layout, "frame");
        let reflected_frame = FrameBinding::new(device, &frame_layout, "reflected frame");
        let sampler = drawables::repeating_sampler(device, anisotropy);
        let textures = RoomTextures::upload(device, queue, assets);
        let maker = DrawableMaker {
            device,
            layout: &object_layout,
            sampler: &sampler,
        };
        let objects = RoomObjects::new(&maker, &textures, &assets.model);
        let depth_view = DepthViewPipelines::supported(adapter)
            .then(|| DepthViewPipelines::new(device, color_format, (NEAR, FAR)));
        Self {
            color_format,
            floor: objects.floor,
            wall: objects.wall,
            mirror: objects.mirror,
            crate_box: objects.crate_box,
            skull: objects.skull,
            skull_shape: assets.model.clone(),
            fence_box: objects.fence_box,
            water: objects.water,
            floor_mirror: objects.floor_mirror,
            floor_around_mirror: objects.floor_around_mirror,
            frame,
            reflected_frame,
            pipeline_layout,
            frame_layout,
            object_layout,
            sampler,
            shader,
            clip_distances_shader,
            depth_view,
            stencil_view: StencilViewPipeline::new(device, color_format),
            blit: Blit::new(device, color_format),
            test_map: TestMapView::new(color_format),
            pipelines: Pipelines::default(),
            lesson_shaders: Default::default(),
        }
    }

    /// Writes this frame's camera and lights, and the reflected lights for mirror images.
    pub fn update(&self, queue: &wgpu::Queue, view: &View) {
        self.frame.write(queue, view, &LIGHTS, Vec4::ZERO);
        self.reflected_frame
            .write(queue, view, &reflected_lights(), Vec4::ZERO);
    }

    /// A camera-and-lights binding of a lesson's own, written with [`FrameBinding::write`].
    pub fn frame_binding(&self, device: &wgpu::Device, label: &str) -> FrameBinding {
        FrameBinding::new(device, &self.frame_layout, label)
    }

    /// The room's solid objects, all but the mirror: floor, wall, crate and skull.
    pub fn solid_objects(&self) -> [&Drawable; 4] {
        [&self.floor, &self.wall, &self.crate_box, &self.skull]
    }

    /// The whole room, the mirror's surface with the rest as a plain surface (its ice): floor, wall,
    /// mirror, crate and skull — the room of the lessons whose subject is not the mirror.
    pub fn whole_room(&self) -> [&Drawable; 5] {
        [
            &self.floor,
            &self.wall,
            &self.mirror,
            &self.crate_box,
            &self.skull,
        ]
    }

    /// Draws the room's solid objects — floor, wall, crate and skull, all but the mirror — with the
    /// pipeline already set. The mirror lessons start every frame with it.
    pub fn draw_room(&self, pass: &mut Pass<'_, '_>) {
        for object in self.solid_objects() {
            object.draw(pass);
        }
    }

    /// Binds the frame's camera and lights (group 0).
    pub fn bind_frame(&self, pass: &mut Pass<'_, '_>) {
        self.frame.bind(pass);
    }

    /// Binds the camera with the lights reflected in the mirror (group 0), for mirror images: the
    /// reflected skull must be lit as the real one is, seen from behind the glass.
    pub fn bind_reflected_frame(&self, pass: &mut Pass<'_, '_>) {
        self.reflected_frame.bind(pass);
    }
}
