//! The room's objects on the GPU: a drawable (a mesh, where it stands, its material and texture,
//! and its mirror image in the wall mirror), an object placed by another world matrix, and the bind
//! group (group 1) and sampler they are drawn with.

use std::cell::Cell;

use glam::{Mat4, Vec2, Vec3, Vec4};
use wgpu::util::DeviceExt;

use super::Scene;
use super::materials::Material;
use super::mirror::{mirror_reflection, reflected_world};
use crate::gpu::pass::Pass;
use crate::math::reflect::normal_matrix;
use crate::room::mesh::{GpuMesh, MeshData};

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

    /// Draws another mesh as this object, with its transform, material and texture: a lesson's
    /// variant of the object's own mesh (the skull with a hole in it).
    pub fn draw_mesh(&self, pass: &mut Pass<'_, '_>, mesh: &GpuMesh) {
        pass.set_bind_group(1, &self.bind_group, &[]);
        pass.object(self.name);
        mesh.draw(pass);
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

/// The layout of an object's bind group (group 1): its uniforms, texture and sampler.
pub(super) fn object_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("object bind group layout"),
        entries: &[
            crate::gpu::uniform_entry(0),
            crate::gpu::texture_entry(1),
            crate::gpu::sampler_entry(2),
        ],
    })
}

/// The sampler of every object's texture: repeating, trilinear, and anisotropic unless
/// `anisotropy` is 1.
pub(super) fn repeating_sampler(device: &wgpu::Device, anisotropy: u16) -> wgpu::Sampler {
    device.create_sampler(&wgpu::SamplerDescriptor {
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
    })
}

/// What the room's objects are made with: the device, and the bind group layout and sampler
/// every object shares.
pub(super) struct DrawableMaker<'a> {
    pub(super) device: &'a wgpu::Device,
    pub(super) layout: &'a wgpu::BindGroupLayout,
    pub(super) sampler: &'a wgpu::Sampler,
}

impl DrawableMaker<'_> {
    /// The object `name`: `mesh` standing at `world`, made of `material` with the texture `view`
    /// repeated `repeat` times, and its mirror image in the wall mirror.
    pub(super) fn drawable(
        &self,
        name: &'static str,
        mesh: &MeshData,
        world: Mat4,
        material: Material,
        view: &wgpu::TextureView,
        repeat: Vec2,
    ) -> Drawable {
        let device = self.device;
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
                object_bind_group(device, self.layout, self.sampler, view, &label, &uniform);
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

impl Scene {
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
}
