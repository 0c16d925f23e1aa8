//! The room of Luna's Mirror demo, shared by every lesson: a checkered floor, a brick wall with the
//! mirror in it, the mirror, a crate standing partly in front of the mirror and the skull in front of
//! it, lit by three directional lights with Blinn-Phong materials.
//!
//! The room is right-handed with +y up. The mirror lies in the plane z = 0 and faces +z; the room and
//! the camera are on the +z side.

use std::cell::Cell;
use std::f32::consts::FRAC_1_SQRT_2;
use std::path::{Path, PathBuf};

use glam::{Mat4, Vec2, Vec3, Vec4};
use wgpu::util::DeviceExt;

use crate::Gpu;
use crate::gpu::pass::Pass;
use crate::gpu::pipelines::{Pipelines, Stages};
use crate::gpu::states::{Clip, Recipe};
use crate::math::reflect::{Plane, normal_matrix, reflection};
use crate::math::shadow::LightSource;
use crate::room::assets::{Assets, TEXTURE_FILES};
use crate::room::camera::{FAR, NEAR, View};
use crate::room::mesh::{GpuMesh, MeshData, Vertex};
use crate::room::texture;

/// Where the mirror is: the plane z = 0, x in -2.5..2.5, y in 0..4.
pub const MIRROR_MIN: Vec3 = Vec3::new(-2.5, 0.0, 0.0);
pub const MIRROR_MAX: Vec3 = Vec3::new(2.5, 4.0, 0.0);
/// The wall around it: x in -6..6, y in 0..5.
pub const WALL_HALF_WIDTH: f32 = 6.0;
pub const WALL_HEIGHT: f32 = 5.0;
/// The wall is a solid block behind the mirror's plane, this thick.
pub const WALL_THICKNESS: f32 = 0.25;
/// The floor runs from the wall to z = 12.
pub const FLOOR_DEPTH: f32 = 12.0;
/// The crate: a cube standing on the floor, in front of the mirror's lower right corner.
pub const CRATE_SIZE: f32 = 1.4;
pub const CRATE_CENTRE: Vec3 = Vec3::new(2.2, CRATE_SIZE / 2.0, 1.6);
/// The wire-fence crate, to the left in front of the mirror.
pub const FENCE_SIZE: f32 = 1.6;
pub const FENCE_CENTRE: Vec3 = Vec3::new(-3.4, FENCE_SIZE / 2.0, 2.4);
/// The water: a shallow pool on the floor that runs up to the mirror, its surface 25 cm above the
/// tiles, so the mirror's lowest strip is seen through it.
pub const WATER_MIN: Vec3 = Vec3::new(-1.5, 0.25, 0.0);
pub const WATER_MAX: Vec3 = Vec3::new(1.2, 0.25, 2.8);
/// The skull: where its bounding box's centre goes, how tall it is, how far it is turned.
pub const SKULL_CENTRE: Vec3 = Vec3::new(-0.5, 1.5, 2.5);
pub const SKULL_SIZE: f32 = 1.7;
pub const SKULL_YAW_DEGREES: f32 = 50.0;
/// The floor mirror of lesson 8: a slab of polished stone set into the floor (the plane y = 0),
/// x in -4..4, z in 0.3..5.3 — the crate stands on it, the skull floats above it.
pub const FLOOR_MIRROR_MIN: Vec3 = Vec3::new(-4.0, 0.0, 0.3);
pub const FLOOR_MIRROR_MAX: Vec3 = Vec3::new(4.0, 0.0, 5.3);
/// The sky, what every frame is cleared to: a dark slate (Luna clears to a light steel blue). Dark,
/// so that a mirror with nothing reflected in it yet reads as dark glass, and what is missing from a
/// reflection shows as a dark gap.
pub const CLEAR_SRGB: [u8; 3] = [36, 42, 56];

/// A surface's response to light, as Luna's `Material`.
#[derive(Debug, Clone, Copy)]
pub struct Material {
    pub ambient: Vec3,
    pub diffuse: Vec3,
    /// Opacity used when the material is blended (the mirror's is 0.5).
    pub alpha: f32,
    pub specular: Vec3,
    pub shininess: f32,
    /// Texels whose alpha is below this are thrown away (0: none are); the wire fence's holes.
    pub alpha_cutoff: f32,
}

