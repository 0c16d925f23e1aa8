//! Lesson 15: capping.
//!
//! A plane cuts the skull open (lesson 8's clip plane), and the cut shows its inside: the skull is
//! a shell. The stencil closes it. Along the ray through a pixel of the plane, count the faces of
//! what is left of the skull: a back face +1, a front face −1. Where the count is not 0 the plane
//! lies inside the solid there, and a square drawn in the plane, where the stencil is not 0, is the
//! cap. The same count as lesson 14's, with the volume replaced by the solid itself.

use workbook::glam::{Mat4, Vec3, Vec4};
use workbook::gpu::states::{self, Clip};
use workbook::lesson::knobs;
use workbook::math::reflect::Plane;
use workbook::room::camera::Camera;
use workbook::room::mesh::{GpuMesh, MeshData};
use workbook::room::scene::{
    CRATE_SIZE, Drawable, FrameBinding, LIGHTS, POINTS, Placed, Points, SKULL_CENTRE,
};
use workbook::wgpu::{self, CompareFunction, StencilFaceState, StencilOperation};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Pass, Recipe, Scene};

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "cap",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether the cut is closed by the cap, where the stencil counts that the plane lies inside the solid",
    },
    Knob {
        name: "cut",
        values: &["-0.3", "0", "0.3"],
        default: "0",
        meaning: "where the plane cuts, in metres along its normal from the skull's centre: nearer the camera, through the centre, or deeper",
    },
    Knob {
        name: "crate",
        values: &["beside", "through"],
        default: "beside",
        meaning: "whether a second crate goes through the skull, cut and capped with it",
    },
    Knob {
        name: "count",
        values: &["wrap", "invert"],
        default: "wrap",
        meaning: "count +1 and −1 (IncrementWrap, DecrementWrap), or flip between 0 and 255 (Invert: parity, wrong where two solids overlap)",
    },
    Knob {
        name: "mesh",
        values: &["closed", "holed"],
        default: "closed",
        meaning: "the skull as it is, or with a hole in its side: a mesh that is not closed (as scanned models often are)",
    },
];
// ANCHOR_END: knobs

// ANCHOR: plane
/// The way the plane faces: towards the part that is kept, down and a little back: the cranium's
/// top is sawn off, and the camera, above, looks into the cut.
pub const KEPT: Vec3 = Vec3::new(-0.15, -1.0, -0.25);

/// The cut: the plane through the skull's centre moved `offset` metres along its normal; what
/// lies on its front (n · p + d ≥ 0) is kept.
pub fn cut_plane(offset: f32) -> Plane {
    let n = KEPT.normalize();
    let through = SKULL_CENTRE + n * offset;
    Plane::new(n, -n.dot(through))
}

/// The cap: a square in the plane, 2.4 m a side, centred where the skull's centre projects onto
/// it: larger than any cut through the skull. Two triangles, as homogeneous points.
pub fn cap_square(plane: Plane) -> [Vec4; 6] {
    let n = plane.normal;
    let centre = SKULL_CENTRE - n * (n.dot(SKULL_CENTRE) + plane.d);
    let u = n.cross(Vec3::Y).normalize() * 1.2;
    let v = u.cross(n);
    let corner = |a: f32, b: f32| (centre + u * a + v * b).extend(1.0);
    let [p, q, r, s] = [
        corner(-1.0, -1.0),
        corner(1.0, -1.0),
        corner(1.0, 1.0),
        corner(-1.0, 1.0),
    ];
    [p, q, r, p, r, s]
}
// ANCHOR_END: plane

// ANCHOR: recipes
/// CUT_SOLID: the solids with both faces drawn, clipped at the plane by discarding what lies
/// behind it. Without a cap the inside shows through the cut.
pub const CUT_SOLID: Recipe = Recipe {
    name: "CUT_SOLID",
    cull_mode: None,
    clip: Clip::Discard,
    ..states::OPAQUE
};

