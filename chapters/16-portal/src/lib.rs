//! Lesson 16: the portal.
//!
//! The mirror's ice becomes a doorway into another room: this room moved 3 m back and lit by its
//! own evening light. Through that room's doorway the next one shows, moved again, and so on. Room k is drawn where the stencil holds k — lesson 11's levels, with a move
//! where lesson 11 had a reflection: a move keeps the winding, so every room is drawn as the first.
//! Each far room is clipped at the doorway it is seen through, and the depth behind each doorway is
//! reset before the room behind it is drawn.

use workbook::glam::{Mat4, Vec3};
use workbook::gpu::states::{self, Clip};
use workbook::lesson::knobs;
use workbook::lesson::mirror::ResetDepth;
use workbook::math::reflect::Plane;
use workbook::math::screen::ScreenRect;
use workbook::room::camera::Camera;
use workbook::room::mirror_world::MirrorWorld;
use workbook::room::scene::{LIGHTS, Light, MIRROR_MAX, MIRROR_MIN, Placed, mirror_plane};
use workbook::wgpu::{self, CompareFunction, StencilOperation};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "depth",
        values: &["0", "1", "2", "3", "4"],
        default: "3",
        meaning: "how many rooms behind the doorway: 0 is this room alone, 1 the room behind it, 2 the room behind that",
    },
    Knob {
        name: "clip",
        values: &["discard", "oblique", "off"],
        default: "discard",
        meaning: "how a far room is cut at the doorway it is seen through, so that what of it stands on this side does not show: fragments discarded, the near plane moved onto the doorway (lesson 8's oblique projection), or not at all",
    },
    Knob {
        name: "clear-behind",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether, behind each doorway, the depth is reset to the far plane and the colour cleared to the sky before the room behind it is drawn",
    },
    Knob {
        name: "order",
        values: &["room-first", "doorway-first"],
        default: "room-first",
        meaning: "mark a doorway after the room it stands in (what stands in front of it hides it), or before",
    },
];
// ANCHOR_END: knobs

/// The deepest room the knob allows.
pub const MAX_DEPTH: usize = 4;

/// The steps of each room, by name (step names are written once, here).
const DRAW_ROOM_STEPS: [&str; MAX_DEPTH + 1] = [
    "draw the room",
    "draw room 1",
    "draw room 2",
    "draw room 3",
    "draw room 4",
];
const MARK_DOORWAY_STEPS: [&str; MAX_DEPTH] = [
    "mark doorway 1",
    "mark doorway 2",
    "mark doorway 3",
    "mark doorway 4",
];
const CLEAR_BEHIND_STEPS: [&str; MAX_DEPTH] = [
    "clear behind doorway 1",
    "clear behind doorway 2",
    "clear behind doorway 3",
    "clear behind doorway 4",
];

// ANCHOR: move
/// How far each room lies behind the one whose doorway shows it.
pub const ROOM_SPACING: f32 = 3.0;

/// The portal's transform: where room 1 stands, in this room's coordinates — this room moved
/// back through its doorway. A move, not a reflection: its determinant is +1.
pub fn portal() -> Mat4 {
    Mat4::from_translation(Vec3::new(0.0, 0.0, -ROOM_SPACING))
}

/// Room k, through a `portal`: this room moved k times.
pub fn room_transform(portal: Mat4, k: usize) -> Mat4 {
    (0..k).fold(Mat4::IDENTITY, |moved, _| moved * portal)
}

/// The plane of doorway k (the doorway room k − 1 has, through which room k is seen), its front
/// towards the viewer.
pub fn doorway(portal: Mat4, k: usize) -> Plane {
    mirror_plane().transformed(room_transform(portal, k - 1))
}

// ANCHOR_END: move

