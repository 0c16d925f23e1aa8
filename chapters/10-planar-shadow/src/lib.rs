//! Lesson 10: the planar shadow.
//!
//! The skull casts a shadow on the floor: the skull itself, flattened onto the floor by the shadow
//! matrix, drawn black at 50%. Where the flattened skull overlaps itself the shadow would darken
//! twice; the stencil buffer lets each pixel be darkened once. The key light can be directional, a
//! point or a spot, and the wall mirror shows the shadow too — the mirror's mark and the shadow's
//! bit sharing one stencil buffer through masks.

use workbook::glam::{Mat4, Vec3};
use workbook::gpu::states;
use workbook::lesson::knobs;
use workbook::math::reflect::Plane;
use workbook::math::shadow::{LightSource, shadow_matrix};
use workbook::room::camera::Camera;
use workbook::room::mirror_world::MirrorWorld;
use workbook::room::scene::{
    Drawable, FrameBinding, LIGHTS, Light, Placed, SHADOW_MATERIAL, SKULL_CENTRE, Spot,
    mirror_plane,
};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct PlanarShadow {
    lights: [Light; 3],
    room_frame: FrameBinding,
    draw_room: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
    draw_reflection: wgpu::RenderPipeline,
    draw_reflected_shadow: wgpu::RenderPipeline,
    draw_glass: wgpu::RenderPipeline,
    pub draw_shadow: wgpu::RenderPipeline,
    mirror_world: MirrorWorld,
    shadow: Placed,
    reflected_shadow: Option<Placed>,
}

/// The glass's alpha: a quarter glass, three quarters reflection.
const GLASS_ALPHA: f32 = 0.25;

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "no-double-blend",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether the stencil lets each pixel of the shadow be darkened once (NO_DOUBLE_BLEND)",
    },
    Knob {
        name: "light",
        values: &["directional", "point", "spot"],
        default: "directional",
        meaning: "the key light: Luna's directional light, a point light, or a spot light on the skull",
    },
    Knob {
        name: "reflect-shadow",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether the wall mirror shows the shadow too",
    },
    Knob {
        name: "masks",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether the glass reads only the mark's bit (read mask 0b01), not the shadow's too",
    },
    Knob {
        name: "surface",
        values: &["floor", "wall"],
        default: "floor",
        meaning: "where the shadow falls: on the floor, or on the wall (the key light then comes from low in front)",
    },
    Knob {
        name: "lift",
        values: &["offset", "depth-bias", "none"],
        default: "offset",
        meaning: "how the shadow is kept off the floor's depth: 1 cm up, a depth bias, or not (z-fighting)",
    },
];
// ANCHOR_END: knobs

// ANCHOR: lights
/// The key light the `light` knob chooses, for a shadow on the floor or the wall. For the floor the
/// point and the spot stand where Luna's directional light comes from, 4.5 m from the skull; for the
/// wall all three come from low in front and to the right, so that the shadow falls on the bricks
/// left of the mirror. The spot aims at the skull with a 25° cone.
pub fn key_light(name: &str, surface: &str) -> Light {
    let offset = match surface {
        "wall" => Vec3::new(3.5, 0.6, 3.5),
        _ => Vec3::new(2.6, 2.6, 2.6),
    };
    let from = SKULL_CENTRE + offset;
    let source = match (name, surface) {
        ("directional", "wall") => LightSource::Directional {
            direction: -offset.normalize(),
        },
        ("directional", _) => return LIGHTS[0],
        _ => LightSource::Point { position: from },
    };
    let spot = (name == "spot").then(|| Spot {
        axis: (SKULL_CENTRE - from).normalize(),
        cos_cutoff: 25f32.to_radians().cos(),
    });
    Light {
        source,
        spot,
        diffuse: Vec3::splat(1.0),
        specular: Vec3::splat(0.8),
        ..LIGHTS[0]
    }
}
// ANCHOR_END: lights

// ANCHOR: shadow
/// The plane the shadow falls on: the floor, y = 0, facing up, or the wall's face, z = 0.
pub fn shadow_plane(surface: &str) -> Plane {
    match surface {
        "wall" => mirror_plane(),
        _ => Plane::new(Vec3::Y, 0.0),
    }
}

/// Where the shadow is drawn: the skull flattened onto the plane along the key light's rays, then
/// lifted 1 cm off it, along its normal, so that it lies in front of the surface it darkens (unless
/// `lift` is not `offset`).
pub fn shadow_world(skull: Mat4, light: &Light, plane: Plane, lift: &str) -> Mat4 {
    let lift = if lift == "offset" { 0.01 } else { 0.0 };
    Mat4::from_translation(plane.normal * lift) * shadow_matrix(plane, light.source) * skull
}
// ANCHOR_END: shadow

// ANCHOR: recipes
/// The shadow's recipe: NO_DOUBLE_BLEND, or SHADOW alone (every layer darkens); with a depth bias
/// instead of the 1 cm offset if `lift` says so.
pub fn draw_shadow(knobs: &Knobs) -> Recipe {
    let recipe = match knobs.is_on("no-double-blend") {
        true => states::NO_DOUBLE_BLEND,
        false => states::SHADOW,
    };
    with_lift(recipe, knobs)
}

/// The shadow in the mirror: the masked REFLECTED_NO_DOUBLE_BLEND, or SHADOW where the mark is.
pub fn draw_reflected_shadow(knobs: &Knobs) -> Recipe {
    let recipe = match knobs.is_on("no-double-blend") {
        true => states::REFLECTED_NO_DOUBLE_BLEND,
        false => Recipe {
            stencil: states::DRAW_REFLECTION.stencil,
            ..states::SHADOW
        },
    };
    with_lift(recipe, knobs)
}

