//! Lesson 8: the floor mirror.
//!
//! Part of the floor is polished stone: a mirror in the plane y = 0, and the wall, the crate and the
//! skull are reflected in it — lesson 3-6's stencil recipe in another plane. Two things the wall
//! mirror never showed: other ways people draw a reflection (SPE's first version; a blog's depth
//! `Always`), and an object that crosses the mirror's plane, whose reflection must be clipped there.

use anyhow::bail;
use workbook::glam::{Mat4, Vec3};
use workbook::gpu::states::{self, Clip};
use workbook::lesson::mirror::ResetDepth;
use workbook::math::reflect::Plane;
use workbook::room::camera::Camera;
use workbook::room::mirror_world::MirrorWorld;
use workbook::room::scene::{Drawable, skull_world};
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct FloorMirror {
    technique: Technique,
    draw_room: wgpu::RenderPipeline,
    pub mark_mirror: wgpu::RenderPipeline,
    reset_depth: ResetDepth,
    draw_reflection: wgpu::RenderPipeline,
    draw_stone: wgpu::RenderPipeline,
    mirror_world: MirrorWorld,
    oblique: bool,
    /// Whether the skull goes through the floor (`sink` above 0).
    sunk: bool,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "recipe",
        values: &["stencil", "spe", "always"],
        default: "stencil",
        meaning: "the mark and Equal (ours), SPE's no stencil and no depth test, or a blog's depth Always",
    },
    SINK,
    Knob {
        name: "clip",
        values: &["off", "clip-distances", "discard", "oblique"],
        default: "discard",
        meaning: "how the reflection is cut at the mirror's plane: not, by the rasterizer, the fragment shader, or the projection",
    },
];
// ANCHOR_END: knobs

/// How far the skull is lowered (lesson 9 has it too).
pub const SINK: Knob = Knob {
    name: "sink",
    values: &["0", "1", "1.5", "2"],
    default: "0",
    meaning: "how far the skull is lowered, in metres: from 1 on its jaw goes through the floor",
};

/// The three ways of the `recipe` knob.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Technique {
    Stencil,
    Spe,
    Always,
}

// ANCHOR: plane
/// The floor mirror's plane: y = 0, its front facing up, into the room.
pub fn floor_plane() -> Plane {
    Plane::new(Vec3::Y, 0.0)
}
// ANCHOR_END: plane

// ANCHOR: recipes
/// The reflection's recipe: FRONT_CLOCKWISE as on the wall (a reflection flips the winding), SPE's,
/// or the blog's; each clipped at the plane as the `clip` knob says.
pub fn draw_reflection(knobs: &Knobs) -> Recipe {
    let recipe = match knobs.get("recipe") {
        "spe" => states::SPE_REFLECTION,
        "always" => states::ALWAYS_REFLECTION,
        _ => states::FRONT_CLOCKWISE,
    };
    let clip = match knobs.get("clip") {
        "clip-distances" => Clip::Distances,
        "discard" => Clip::Discard,
        _ => Clip::None,
    };
    Recipe { clip, ..recipe }
}
// ANCHOR_END: recipes