/// COUNT_INSIDE: the cut solids again, every fragment along the ray (depth `Always`), writing
/// only the stencil: a back face +1, a front face −1 (or, with count=invert, both flip the value
/// between 0 and 255). Where the ray reaches the plane inside a solid, it leaves the solid through
/// one more back face than it enters through front faces: the count there is not 0.
pub fn count_inside(knobs: &Knobs) -> Recipe {
    let face = |operation| StencilFaceState {
        compare: CompareFunction::Always,
        fail_op: StencilOperation::Keep,
        depth_fail_op: StencilOperation::Keep,
        pass_op: operation,
    };
    let (front, back) = match knobs.get("count") {
        "invert" => (StencilOperation::Invert, StencilOperation::Invert),
        _ => (
            StencilOperation::DecrementWrap,
            StencilOperation::IncrementWrap,
        ),
    };
    Recipe {
        name: "COUNT_INSIDE",
        depth_write: false,
        depth_compare: CompareFunction::Always,
        stencil: wgpu::StencilState {
            front: face(front),
            back: face(back),
            read_mask: 0xff,
            write_mask: 0xff,
        },
        color_writes: wgpu::ColorWrites::empty(),
        ..CUT_SOLID
    }
}

/// DRAW_CAP: the square in the plane, where the count is not 0 (reference 0, `NotEqual`), with
/// the depth test and depth writes; each pixel it draws sets the count back to 0 (`Zero`), ready
/// for another cut.
pub const DRAW_CAP: Recipe = Recipe {
    name: "DRAW_CAP",
    cull_mode: None,
    stencil: wgpu::StencilState {
        front: CAP_FACE,
        back: CAP_FACE,
        read_mask: 0xff,
        write_mask: 0xff,
    },
    ..states::OPAQUE
};

const CAP_FACE: StencilFaceState = StencilFaceState {
    compare: CompareFunction::NotEqual,
    fail_op: StencilOperation::Keep,
    depth_fail_op: StencilOperation::Keep,
    pass_op: StencilOperation::Zero,
};
// ANCHOR_END: recipes

/// The lesson's entries in the room's shader.
pub const SHADER: &str = include_str!("capping.wgsl");

// ANCHOR: solids
/// The second crate, when it goes through the skull: smaller than the room's, turned, and sunk
/// into the skull's side so that the plane cuts both.
pub fn crate_through() -> Mat4 {
    Mat4::from_translation(SKULL_CENTRE + Vec3::new(0.45, -0.2, 0.3))
        * Mat4::from_rotation_y(0.5)
        * Mat4::from_scale(Vec3::splat(0.8 / CRATE_SIZE))
}

/// The skull's mesh with a hole at its back: the triangles whose centres lie within 0.2 of a point
/// at the back of the skull left out (in the mesh's own units, where the skull is 1 across).
pub fn holed(shape: &MeshData) -> MeshData {
    let centre = Vec3::new(0.15, -0.1, -0.4);
    let near = |t: &[u32]| {
        let p = |i: u32| Vec3::from(shape.vertices[i as usize].position);
        ((p(t[0]) + p(t[1]) + p(t[2])) / 3.0).distance(centre) < 0.2
    };
    let indices = (shape.indices.chunks_exact(3))
        .filter(|t| !near(t))
        .flatten()
        .copied()
        .collect();
    MeshData {
        vertices: shape.vertices.clone(),
        indices,
    }
}
// ANCHOR_END: solids

/// Which of the cut solids a draw takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Solids {
    /// The skull, and the second crate if it goes through.
    Both,
    Skull,
    /// The second crate (nothing if it does not go through).
    Crate,
}

/// What the frame counts and caps with, and the solid it cuts: the lesson's, from its knobs
/// ([`Cutting::of`]), or an exercise's.
pub struct Cutting {
    /// The counts, each drawing the solids it names.
    pub counts: Vec<(Recipe, Solids)>,
    /// The caps, each the square in the plane drawn where its stencil test passes.
    pub caps: Vec<Recipe>,
    /// The skull's mesh replaced (by the skull with a hole, say), or `None`: the skull as loaded.
    pub solid: Option<MeshData>,
}

impl Cutting {
    /// The lesson's: one count of both solids, one cap (none with cap=off), the skull's mesh as
    /// the knob `mesh` says.
    pub fn of(knobs: &Knobs, scene: &Scene) -> Self {
        let capped = knobs.is_on("cap");
        Self {
            counts: capped
                .then(|| (count_inside(knobs), Solids::Both))
                .into_iter()
                .collect(),
            caps: capped.then_some(DRAW_CAP).into_iter().collect(),
            solid: (knobs.get("mesh") == "holed").then(|| holed(&scene.skull_shape)),
        }
    }
}