/// Luna's room and skull material: half ambient, full diffuse, a dull highlight.
pub const ROOM_MATERIAL: Material = Material {
    ambient: Vec3::splat(0.5),
    diffuse: Vec3::ONE,
    alpha: 1.0,
    specular: Vec3::splat(0.4),
    shininess: 16.0,
    alpha_cutoff: 0.0,
};
pub const SKULL_MATERIAL: Material = Material {
    ambient: Vec3::splat(0.5),
    diffuse: Vec3::ONE,
    alpha: 1.0,
    specular: Vec3::splat(0.4),
    shininess: 24.0,
    alpha_cutoff: 0.0,
};
pub const MIRROR_MATERIAL: Material = Material {
    alpha: 0.5,
    ..ROOM_MATERIAL
};
/// Lesson 8's polished stone: 60% of what is seen in it is the stone's own colour, 40% the
/// reflection — SPE's constant alpha of 0.4 for the reflection, the other way round.
pub const FLOOR_MIRROR_MATERIAL: Material = Material {
    alpha: 0.6,
    ambient: Vec3::splat(0.2),
    diffuse: Vec3::new(0.35, 0.38, 0.42),
    ..ROOM_MATERIAL
};
/// A planar shadow: black, at 50%.
pub const SHADOW_MATERIAL: Material = Material {
    ambient: Vec3::ZERO,
    diffuse: Vec3::ZERO,
    alpha: 0.5,
    specular: Vec3::ZERO,
    shininess: 1.0,
    alpha_cutoff: 0.0,
};
/// Water lets half the light through.
pub const WATER_MATERIAL: Material = Material {
    alpha: 0.5,
    specular: Vec3::splat(0.8),
    shininess: 64.0,
    ..ROOM_MATERIAL
};
/// The wire fence: opaque wires, holes cut where the texture's alpha is below 0.1, the soft edges
/// in between blended.
pub const FENCE_MATERIAL: Material = Material {
    alpha_cutoff: 0.1,
    ..ROOM_MATERIAL
};

/// A light, as Luna's `DirectionalLight`, `PointLight` and `SpotLight`.
#[derive(Debug, Clone, Copy)]
pub struct Light {
    /// The direction the light travels, or where it is.
    pub source: LightSource,
    /// A spot light's cone, around its axis.
    pub spot: Option<Spot>,
    pub ambient: Vec3,
    pub diffuse: Vec3,
    pub specular: Vec3,
}

/// A spot light's cone: light leaves along `axis`, fading out at the angle whose cosine is
/// `cos_cutoff`.
#[derive(Debug, Clone, Copy)]
pub struct Spot {
    pub axis: Vec3,
    pub cos_cutoff: f32,
}

// ANCHOR: light_reflected
impl Light {
    /// The light as the mirror world sees it: a position goes through the reflection as a point;
    /// a direction, and a spot's axis, as vectors (no translation).
    pub fn reflected(&self, reflection: Mat4) -> Light {
        Light {
            source: self.source.reflected(reflection),
            spot: self.spot.map(|spot| Spot {
                axis: reflection.transform_vector3(spot.axis),
                ..spot
            }),
            ..*self
        }
    }
}
// ANCHOR_END: light_reflected