// ANCHOR: scissor
/// Where room k can show on a target of `size`, for k from 1 to `depth`: the rectangle around
/// doorway k's corners on the screen, within the rectangle of the doorway before it.
pub fn behind_doorways(
    portal: Mat4,
    depth: usize,
    view_projection: Mat4,
    size: (u32, u32),
) -> Vec<ScreenRect> {
    let (min, max) = (MIRROR_MIN, MIRROR_MAX);
    let corners = [
        (min.x, min.y),
        (max.x, min.y),
        (max.x, max.y),
        (min.x, max.y),
    ]
    .map(|(x, y)| Vec3::new(x, y, min.z));
    let mut inside = ScreenRect::whole(size);
    (1..=depth)
        .map(|k| {
            let doorway = corners.map(|c| room_transform(portal, k - 1).transform_point3(c));
            inside = inside.within(ScreenRect::around(view_projection, &doorway, size));
            inside
        })
        .collect()
}
// ANCHOR_END: scissor

/// The far rooms' light: an evening sun, low and warm, from the left, and a cool sky.
pub const EVENING: [Light; 3] = [
    Light {
        diffuse: Vec3::new(0.75, 0.45, 0.25),
        specular: Vec3::new(0.5, 0.35, 0.2),
        ambient: Vec3::new(0.18, 0.12, 0.1),
        ..LIGHTS[1]
    },
    Light {
        diffuse: Vec3::new(0.12, 0.15, 0.25),
        ..LIGHTS[0]
    },
    LIGHTS[2],
];

// ANCHOR: recipes
/// MARK_DOORWAY: the doorway where the stencil holds k (the reference), raised to k + 1 wherever
/// it passes the depth test — inside the room that sees it, behind whatever stands in front of it.
/// The room drew the doorway's surface already: `LessEqual` passes where that surface was the
/// nearest thing drawn (the same triangles, the same depths).
pub const MARK_DOORWAY: Recipe = Recipe {
    name: "MARK_DOORWAY",
    depth_compare: CompareFunction::LessEqual,
    stencil: wgpu::StencilState {
        front: RAISE_IF_EQUAL,
        back: RAISE_IF_EQUAL,
        ..states::MARK_MIRROR.stencil
    },
    ..states::MARK_MIRROR
};

const RAISE_IF_EQUAL: wgpu::StencilFaceState = wgpu::StencilFaceState {
    compare: CompareFunction::Equal,
    fail_op: StencilOperation::Keep,
    depth_fail_op: StencilOperation::Keep,
    pass_op: StencilOperation::IncrementClamp,
};

/// DRAW_FAR_ROOM: room k where the stencil holds k — with clip=discard, its fragments on this side
/// of the doorway it is seen through discarded (with clip=oblique the projection cuts them). The
/// winding is the room's own: a move does not turn it.
pub fn draw_far_room(knobs: &Knobs) -> Recipe {
    Recipe {
        name: "DRAW_FAR_ROOM",
        clip: match knobs.get("clip") {
            "discard" => Clip::Discard,
            _ => Clip::None,
        },
        ..states::DRAW_REFLECTION
    }
}
// ANCHOR_END: recipes

pub struct Portal {
    depth: usize,
    draw_room: wgpu::RenderPipeline,
    mark_doorway: wgpu::RenderPipeline,
    draw_far_room: wgpu::RenderPipeline,
    reset_depth: Option<ResetDepth>,
    doorway_first: bool,
    /// Whether each far room is seen through a projection whose near plane is its doorway.
    oblique: bool,
    /// Rooms 1 to depth: this room moved, clipped at the doorway it is seen through.
    rooms: Vec<MirrorWorld>,
    /// Doorway k's surface, placed in room k − 1, for k from 1 to depth.
    doorways: Vec<Placed>,
    /// The portal's transform.
    portal: Mat4,
}