/// The glass over the mark: reading the mark's bit only, or (masks=off) the whole value, which the
/// shadow's bit has changed.
pub fn draw_glass(knobs: &Knobs) -> Recipe {
    match knobs.is_on("masks") {
        true => states::BLEND_OVER_MARK_BIT,
        false => states::BLEND_OVER_MARK,
    }
}

/// A depth bias pulls the shadow's depth towards the camera instead of moving the shadow up: a
/// constant number of the depth format's steps plus a multiple of the slope.
fn with_lift(recipe: Recipe, knobs: &Knobs) -> Recipe {
    if knobs.get("lift") != "depth-bias" {
        return recipe;
    }
    Recipe {
        depth_bias: wgpu::DepthBiasState {
            constant: -64,
            slope_scale: -2.0,
            clamp: 0.0,
        },
        ..recipe
    }
}
// ANCHOR_END: recipes

impl Lesson for PlanarShadow {
    const NAME: &'static str = "planar-shadow";
    const TITLE: &'static str = "Lesson 10: the planar shadow";
    const KNOBS: &'static [Knob] = KNOBS;
    /// From above, where the shadow falls between the skull and the crate.
    const CAMERA: Camera = Camera {
        yaw: 10.0,
        pitch: 60.0,
        distance: 9.0,
    };

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let device = &gpu.device;
        // Clearer glass than lesson 6's, so that the shadow's image shows through it.
        scene.mirror.set_alpha(&gpu.queue, GLASS_ALPHA);
        let surface = knobs.get("surface");
        let key = key_light(knobs.get("light"), surface);
        let lights = [key, LIGHTS[1], LIGHTS[2]];
        let plane = shadow_plane(surface);
        let world = shadow_world(scene.skull.world(), &key, plane, knobs.get("lift"));
        let shadow = scene.placed_as(device, &scene.skull, world, Some(SHADOW_MATERIAL));
        // The mirror shows the floor the shadow falls on (and the crate), not only the skull: the
        // shadow's image must lie on something for the eye to see it darken.
        let mut mirror_world = MirrorWorld::new(gpu, scene, mirror_plane(), &reflected(scene));
        mirror_world.set_room_lights(lights);
        // The shadow's own mirror image: the shadow (made by the real light) reflected. (A shadow
        // on the wall lies in the mirror's own plane: its image is itself.)
        let reflect = knobs.is_on("reflect-shadow") && surface == "floor";
        let reflected_shadow = reflect.then(|| {
            let image = mirror_world.reflection * world;
            scene.placed_as(device, &scene.skull, image, Some(SHADOW_MATERIAL))
        });
        // Pipelines that shade by point and spot lights too.
        let pipeline = |recipe: &Recipe| scene.pipeline_lit_by(device, recipe, &lights);
        Ok(Self {
            lights,
            room_frame: scene.frame_binding(device, "lit room"),
            draw_room: pipeline(&states::OPAQUE),
            mark_mirror: pipeline(&states::MARK_MIRROR),
            draw_reflection: pipeline(&states::FRONT_CLOCKWISE),
            draw_reflected_shadow: pipeline(&draw_reflected_shadow(knobs)),
            draw_glass: pipeline(&draw_glass(knobs)),
            draw_shadow: pipeline(&draw_shadow(knobs)),
            mirror_world,
            shadow,
            reflected_shadow,
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // This lesson's lights for the room, and reflected for the mirror world.
        let queue = &frame.gpu.queue;
        self.room_frame
            .write(queue, &frame.view, &self.lights, Default::default());
        self.mirror_world.update(frame, false);
        frame.clear();

        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            self.room_frame.bind(pass);
            for object in scene.solid_objects() {
                object.draw(pass);
            }
        });
        frame.step("mark the mirror", |pass| {
            pass.set_pipeline(&self.mark_mirror);
            pass.set_stencil_reference(1);
            scene.mirror.draw(pass);
        });
        frame.step("draw the reflected room", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            self.mirror_world.bind(pass);
            for object in reflected(scene) {
                self.mirror_world.draw(pass, object);
            }
        });

        // The shadow in the mirror: where the mark (bit 0) is set and the shadow's bit (bit 1) is
        // not; each pixel then sets bit 1, so it is darkened once.
        if let Some(reflected_shadow) = &self.reflected_shadow {
            frame.step("draw the reflected shadow", |pass| {
                pass.set_pipeline(&self.draw_reflected_shadow);
                pass.set_stencil_reference(1);
                self.mirror_world.bind(pass);
                scene.skull.draw_placed(pass, reflected_shadow);
            });
        }

        // The glass over the mirror, where the mark's bit is set.
        frame.step("draw the glass", |pass| {
            pass.set_pipeline(&self.draw_glass);
            pass.set_stencil_reference(1);
            self.room_frame.bind(pass);
            scene.mirror.draw(pass);
        });

        // The shadow on the floor, NO_DOUBLE_BLEND: where the stencil is 0, which it then
        // increments.
        frame.step("draw the shadow", |pass| {
            pass.set_pipeline(&self.draw_shadow);
            pass.set_stencil_reference(0);
            self.room_frame.bind(pass);
            scene.skull.draw_placed(pass, &self.shadow);
        });
    }
    // ANCHOR_END: render
}

/// What the wall mirror shows: the floor, the crate and the skull in front of it.
fn reflected(scene: &Scene) -> [&Drawable; 3] {
    [&scene.floor, &scene.crate_box, &scene.skull]
}