/// Luna's three lights (a key light from the front right, a fill from the front left, a back light),
/// with z negated: his room lies on −z in a left-handed frame, ours on +z in a right-handed one.
pub const LIGHTS: [Light; 3] = [
    Light {
        source: LightSource::Directional {
            direction: Vec3::new(0.577_35, -0.577_35, -0.577_35),
        },
        spot: None,
        ambient: Vec3::splat(0.2),
        diffuse: Vec3::splat(0.5),
        specular: Vec3::splat(0.5),
    },
    Light {
        source: LightSource::Directional {
            direction: Vec3::new(-0.577_35, -0.577_35, -0.577_35),
        },
        spot: None,
        ambient: Vec3::ZERO,
        diffuse: Vec3::splat(0.2),
        specular: Vec3::splat(0.25),
    },
    Light {
        source: LightSource::Directional {
            direction: Vec3::new(0.0, -FRAC_1_SQRT_2, FRAC_1_SQRT_2),
        },
        spot: None,
        ambient: Vec3::ZERO,
        diffuse: Vec3::splat(0.2),
        specular: Vec3::ZERO,
    },
];

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct LightUniform {
    /// w = 0: xyz is the direction the light travels; w = 1: xyz is where it is.
    position: Vec4,
    ambient: Vec4,
    diffuse: Vec4,
    specular: Vec4,
    /// A spot's axis (xyz) and the cosine of its cut-off angle (w); w = -2: no spot.
    spot: Vec4,
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct FrameUniform {
    view_projection: Mat4,
    eye: Vec4,
    lights: [LightUniform; 3],
    /// (n, d) of the plane that clipping recipes keep the front of (zero: none).
    clip_plane: Vec4,
}

/// A frame's camera and lights on the GPU (bind group 0): the scene's own, and one for each world
/// a lesson sees differently (reflected lights, a reflected camera, a clip plane).
pub struct FrameBinding {
    buffer: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

impl FrameBinding {
    /// Writes what this frame sees through `view`, lit by `lights`, clipped by `clip_plane`.
    pub fn write(&self, queue: &wgpu::Queue, view: &View, lights: &[Light; 3], clip_plane: Vec4) {
        let uniform = FrameUniform {
            view_projection: view.view_projection(),
            eye: view.eye.extend(view.aspect()),
            lights: lights.map(|light| LightUniform {
                position: match light.source {
                    LightSource::Directional { direction } => direction.extend(0.0),
                    LightSource::Point { position } => position.extend(1.0),
                },
                ambient: light.ambient.extend(1.0),
                diffuse: light.diffuse.extend(1.0),
                specular: light.specular.extend(1.0),
                spot: light.spot.map_or(Vec4::new(0.0, 0.0, 0.0, -2.0), |s| {
                    s.axis.extend(s.cos_cutoff)
                }),
            }),
            clip_plane,
        };
        queue.write_buffer(&self.buffer, 0, bytemuck::bytes_of(&uniform));
    }

    /// Binds it as group 0.
    pub fn bind(&self, pass: &mut Pass<'_, '_>) {
        pass.set_bind_group(0, &self.bind_group, &[]);
    }
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct ObjectUniform {
    world: Mat4,
    normal_matrix: Mat4,
    ambient: Vec4,
    diffuse: Vec4,
    specular: Vec4,
    params: Vec4,
}

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

/// One thing in the room: a mesh, where it stands, what it is made of — and the same thing as the
/// mirror shows it.
pub struct Drawable {
    pub name: &'static str,
    pub(crate) mesh: GpuMesh,
    bind_group: wgpu::BindGroup,
    reflected: wgpu::BindGroup,
    /// The uniform buffers of both bind groups, with what they hold.
    uniforms: [(wgpu::Buffer, Cell<ObjectUniform>); 2],
    /// The texture, kept to make more bind groups of the object (see [`Scene::placed`]).
    texture: wgpu::TextureView,
    /// The centre of the mesh's bounding box, in the mesh's own coordinates.
    local_centre: Vec3,
}

impl Drawable {
    /// Binds this object's transform, material and texture (group 1) and draws it.
    pub fn draw(&self, pass: &mut Pass<'_, '_>) {
        pass.set_bind_group(1, &self.bind_group, &[]);
        pass.object(self.name);
        self.mesh.draw(pass);
    }

    /// Draws the object's mirror image: its world matrix is `R * world`, R the reflection in the
    /// mirror's plane. Bind the reflected lights with [`Scene::bind_reflected_frame`] first.
    pub fn draw_reflected(&self, pass: &mut Pass<'_, '_>) {
        pass.set_bind_group(1, &self.reflected, &[]);
        pass.object(self.name);
        self.mesh.draw(pass);
    }

    /// The centre of the object's bounding box, in the world.
    pub fn centre(&self) -> Vec3 {
        self.world().transform_point3(self.local_centre)
    }

    /// Where the object stands: its world matrix.
    pub fn world(&self) -> Mat4 {
        self.uniforms[0].1.get().world
    }

    /// Moves the object (and its mirror image in the wall mirror).
    pub fn set_world(&self, queue: &wgpu::Queue, world: Mat4) {
        let worlds = [world, reflected_world(world)];
        for ((buffer, uniform), world) in self.uniforms.iter().zip(worlds) {
            uniform.set(ObjectUniform {
                world,
                normal_matrix: normal_matrix(world),
                ..uniform.get()
            });
            queue.write_buffer(buffer, 0, bytemuck::bytes_of(&uniform.get()));
        }
    }

    /// Where the object's mirror image stands: its centre reflected in the mirror's plane.
    pub fn reflected_centre(&self) -> Vec3 {
        mirror_reflection().transform_point3(self.centre())
    }

    /// Draws the object placed elsewhere (see [`Scene::placed`]).
    pub fn draw_placed(&self, pass: &mut Pass<'_, '_>, placed: &Placed) {
        debug_assert_eq!(placed.object, self.name, "a placement of another object");
        pass.set_bind_group(1, &placed.bind_group, &[]);
        pass.object(self.name);
        self.mesh.draw(pass);
    }

    /// Changes the material's alpha (for the object and its mirror image).
    pub fn set_alpha(&self, queue: &wgpu::Queue, alpha: f32) {
        for (buffer, uniform) in &self.uniforms {
            uniform.set(ObjectUniform {
                diffuse: uniform.get().diffuse.truncate().extend(alpha),
                ..uniform.get()
            });
            queue.write_buffer(buffer, 0, bytemuck::bytes_of(&uniform.get()));
        }
    }
}

/// An object placed by another world matrix: see [`Scene::placed`].
pub struct Placed {
    object: &'static str,
    bind_group: wgpu::BindGroup,
}

impl Placed {
    /// The name of the object placed.
    pub fn object(&self) -> &'static str {
        self.object
    }
}

impl FrameBinding {
    fn new(device: &wgpu::Device, layout: &wgpu::BindGroupLayout, label: &str) -> Self {
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(&format!("{label} uniforms")),
            size: std::mem::size_of::<FrameUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(&format!("{label} bind group")),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: buffer.as_entire_binding(),
            }],
        });
        Self { buffer, bind_group }
    }
}

