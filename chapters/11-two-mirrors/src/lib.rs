//! Lesson 11: two mirrors.
//!
//! A second mirror stands behind the camera, facing the first: the first shows the room, the second
//! mirror in the room, the first mirror in that, and so on — a corridor of images. Level k of the
//! corridor is drawn where the stencil holds k; each level's mirror is marked by incrementing inside
//! the level that sees it; the reflections compose (R₁, R₁R₂, R₁R₂R₁, ...) and the winding flips at
//! odd levels only.

use workbook::glam::{Mat4, Vec3};
use workbook::gpu::states::{self, Clip};
use workbook::lesson::mirror::ResetDepth;
use workbook::math::reflect::{Plane, reflection};
use workbook::room::camera::Camera;
use workbook::room::mirror_world::MirrorWorld;
use workbook::room::scene::{Placed, mirror_plane};
use workbook::wgpu::{self, CompareFunction, FrontFace, StencilOperation};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Pass, Recipe, Scene};

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "depth",
        values: &["0", "1", "2", "3", "4", "5", "6"],
        default: "3",
        meaning: "how many levels of reflection: 0 is the room alone, 1 its image, 2 the image's image",
    },
    Knob {
        name: "winding",
        values: &["per-level", "always-flipped"],
        default: "per-level",
        meaning: "flip the front face at odd levels only (R₁R₂ turns it back), or at every level",
    },
    Knob {
        name: "mark",
        values: &["increment", "replace"],
        default: "increment",
        meaning: "mark each level's mirror by incrementing inside the level that sees it, or by writing k+1 anywhere",
    },
];
// ANCHOR_END: knobs

/// The deepest level the knob allows.
pub const MAX_DEPTH: usize = 6;

/// The steps of each level, by name (step names are written once, here).
const DRAW_LEVEL: [&str; MAX_DEPTH + 1] = [
    "draw the room",
    "draw level 1",
    "draw level 2",
    "draw level 3",
    "draw level 4",
    "draw level 5",
    "draw level 6",
];
const MARK_LEVEL: [&str; MAX_DEPTH] = [
    "mark level 1",
    "mark level 2",
    "mark level 3",
    "mark level 4",
    "mark level 5",
    "mark level 6",
];
const RESET_LEVEL: [&str; MAX_DEPTH] = [
    "reset the depth in level 1",
    "reset the depth in level 2",
    "reset the depth in level 3",
    "reset the depth in level 4",
    "reset the depth in level 5",
    "reset the depth in level 6",
];

// ANCHOR: mirrors
/// The first mirror: the wall's, z = 0, facing the room.
pub fn first_mirror() -> Plane {
    mirror_plane()
}

/// Where the second mirror stands: the first one turned round and moved to z = 10.
pub const SECOND_MIRROR_Z: f32 = 10.0;

/// The second mirror: z = 10, facing the first.
pub fn second_mirror() -> Plane {
    Plane::new(-Vec3::Z, SECOND_MIRROR_Z)
}

/// The second mirror's world matrix: the first mirror's quad, narrowed to 3 m (so that the mirrors
/// it shows are not framed exactly by it), turned half round about the vertical axis through z = 5
/// (a turn, not a reflection: its triangles keep their winding).
pub fn second_mirror_world() -> Mat4 {
    let middle = Vec3::new(0.0, 0.0, SECOND_MIRROR_Z / 2.0);
    Mat4::from_translation(middle)
        * Mat4::from_rotation_y(std::f32::consts::PI)
        * Mat4::from_translation(-middle)
        * Mat4::from_scale(Vec3::new(0.6, 1.0, 1.0))
}

/// Level k's reflection: the first mirror's at level 1, then the second's in it, and so on:
/// R₁, R₁R₂, R₁R₂R₁, ... (the mirror seen at level k is the first at even k, the second at odd k).
pub fn level_reflection(level: usize) -> Mat4 {
    (0..level).fold(Mat4::IDENTITY, |composed, k| {
        composed * reflection(seen_at(k))
    })
}

/// The plane of the mirror seen at level k, where the room of level 0 has it.
pub fn seen_at(level: usize) -> Plane {
    if level.is_multiple_of(2) {
        first_mirror()
    } else {
        second_mirror()
    }
}
// ANCHOR_END: mirrors

pub struct TwoMirrors {
    depth: usize,
    draw_room: wgpu::RenderPipeline,
    /// Per front face: Ccw for even levels, Cw for odd ones (or always, with winding=always-flipped).
    draw_level: [wgpu::RenderPipeline; 2],
    pub mark_level: [wgpu::RenderPipeline; 2],
    draw_glass: [wgpu::RenderPipeline; 2],
    reset_depth: ResetDepth,
    /// Levels 1 to depth: the room under level k's reflection, clipped behind its mirror.
    worlds: Vec<MirrorWorld>,
    /// The mirror seen at each level 0 to depth, placed by that level's reflection.
    mirrors: Vec<Placed>,
    flip_every_level: bool,
    replace: bool,
}