pub struct Capping {
    frame: FrameBinding,
    plane: Plane,
    draw_room: wgpu::RenderPipeline,
    cut_solid: wgpu::RenderPipeline,
    counts: Vec<(wgpu::RenderPipeline, Solids)>,
    caps: Vec<wgpu::RenderPipeline>,
    cap: Points,
    crate_through: Option<Placed>,
    solid: Option<GpuMesh>,
}

/// The room but the skull: floor, wall, mirror (as a plain surface) and crate.
pub fn room(scene: &Scene) -> [&Drawable; 4] {
    [&scene.floor, &scene.wall, &scene.mirror, &scene.crate_box]
}

impl Lesson for Capping {
    const NAME: &'static str = "capping";
    const TITLE: &'static str = "Lesson 15: capping";
    const KNOBS: &'static [Knob] = KNOBS;
    /// Above and to the right, looking down into the cut.
    const CAMERA: Camera = Camera {
        yaw: 22.0,
        pitch: 35.0,
        distance: 8.0,
    };

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Self::cutting(gpu, scene, knobs, Cutting::of(knobs, scene))
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // The room's lights; the plane, for the recipes that clip.
        let queue = &frame.gpu.queue;
        (self.frame).write(queue, &frame.view, &LIGHTS, self.plane.as_vec4());
        frame.clear();

        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            self.frame.bind(pass);
            room(scene).iter().for_each(|object| object.draw(pass));
        });
        frame.step("draw the cut solids", |pass| {
            pass.set_pipeline(&self.cut_solid);
            self.frame.bind(pass);
            self.draw_solids(pass, scene, Solids::Both);
        });
        if self.caps.is_empty() {
            return;
        }
        // Each pixel counts the cut solids' faces along its ray: not 0 where the plane is inside.
        frame.step("count the inside", |pass| {
            self.frame.bind(pass);
            for (count, solids) in &self.counts {
                pass.set_pipeline(count);
                self.draw_solids(pass, scene, *solids);
            }
        });
        // The cap, where the count is not 0.
        frame.step("draw the cap", |pass| {
            pass.set_stencil_reference(0);
            self.frame.bind(pass);
            for cap in &self.caps {
                pass.set_pipeline(cap);
                self.cap.draw(pass, 0..self.cap.len());
            }
        });
    }
    // ANCHOR_END: render
}

impl Capping {
    /// The lesson with `cutting`'s counts, caps and solid.
    pub fn cutting(
        gpu: &Gpu,
        scene: &Scene,
        knobs: &Knobs,
        cutting: Cutting,
    ) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let plane = cut_plane(knobs.get("cut").parse()?);
        let shader = scene.shader_with(device, "capping.wgsl", SHADER);
        let cap = |recipe| {
            let entries = (&shader, "vs_cap", "fs_cap");
            scene.pipeline_for_vertices(device, recipe, entries, &POINTS)
        };
        Ok(Self {
            frame: scene.frame_binding(device, "cut room"),
            plane,
            draw_room: scene.pipeline(device, &states::OPAQUE),
            cut_solid: scene.pipeline(device, &CUT_SOLID),
            counts: (cutting.counts.iter())
                .map(|(recipe, solids)| (scene.pipeline(device, recipe), *solids))
                .collect(),
            caps: cutting.caps.iter().map(cap).collect(),
            cap: Points::new(device, "the cap", &cap_square(plane)),
            crate_through: (knobs.get("crate") == "through")
                .then(|| scene.placed(device, &scene.crate_box, crate_through())),
            solid: (cutting.solid.as_ref()).map(|mesh| GpuMesh::new(device, "the cut solid", mesh)),
        })
    }

    /// The solids the plane cuts, those `which` names: the skull (or what replaces its mesh), and
    /// the second crate if it goes through.
    fn draw_solids(&self, pass: &mut Pass<'_, '_>, scene: &Scene, which: Solids) {
        if which != Solids::Crate {
            match &self.solid {
                Some(mesh) => scene.skull.draw_mesh(pass, mesh),
                None => scene.skull.draw(pass),
            }
        }
        if let (Some(placed), true) = (&self.crate_through, which != Solids::Skull) {
            scene.crate_box.draw_placed(pass, placed);
        }
    }
}