/// An object's bind group (group 1): its uniforms, texture and sampler.
fn object_bind_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    sampler: &wgpu::Sampler,
    texture: &wgpu::TextureView,
    label: &str,
    uniform: &ObjectUniform,
) -> (wgpu::Buffer, wgpu::BindGroup) {
    let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some(&format!("{label} uniforms")),
        contents: bytemuck::bytes_of(uniform),
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(&format!("{label} bind group")),
        layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: buffer.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: wgpu::BindingResource::TextureView(texture),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: wgpu::BindingResource::Sampler(sampler),
            },
        ],
    });
    (buffer, group)
}

/// The room on the GPU, and the layouts every lesson's pipelines share.
pub struct Scene {
    pub color_format: wgpu::TextureFormat,
    pub floor: Drawable,
    pub wall: Drawable,
    pub mirror: Drawable,
    pub crate_box: Drawable,
    pub skull: Drawable,
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
    pub(crate) depth_view: Option<crate::gpu::views::DepthViewPipelines>,
    pub(crate) stencil_view: crate::gpu::views::StencilViewPipeline,
    pub(crate) blit: crate::gpu::views::Blit,
    /// Every pipeline baked for the lesson, with its recipe (a pixel's story names them).
    pub pipelines: Pipelines,
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
        let skull_mesh = &assets.model;