// ANCHOR: recipes
/// The recipes of level k: the room's objects where the stencil holds k (the reference), clipped
/// behind the mirror that shows them; the mark of the mirror they show, by incrementing k to k + 1
/// (or, mark=replace, by writing k + 1 wherever the mirror passes the depth test); each with the
/// front face the level's determinant asks for.
pub fn level_recipes(front_face: FrontFace, replace: bool) -> (Recipe, Recipe, Recipe) {
    let draw = Recipe {
        name: "DRAW_LEVEL",
        front_face,
        clip: Clip::Discard,
        ..states::DRAW_REFLECTION
    };
    let increment = wgpu::StencilFaceState {
        compare: CompareFunction::Equal,
        fail_op: StencilOperation::Keep,
        depth_fail_op: StencilOperation::Keep,
        pass_op: StencilOperation::IncrementClamp,
    };
    let mark_face = match replace {
        false => increment,
        true => wgpu::StencilFaceState {
            compare: CompareFunction::Always,
            pass_op: StencilOperation::Replace,
            ..increment
        },
    };
    let mark = Recipe {
        name: "MARK_LEVEL",
        front_face,
        stencil: wgpu::StencilState {
            front: mark_face,
            back: mark_face,
            ..states::MARK_MIRROR.stencil
        },
        ..states::MARK_MIRROR
    };
    let glass = Recipe {
        name: "DRAW_LAST_MIRROR",
        front_face,
        ..states::DRAW_REFLECTION
    };
    (draw, mark, glass)
}
// ANCHOR_END: recipes

impl Lesson for TwoMirrors {
    const NAME: &'static str = "two-mirrors";
    const TITLE: &'static str = "Lesson 11: two mirrors";
    const KNOBS: &'static [Knob] = KNOBS;
    /// Between the mirrors, looking at the first one a little from the side.
    const CAMERA: Camera = Camera {
        yaw: 20.0,
        pitch: 8.0,
        distance: 7.5,
    };

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let depth: usize = knobs.get("depth").parse()?;
        let replace = knobs.get("mark") == "replace";
        let pipeline = |recipe: &Recipe| scene.pipeline(&gpu.device, recipe);
        let [ccw, cw] = [FrontFace::Ccw, FrontFace::Cw].map(|face| level_recipes(face, replace));
        let objects = scene.solid_objects();
        let worlds = (1..=depth)
            .map(|level| {
                // Level k is seen through the mirror of level k - 1, where that level has it.
                let portal = seen_at(level - 1).transformed(level_reflection(level - 1));
                let placing = (level_reflection(level), portal);
                MirrorWorld::seen_through(gpu, scene, placing, &objects)
            })
            .collect();
        let mirrors = (0..=depth)
            .map(|level| {
                let own = if level.is_multiple_of(2) {
                    Mat4::IDENTITY
                } else {
                    second_mirror_world()
                };
                scene.placed(&gpu.device, &scene.mirror, level_reflection(level) * own)
            })
            .collect();
        Ok(Self {
            depth,
            draw_room: pipeline(&states::OPAQUE),
            draw_level: [pipeline(&ccw.0), pipeline(&cw.0)],
            mark_level: [pipeline(&ccw.1), pipeline(&cw.1)],
            draw_glass: [pipeline(&ccw.2), pipeline(&cw.2)],
            reset_depth: ResetDepth::new(gpu, scene),
            worlds,
            mirrors,
            flip_every_level: knobs.get("winding") == "always-flipped",
            replace,
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        for world in &self.worlds {
            world.update(frame, false);
        }
        frame.clear();
        frame.step(DRAW_LEVEL[0], |pass| {
            pass.set_pipeline(&self.draw_room);
            for object in scene.solid_objects() {
                object.draw(pass);
            }
        });
        for level in 0..self.depth {
            // Mark the mirror this level sees: k + 1 inside level k's pixels (where the stencil
            // holds k), where the mirror passes the depth test.
            frame.step(MARK_LEVEL[level], |pass| {
                pass.set_pipeline(&self.mark_level[self.face(level)]);
                pass.set_stencil_reference(if self.replace { level + 1 } else { level } as u32);
                self.world_frame(pass, scene, level);
                scene.mirror.draw_placed(pass, &self.mirrors[level]);
            });
            // Whatever level k drew behind that mirror must not hide level k + 1.
            frame.step(RESET_LEVEL[level], |pass| {
                self.reset_depth.draw(pass, level as u32 + 1);
            });
            // Level k + 1: the room under its composed reflection, where the stencil holds k + 1.
            let world = &self.worlds[level];
            frame.step(DRAW_LEVEL[level + 1], |pass| {
                pass.set_pipeline(&self.draw_level[self.face(level + 1)]);
                pass.set_stencil_reference(level as u32 + 1);
                world.bind(pass);
                for object in scene.solid_objects() {
                    world.draw(pass, object);
                }
            });
        }
        // The deepest level's mirror, not followed further: plain glass.
        frame.step("draw the last mirror", |pass| {
            pass.set_pipeline(&self.draw_glass[self.face(self.depth)]);
            pass.set_stencil_reference(self.depth as u32);
            self.world_frame(pass, scene, self.depth);
            scene.mirror.draw_placed(pass, &self.mirrors[self.depth]);
        });
    }
    // ANCHOR_END: render
}

impl TwoMirrors {
    /// Which of the two pipelines draws level k: reflections turn the winding round, so odd levels
    /// (determinant −1) take the clockwise front face; even levels have an even number of
    /// reflections and take the usual one again.
    fn face(&self, level: usize) -> usize {
        match (level, self.flip_every_level) {
            (0, _) => 0,
            (_, true) => 1,
            (level, false) => level % 2,
        }
    }

    /// Binds level k's camera and lights: the room's at level 0, the level's world's beyond.
    fn world_frame(&self, pass: &mut Pass<'_, '_>, scene: &Scene, level: usize) {
        match level {
            0 => scene.bind_frame(pass),
            level => self.worlds[level - 1].bind(pass),
        }
    }
}