impl Lesson for Portal {
    const NAME: &'static str = "portal";
    const TITLE: &'static str = "Lesson 16: the portal";
    const KNOBS: &'static [Knob] = KNOBS;
    /// In front of the doorway, a little to the right and above, looking through it.
    const CAMERA: Camera = Camera {
        yaw: 15.0,
        pitch: 10.0,
        distance: 8.0,
    };

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Self::through(gpu, scene, knobs, portal())
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        for room in &self.rooms {
            room.update(frame, self.oblique);
        }
        frame.clear();
        if self.doorway_first && self.depth > 0 {
            self.mark_doorway(frame, 0);
        }
        frame.step(DRAW_ROOM_STEPS[0], |pass| {
            pass.set_pipeline(&self.draw_room);
            for object in scene.whole_room() {
                object.draw(pass);
            }
        });
        let view_projection = frame.view.view_projection();
        let scissors = behind_doorways(self.portal, self.depth, view_projection, frame.size());
        for k in 0..self.depth {
            // Doorway k + 1, seen from room k: k + 1 where the stencil holds k and the doorway
            // passes the depth test.
            if !self.doorway_first || k > 0 {
                self.mark_doorway(frame, k);
            }
            // Room k + 1 shows only inside doorway k + 1: the scissor rectangle around it spares
            // the rasterizer the pixels outside.
            let inside = scissors[k];
            // Whatever room k drew behind its doorway must not hide room k + 1.
            if let Some(reset) = &self.reset_depth {
                frame.step(CLEAR_BEHIND_STEPS[k], |pass| {
                    pass.set_scissor(inside);
                    reset.draw(pass, k as u32 + 1);
                });
            }
            // Room k + 1: this room moved k + 1 times, where the stencil holds k + 1.
            let far = &self.rooms[k];
            frame.step(DRAW_ROOM_STEPS[k + 1], |pass| {
                pass.set_scissor(inside);
                pass.set_pipeline(&self.draw_far_room);
                pass.set_stencil_reference(k as u32 + 1);
                far.bind(pass);
                for object in scene.whole_room() {
                    far.draw(pass, object);
                }
            });
        }
    }
    // ANCHOR_END: render
}

impl Portal {
    /// The lesson through another portal: its rooms moved by `portal` instead of [`portal()`].
    pub fn through(gpu: &Gpu, scene: &Scene, knobs: &Knobs, portal: Mat4) -> anyhow::Result<Self> {
        let depth: usize = knobs.get("depth").parse()?;
        let pipeline = |recipe: &Recipe| scene.pipeline(&gpu.device, recipe);
        let objects = scene.whole_room();
        let rooms = (1..=depth)
            .map(|k| {
                let mut far = MirrorWorld::seen_through(
                    gpu,
                    scene,
                    (room_transform(portal, k), doorway(portal, k)),
                    &objects,
                );
                far.set_room_lights(EVENING);
                far
            })
            .collect();
        let doorways = (1..=depth)
            .map(|k| scene.placed(&gpu.device, &scene.mirror, room_transform(portal, k - 1)))
            .collect();
        Ok(Self {
            depth,
            draw_room: pipeline(&states::OPAQUE),
            mark_doorway: pipeline(&MARK_DOORWAY),
            draw_far_room: pipeline(&draw_far_room(knobs)),
            reset_depth: knobs
                .is_on("clear-behind")
                .then(|| ResetDepth::to_the_sky(gpu, scene)),
            doorway_first: knobs.get("order") == "doorway-first",
            oblique: knobs.get("clip") == "oblique",
            rooms,
            doorways,
            portal,
        })
    }

    /// Marks doorway k + 1 as room k sees it: with room k's camera, where the stencil holds k.
    fn mark_doorway(&self, frame: &mut Frame<'_>, k: usize) {
        let scene = frame.scene;
        frame.step(MARK_DOORWAY_STEPS[k], |pass| {
            pass.set_pipeline(&self.mark_doorway);
            pass.set_stencil_reference(k as u32);
            match k {
                0 => scene.bind_frame(pass),
                k => self.rooms[k - 1].bind(pass),
            }
            scene.mirror.draw_placed(pass, &self.doorways[k]);
        });
    }
}