        let frame_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("frame bind group layout"),
            entries: &[crate::gpu::uniform_entry(0)],
        });
        let object_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("object bind group layout"),
            entries: &[
                crate::gpu::uniform_entry(0),
                crate::gpu::texture_entry(1),
                crate::gpu::sampler_entry(2),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("scene pipeline layout"),
            bind_group_layouts: &[Some(&frame_layout), Some(&object_layout)],
            immediate_size: 0,
        });
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("scene.wgsl"),
            source: wgpu::ShaderSource::Wgsl(include_str!("../shaders/scene.wgsl").into()),
        });
        // The same shader with a user clip distance (its `enable` must come first).
        let clip_distances_shader = device
            .features()
            .contains(wgpu::Features::CLIP_DISTANCES)
            .then(|| {
                let source = format!(
                    "enable clip_distances;\n{}\n{}",
                    include_str!("../shaders/scene.wgsl"),
                    include_str!("../shaders/clip_distances.wgsl")
                );
                device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some("scene.wgsl with clip distances"),
                    source: wgpu::ShaderSource::Wgsl(source.into()),
                })
            });
        let frame = FrameBinding::new(device, &frame_layout, "frame");
        let reflected_frame = FrameBinding::new(device, &frame_layout, "reflected frame");
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some(match anisotropy {
                1 => "repeating trilinear sampler",
                _ => "repeating anisotropic sampler",
            }),
            address_mode_u: wgpu::AddressMode::Repeat,
            address_mode_v: wgpu::AddressMode::Repeat,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            anisotropy_clamp: anisotropy,
            ..Default::default()
        });
        // Each picture uploaded once (the floor and the floor mirror share theirs).
        let [checker, bricks, ice, crate_image, fence_image, water_image] =
            std::array::from_fn(|i| {
                let name = TEXTURE_FILES[i].trim_end_matches(".png");
                texture::upload(
                    device,
                    queue,
                    &format!("{name} texture"),
                    &assets.textures[i],
                )
            });
        let white =
            texture::Mipmapped::new(image::RgbaImage::from_pixel(1, 1, image::Rgba([255; 4])));
        let white = texture::upload(device, queue, "white texture", &white);

        let object = |name: &'static str,
                      mesh: &MeshData,
                      world: Mat4,
                      material: Material,
                      view: &wgpu::TextureView,
                      repeat: Vec2| {
            let make = |label: String, world: Mat4| {
                let uniform = ObjectUniform {
                    world,
                    normal_matrix: normal_matrix(world),
                    ambient: material.ambient.extend(1.0),
                    diffuse: material.diffuse.extend(material.alpha),
                    specular: material.specular.extend(material.shininess),
                    params: Vec4::new(repeat.x, repeat.y, material.alpha_cutoff, 0.0),
                };
                let (buffer, group) =
                    object_bind_group(device, &object_layout, &sampler, view, &label, &uniform);
                (group, (buffer, Cell::new(uniform)))
            };
            let (bind_group, normal) = make(name.to_string(), world);
            let (reflected, mirrored) = make(format!("reflected {name}"), reflected_world(world));
            let (min, max) = mesh.bounds();
            Drawable {
                name,
                mesh: GpuMesh::new(device, name, mesh),
                bind_group,
                reflected,
                uniforms: [normal, mirrored],
                texture: view.clone(),
                local_centre: (min + max) / 2.0,
            }
        };

        let floor = object(
            "floor",
            &floor_mesh(),
            Mat4::IDENTITY,
            ROOM_MATERIAL,
            &checker,
            Vec2::ONE,
        );
        let wall = object(
            "wall",
            &wall_mesh(),
            Mat4::IDENTITY,
            ROOM_MATERIAL,
            &bricks,
            Vec2::ONE,
        );
        let mirror = object(
            "mirror",
            &mirror_mesh(),
            Mat4::IDENTITY,
            MIRROR_MATERIAL,
            &ice,
            Vec2::ONE,
        );
        let crate_box = object(
            "crate",
            &MeshData::cuboid(Vec3::splat(CRATE_SIZE)),
            Mat4::from_translation(CRATE_CENTRE),
            ROOM_MATERIAL,
            &crate_image,
            Vec2::ONE,
        );
        let skull = object(
            "skull",
            skull_mesh,
            skull_world(),
            SKULL_MATERIAL,
            &white,
            Vec2::ONE,
        );
        let fence_box = object(
            "wire-fence crate",
            &MeshData::cuboid(Vec3::splat(FENCE_SIZE)),
            Mat4::from_translation(FENCE_CENTRE),
            FENCE_MATERIAL,
            &fence_image,
            Vec2::ONE,
        );
        let water_size = WATER_MAX - WATER_MIN;
        let mut water_mesh = MeshData::default();
        water_mesh.add_quad(
            Vec3::new(WATER_MIN.x, WATER_MIN.y, WATER_MAX.z),
            Vec3::X * water_size.x,
            -Vec3::Z * water_size.z,
            Vec2::new(water_size.x, water_size.z) / 2.0,
        );
        let water = object(
            "water",
            &water_mesh,
            Mat4::IDENTITY,
            WATER_MATERIAL,
            &water_image,
            Vec2::ONE,
        );
        let floor_mirror = object(
            "floor mirror",
            &floor_mirror_mesh(),
            Mat4::IDENTITY,
            FLOOR_MIRROR_MATERIAL,
            &ice,
            Vec2::ONE,
        );
        let floor_around_mirror = object(
            "floor around the mirror",
            &floor_around_mirror_mesh(),
            Mat4::IDENTITY,
            ROOM_MATERIAL,
            &checker,
            Vec2::ONE,
        );
        let depth_view = crate::gpu::views::DepthViewPipelines::supported(adapter)
            .then(|| crate::gpu::views::DepthViewPipelines::new(device, color_format, (NEAR, FAR)));
        Self {
            color_format,
            floor,
            wall,
            mirror,
            crate_box,
            skull,
            fence_box,
            water,
            floor_mirror,
            floor_around_mirror,
            frame,
            reflected_frame,
            pipeline_layout,
            frame_layout,
            object_layout,
            sampler,
            shader,
            clip_distances_shader,
            depth_view,
            stencil_view: crate::gpu::views::StencilViewPipeline::new(device, color_format),
            blit: crate::gpu::views::Blit::new(device, color_format),
            pipelines: Pipelines::default(),
        }
    }

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
                format!("{}\n{extra}", include_str!("../shaders/scene.wgsl")).into(),
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

    /// The object placed by another world matrix (a mirror image in another plane, say), as a bind
    /// group of its own: draw it with [`Drawable::draw_placed`].
    pub fn placed(&self, device: &wgpu::Device, object: &Drawable, world: Mat4) -> Placed {
        self.placed_as(device, object, world, None)
    }

    /// [`Scene::placed`], made of another material: a shadow is the skull in black at 50%. A world
    /// matrix that flattens the object (a shadow matrix, determinant 0) has no normals to carry:
    /// they are left as they are, and the material should not need them.
    pub fn placed_as(
        &self,
        device: &wgpu::Device,
        object: &Drawable,
        world: Mat4,
        material: Option<Material>,
    ) -> Placed {
        let own = object.uniforms[0].1.get();
        let normal_matrix = match world.determinant().abs() > 1e-6 {
            true => normal_matrix(world),
            false => Mat4::IDENTITY,
        };
        let uniform = ObjectUniform {
            world,
            normal_matrix,
            ambient: material.map_or(own.ambient, |m| m.ambient.extend(1.0)),
            diffuse: material.map_or(own.diffuse, |m| m.diffuse.extend(m.alpha)),
            specular: material.map_or(own.specular, |m| m.specular.extend(m.shininess)),
            ..own
        };
        let label = format!("{} placed", object.name);
        let (layout, sampler) = (&self.object_layout, &self.sampler);
        let (_, bind_group) =
            object_bind_group(device, layout, sampler, &object.texture, &label, &uniform);
        Placed {
            object: object.name,
            bind_group,
        }
    }

    /// Draws the room's solid objects — floor, wall, crate and skull, all but the mirror — with the
    /// pipeline already set. The mirror lessons start every frame with it.
    pub fn draw_room(&self, pass: &mut Pass<'_, '_>) {
        for object in [&self.floor, &self.wall, &self.crate_box, &self.skull] {
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

/// The plane of the mirror: z = 0, facing the room (+z).
pub fn mirror_plane() -> Plane {
    Plane::new(Vec3::Z, 0.0)
}

/// The reflection in the mirror's plane.
pub fn mirror_reflection() -> Mat4 {
    reflection(mirror_plane())
}

// ANCHOR: reflected_world
/// The world matrix of an object's mirror image: first its own world matrix, then the reflection.
/// (Column vectors: R * world. DirectXMath's row vectors write it world * R.)
pub fn reflected_world(world: Mat4) -> Mat4 {
    mirror_reflection() * world
}
// ANCHOR_END: reflected_world

// ANCHOR: reflected_lights
/// The lights as the mirror world sees them: each one reflected too ([`Light::reflected`]). Without
/// this the mirror image would be lit from the wrong side (a key light from the front right would
/// light the image's front right, which faces away from the light).
pub fn reflected_lights() -> [Light; 3] {
    LIGHTS.map(|light| light.reflected(mirror_reflection()))
}
// ANCHOR_END: reflected_lights

/// Where the skull stands: turned towards the camera's side, so the mirror shows its other side.
pub fn skull_world() -> Mat4 {
    Mat4::from_translation(SKULL_CENTRE)
        * Mat4::from_rotation_y(SKULL_YAW_DEGREES.to_radians())
        * Mat4::from_scale(Vec3::splat(SKULL_SIZE))
}

/// The floor: one 4 m checker tile repeated.
fn floor_mesh() -> MeshData {
    let mut mesh = MeshData::default();
    let width = 2.0 * WALL_HALF_WIDTH;
    mesh.add_quad(
        Vec3::new(-WALL_HALF_WIDTH, 0.0, FLOOR_DEPTH),
        Vec3::X * width,
        -Vec3::Z * FLOOR_DEPTH,
        Vec2::new(width, FLOOR_DEPTH) / 4.0,
    );
    mesh
}

/// The wall: three solid blocks around the mirror's opening, WALL_THICKNESS deep behind the plane
/// z = 0, so it has a back a camera behind it can see. Bricks are laid by position, so the courses
/// line up across the blocks.
fn wall_mesh() -> MeshData {
    let mut mesh = MeshData::default();
    let (w, h, t) = (WALL_HALF_WIDTH, WALL_HEIGHT, WALL_THICKNESS);
    let (a, b) = (MIRROR_MIN, MIRROR_MAX);
    // (left, bottom) and (right, top) of each block's face.
    for (min, max) in [
        (Vec2::new(-w, 0.0), Vec2::new(a.x, b.y)),
        (Vec2::new(b.x, 0.0), Vec2::new(w, b.y)),
        (Vec2::new(-w, b.y), Vec2::new(w, h)),
    ] {
        let size = (max - min).extend(t);
        let centre = ((min + max) / 2.0).extend(-t / 2.0);
        mesh.append(MeshData::cuboid(size).translated(centre));
    }
    // One brick texture per 2 m, projected along each face's normal.
    for vertex in &mut mesh.vertices {
        let [x, y, z] = vertex.position;
        let n = Vec3::from(vertex.normal).abs();
        vertex.uv = if n.z > 0.5 {
            [x / 2.0, -y / 2.0]
        } else if n.x > 0.5 {
            [z / 2.0, -y / 2.0]
        } else {
            [x / 2.0, z / 2.0]
        };
    }
    mesh
}

/// Lesson 8's stone mirror: one slab of the floor, facing up.
fn floor_mirror_mesh() -> MeshData {
    let mut mesh = MeshData::default();
    let size = FLOOR_MIRROR_MAX - FLOOR_MIRROR_MIN;
    let near_left = Vec3::new(FLOOR_MIRROR_MIN.x, 0.0, FLOOR_MIRROR_MAX.z);
    mesh.add_quad(
        near_left,
        Vec3::X * size.x,
        -Vec3::Z * size.z,
        Vec2::new(2.0, 1.25),
    );
    mesh
}

/// The floor with a hole where lesson 8's stone mirror lies (no two surfaces in one plane, so no
/// z-fighting): four strips around it, the checker tiles laid by position so they line up.
fn floor_around_mirror_mesh() -> MeshData {
    let (w, depth) = (WALL_HALF_WIDTH, FLOOR_DEPTH);
    let (a, b) = (FLOOR_MIRROR_MIN, FLOOR_MIRROR_MAX);
    let mut mesh = MeshData::default();
    // (x0, z0) to (x1, z1) of each strip: behind, in front of, left of and right of the slab.
    for (x0, z0, x1, z1) in [
        (-w, 0.0, w, a.z),
        (-w, b.z, w, depth),
        (-w, a.z, a.x, b.z),
        (b.x, a.z, w, b.z),
    ] {
        mesh.add_quad(
            Vec3::new(x0, 0.0, z1),
            Vec3::X * (x1 - x0),
            -Vec3::Z * (z1 - z0),
            Vec2::new(x1 - x0, z1 - z0) / 4.0,
        );
    }
    // One 4 m tile, by position, as the whole floor lays it.
    for vertex in &mut mesh.vertices {
        let [x, _, z] = vertex.position;
        vertex.uv = [(x + w) / 4.0, z / 4.0];
    }
    mesh
}

fn mirror_mesh() -> MeshData {
    let mut mesh = MeshData::default();
    let size = MIRROR_MAX - MIRROR_MIN;
    mesh.add_quad(MIRROR_MIN, Vec3::X * size.x, Vec3::Y * size.y, Vec2::ONE);
    mesh
}