// ANCHOR: sink
/// Lowers the skull by the `sink` knob's metres: from 1 m on, its jaw goes through the floor.
pub fn sink_skull(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<()> {
    let sink: f32 = knobs.get("sink").parse()?;
    let lowered = Mat4::from_translation(Vec3::new(0.0, -sink, 0.0)) * skull_world();
    scene.skull.set_world(&gpu.queue, lowered);
    Ok(())
}
// ANCHOR_END: sink

/// SPE's constant alpha: the reflection is mixed in at 40%.
const SPE_ALPHA: f64 = 0.4;

impl Lesson for FloorMirror {
    const NAME: &'static str = "floor-mirror";
    const TITLE: &'static str = "Lesson 8: the floor mirror";
    const KNOBS: &'static [Knob] = KNOBS;
    /// Higher than the other lessons' camera, looking down on the floor.
    const CAMERA: Camera = Camera {
        yaw: 15.0,
        pitch: 28.0,
        distance: 12.0,
    };

    fn unavailable(scene: &Scene, knob: &str, value: &str) -> Option<&'static str> {
        let needs_clip_distances = (knob, value) == ("clip", "clip-distances");
        (needs_clip_distances && !scene.has_clip_distances())
            .then_some("this GPU has no user clip distances (wgpu's Features::CLIP_DISTANCES)")
    }

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        if let Some(reason) = Self::unavailable(scene, "clip", knobs.get("clip")) {
            bail!("{reason}: use --set clip=discard or --set clip=oblique");
        }
        let technique = match knobs.get("recipe") {
            "spe" => Technique::Spe,
            "always" => Technique::Always,
            _ => Technique::Stencil,
        };
        sink_skull(gpu, scene, knobs)?;
        let pipeline = |recipe: &Recipe| scene.pipeline(&gpu.device, recipe);
        Ok(Self {
            technique,
            draw_room: pipeline(&states::OPAQUE),
            mark_mirror: pipeline(&states::MARK_MIRROR),
            reset_depth: ResetDepth::new(gpu, scene),
            draw_reflection: pipeline(&draw_reflection(knobs)),
            draw_stone: pipeline(&states::BLEND_OVER_MARK),
            mirror_world: MirrorWorld::new(gpu, scene, floor_plane(), &reflected(scene)),
            oblique: knobs.get("clip") == "oblique",
            sunk: knobs.get("sink") != "0",
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // The mirror world's camera for this frame: the reflected lights, the clip plane, and with
        // clip=oblique the projection whose near plane is the floor.
        self.mirror_world.update(frame, self.oblique);
        frame.clear();

        // The room, with a hole in the floor where the stone is; SPE draws the stone here too, as
        // its floor, opaque.
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            for object in room(scene) {
                object.draw(pass);
            }
            if self.technique == Technique::Spe {
                scene.floor_mirror.draw(pass);
            }
        });

        // Mark the stone's visible pixels with 1, as lesson 3 marked the wall mirror. (SPE has no
        // stencil.)
        if self.technique != Technique::Spe {
            frame.step("mark the floor mirror", |pass| {
                pass.set_pipeline(&self.mark_mirror);
                pass.set_stencil_reference(1);
                scene.floor_mirror.draw(pass);
            });
        }
        // With the skull sunk through the floor, the room drew it *under* the stone: put the
        // mark's depth back to the far plane, so that it cannot hide the mirror world.
        if self.technique != Technique::Spe && self.sunk {
            frame.step("reset the depth in the mark", |pass| {
                self.reset_depth.draw(pass, 1);
            });
        }

        // The mirror world: the room's objects reflected in the floor, lit by reflected lights,
        // with the recipe the knobs chose — where the mark is, or (SPE) everywhere at 40%.
        frame.step("draw the reflection", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            if self.technique == Technique::Spe {
                let a = SPE_ALPHA;
                pass.set_blend_constant(wgpu::Color {
                    r: a,
                    g: a,
                    b: a,
                    a,
                });
            }
            self.mirror_world.bind(pass);
            for object in reflected(scene) {
                self.mirror_world.draw(pass, object);
            }
        });

        // The polished stone over its reflection: 60% stone, 40% reflection, where the mark is.
        if self.technique != Technique::Spe {
            frame.step("draw the stone", |pass| {
                pass.set_pipeline(&self.draw_stone);
                pass.set_stencil_reference(1);
                scene.floor_mirror.draw(pass);
            });
        }
    }
    // ANCHOR_END: render
}

/// The room of this lesson: the floor around the stone, the wall with its (unlit) mirror, the crate
/// and the skull.
pub fn room(scene: &Scene) -> [&Drawable; 5] {
    [
        &scene.floor_around_mirror,
        &scene.wall,
        &scene.mirror,
        &scene.crate_box,
        &scene.skull,
    ]
}

/// What the floor mirror shows, nearest first: with depth `Always` the last drawn covers the rest.
pub fn reflected(scene: &Scene) -> [&Drawable; 4] {
    [&scene.skull, &scene.crate_box, &scene.wall, &scene.mirror]
}
