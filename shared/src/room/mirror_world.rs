//! A mirror world: the room's objects reflected in a plane, lit by the lights reflected in it, and
//! clipped to the far side of the glass — what any mirror but the wall's shows (lesson 8's floor).
//! The wall mirror of lessons 4-7 has the same thing built into every [`Drawable`].

use glam::Mat4;

use crate::Gpu;
use crate::gpu::pass::Pass;
use crate::math::clip::oblique_projection;
use crate::math::reflect::{Plane, reflection};
use crate::room::camera::View;
use crate::room::scene::{Drawable, FrameBinding, LIGHTS, Light, Placed, Scene};

pub struct MirrorWorld {
    /// The mirror's plane, its front facing the room (where the camera is).
    pub plane: Plane,
    /// The reflection in that plane (or several composed, for a mirror seen in a mirror).
    pub reflection: Mat4,
    frame: FrameBinding,
    images: Vec<Placed>,
    /// The lights of the room it mirrors (the scene's own unless a lesson says otherwise).
    room_lights: [Light; 3],
}

impl MirrorWorld {
    /// The mirror images of `objects` in `plane`, placed where they stand now.
    pub fn new(gpu: &Gpu, scene: &Scene, plane: Plane, objects: &[&Drawable]) -> Self {
        Self::seen_through(gpu, scene, (reflection(plane), plane), objects)
    }

    /// The mirror images of `objects` under any `reflection` — several composed, for a mirror seen
    /// in a mirror (lesson 11) — seen through the mirror in plane `portal` (in the world, its front
    /// towards the viewer), which clips them.
    pub fn seen_through(
        gpu: &Gpu,
        scene: &Scene,
        (reflection, portal): (Mat4, Plane),
        objects: &[&Drawable],
    ) -> Self {
        let plane = portal;
        let device = &gpu.device;
        let images = objects
            .iter()
            .map(|object| scene.placed(device, object, reflection * object.world()))
            .collect();
        Self {
            plane,
            reflection,
            frame: scene.frame_binding(device, "mirror world frame"),
            images,
            room_lights: LIGHTS,
        }
    }

    /// Lights the room with other lights than the scene's (the mirror world reflects them).
    pub fn set_room_lights(&mut self, lights: [Light; 3]) {
        self.room_lights = lights;
    }

    /// The lights as the mirror world sees them: each one reflected.
    pub fn lights(&self) -> [Light; 3] {
        self.room_lights
            .map(|light| light.reflected(self.reflection))
    }

    /// The side of the mirror's plane the mirror world lies on, as a plane whose front it is: what
    /// clipping keeps.
    pub fn kept_side(&self) -> Plane {
        self.plane.flipped()
    }

    // ANCHOR: view
    /// What the camera sees the mirror world through: its own view, or with `oblique` the same view
    /// with the projection's near plane moved onto the mirror's plane, so that the GPU's own near
    /// clipping throws away whatever lies in front of the glass.
    pub fn view(&self, view: &View, oblique: bool) -> View {
        if !oblique {
            return *view;
        }
        // The plane in view space: planes go through a transform by its inverse transpose.
        let in_view_space = self.kept_side().transformed(view.view);
        View {
            projection: oblique_projection(view.projection, in_view_space),
            ..*view
        }
    }
    // ANCHOR_END: view

    /// Writes the mirrored camera of `view` (oblique or not), the reflected lights and the clip
    /// plane (a lesson calls `update` with its frame: see [`crate::lesson::mirror`]).
    pub fn write(&self, queue: &wgpu::Queue, view: &View, oblique: bool) {
        let view = self.view(view, oblique);
        let clip_plane = self.kept_side().as_vec4();
        self.frame.write(queue, &view, &self.lights(), clip_plane);
    }

    /// Binds the mirror world's camera and lights (group 0).
    pub fn bind(&self, pass: &mut Pass<'_, '_>) {
        self.frame.bind(pass);
    }

    /// Draws the mirror image of `object` (one of those the world was made with).
    pub fn draw(&self, pass: &mut Pass<'_, '_>, object: &Drawable) {
        let image = self
            .images
            .iter()
            .find(|image| image.object() == object.name);
        object.draw_placed(pass, image.expect("an object of this mirror world"));
    }
}
