//! Lesson 14: the shadow volume.
//!
//! The skull and the crate shadow the room, each other and themselves. Each casts a volume of
//! shadow away from the key light; a point of the room is in shadow when it lies inside a volume,
//! and the stencil buffer finds out by counting, along the ray from the eye, the volume's faces the
//! ray crosses: in +1, out −1 (z-pass), or the same count behind the point (z-fail, which still
//! works when the eye is itself in a shadow). The room is drawn as it looks in shadow, the volumes
//! counted, then the key light added where the count is 0.

mod volume;

pub use volume::{Volume, at_infinity, shadow_volume};

use workbook::glam::Vec3;
use workbook::gpu::states;
use workbook::lesson::knobs;
use workbook::math::shadow::LightSource;
use workbook::room::camera::{Camera, View};
use workbook::room::mesh::MeshData;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, FrameBinding, LIGHTS, Light, POINTS, Points,
};
use workbook::wgpu::{self, CompareFunction, Face, StencilFaceState, StencilOperation};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Pass, Recipe, Scene};

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "method",
        values: &["z-fail", "z-pass"],
        default: "z-fail",
        meaning: "count the faces behind the visible point, where the depth test fails (z-fail), or in front of it, where it passes (z-pass: wrong where the eye is in a shadow)",
    },
    Knob {
        name: "caps",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether the volumes are closed at the solid and at infinity (z-fail counts through them)",
    },
    Knob {
        name: "faces",
        values: &["two-sided", "two-passes"],
        default: "two-sided",
        meaning: "count front and back faces in one pass, each face its own stencil state, or in two passes, culling one side each time",
    },
    Knob {
        name: "increment",
        values: &["wrap", "clamp"],
        default: "wrap",
        meaning: "what +1 at 255 and −1 at 0 do: go round (IncrementWrap, DecrementWrap), or stay (…Clamp: a −1 met before its +1 is lost)",
    },
    Knob {
        name: "see-volumes",
        values: knobs::ON_OFF,
        default: "off",
        meaning: "whether the volumes are drawn at the end, a faint amber, to see where they are",
    },
];
// ANCHOR_END: knobs

// ANCHOR: key_light
/// The key light: a point light behind the skull and to its left, 3 m up, so that the shadows
/// fall forwards, across the floor towards the camera.
pub const KEY_LIGHT: Vec3 = Vec3::new(-2.0, 3.0, 1.0);

/// The lights: the key light, which casts the shadows (bright, since it fades with the distance,
/// and with little ambient light, so that its shadows are dark), and Luna's two fill lights, which
/// cast none.
pub fn lights(key: LightSource) -> [Light; 3] {
    let key = Light {
        source: key,
        ambient: Vec3::splat(0.12),
        diffuse: Vec3::splat(1.6),
        specular: Vec3::splat(0.6),
        spot: None,
    };
    [key, LIGHTS[1], LIGHTS[2]]
}

/// The key light as [`shadow_volume`] takes it.
pub const KEY: LightSource = LightSource::Point {
    position: KEY_LIGHT,
};

/// A pose with the eye inside the skull's shadow, low behind it, looking back at the mirror: where
/// z-pass goes wrong.
pub const IN_THE_SKULLS_SHADOW: Camera = Camera {
    yaw: 9.0,
    pitch: -18.0,
    distance: 3.8,
};
// ANCHOR_END: key_light

// ANCHOR: recipes
/// DRAW_IN_SHADOW: the room, opaque, as it looks in shadow (its shader leaves the key light out).
pub const DRAW_IN_SHADOW: Recipe = Recipe {
    name: "DRAW_IN_SHADOW",
    ..states::OPAQUE
};

/// COUNT_Z_PASS or COUNT_Z_FAIL: the volumes' faces, both sides, written into the stencil only.
/// z-pass counts a face where it lies in front of what was drawn (the depth test passes): front
/// faces +1, back faces −1. z-fail counts it where it lies behind (the test fails): back faces +1,
/// front faces −1. Either way a pixel ends at 0 where its visible point is outside every volume.
pub fn count_volumes(knobs: &Knobs) -> Recipe {
    let (up, down) = match knobs.get("increment") {
        "clamp" => (
            StencilOperation::IncrementClamp,
            StencilOperation::DecrementClamp,
        ),
        _ => (
            StencilOperation::IncrementWrap,
            StencilOperation::DecrementWrap,
        ),
    };
    let keep = StencilOperation::Keep;
    let face = |depth_pass, depth_fail| StencilFaceState {
        compare: CompareFunction::Always,
        fail_op: keep,
        depth_fail_op: depth_fail,
        pass_op: depth_pass,
    };
    let (name, front, back) = match knobs.get("method") {
        "z-pass" => ("COUNT_Z_PASS", face(up, keep), face(down, keep)),
        _ => ("COUNT_Z_FAIL", face(keep, down), face(keep, up)),
    };
    Recipe {
        name,
        depth_write: false,
        stencil: wgpu::StencilState {
            front,
            back,
            read_mask: 0xff,
            write_mask: 0xff,
        },
        cull_mode: None,
        color_writes: wgpu::ColorWrites::empty(),
        depth_bias: BEHIND_THE_SURFACE,
        ..states::OPAQUE
    }
}

/// The volumes' depths pushed a little farther than they are: 16 of the depth buffer's smallest
/// steps (about 0.2 mm, 10 m from the eye). A near cap lies exactly on the solid's dark side, which
/// the room drew; without the push, whether the cap counts there (its depth test fails) or not is
/// the rasteriser's rounding, pixel by pixel, and differs from one GPU to another. With it, the cap
/// lies behind. (No push by the slope: the volumes' sides meet the floor at grazing angles, and a
/// push by their slope would move the shadows' edges.)
pub const BEHIND_THE_SURFACE: wgpu::DepthBiasState = wgpu::DepthBiasState {
    constant: 16,
    slope_scale: 0.0,
    clamp: 0.0,
};

/// ADD_KEY_LIGHT: the room again, adding the key light's colour to what is there (One + One) where
/// the count is 0 and the surface is the one drawn first (depth `LessEqual`, no depth writes).
pub const ADD_KEY_LIGHT: Recipe = Recipe {
    name: "ADD_KEY_LIGHT",
    depth_write: false,
    depth_compare: CompareFunction::LessEqual,
    stencil: wgpu::StencilState {
        front: states::KEEP_IF_EQUAL,
        back: states::KEEP_IF_EQUAL,
        read_mask: 0xff,
        write_mask: 0,
    },
    blend: Some(wgpu::BlendState {
        color: wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        },
        alpha: wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::Zero,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        },
    }),
    ..states::OPAQUE
};

/// SEE_VOLUMES: the volumes, both sides, blended over the picture where they are in front of it.
pub const SEE_VOLUMES: Recipe = Recipe {
    name: "SEE_VOLUMES",
    depth_write: false,
    cull_mode: None,
    blend: Some(wgpu::BlendState::ALPHA_BLENDING),
    ..states::OPAQUE
};
// ANCHOR_END: recipes

// ANCHOR: two_passes
/// The count in two passes, as before GPUs had a stencil state for each side: the same recipe
/// drawn twice, culling one side each time. The side that adds goes first (front faces for z-pass,
/// back faces for z-fail), so that a count that clamps at 0 never goes below it.
pub fn two_passes(count: &Recipe) -> [Recipe; 2] {
    let culling = |culled| Recipe {
        cull_mode: Some(culled),
        ..count.clone()
    };
    let adds = |op| {
        matches!(
            op,
            StencilOperation::IncrementWrap | StencilOperation::IncrementClamp
        )
    };
    let front = count.stencil.front;
    match adds(front.pass_op) || adds(front.depth_fail_op) {
        true => [culling(Face::Back), culling(Face::Front)],
        false => [culling(Face::Front), culling(Face::Back)],
    }
}
// ANCHOR_END: two_passes

/// The lesson's entries in the room's shader.
pub const SHADER: &str = include_str!("shadow_volume.wgsl");

/// A shadow volume in a vertex buffer: its sides, then its caps.
pub struct VolumeBuffer {
    points: Points,
    sides: u32,
}

impl VolumeBuffer {
    pub fn new(device: &wgpu::Device, name: &'static str, volume: &Volume) -> Self {
        let points = [&volume.sides[..], &volume.caps[..]].concat();
        Self {
            points: Points::new(device, name, &points),
            sides: volume.sides.len() as u32,
        }
    }

    /// Draws the sides, and the caps if `caps`.
    pub fn draw(&self, pass: &mut Pass<'_, '_>, caps: bool) {
        let end = if caps { self.points.len() } else { self.sides };
        self.points.draw(pass, 0..end);
    }
}

/// The volumes of the solids that cast shadows, in the world: the skull (or the model `--model`
/// names) and the crate.
pub fn volumes(scene: &Scene, light: LightSource) -> [(&'static str, Volume); 2] {
    let crate_box = MeshData::cuboid(Vec3::splat(CRATE_SIZE));
    let crate_world = workbook::glam::Mat4::from_translation(CRATE_CENTRE);
    [
        (
            "the skull's volume",
            shadow_volume(&scene.skull_shape, scene.skull.world(), light),
        ),
        (
            "the crate's volume",
            shadow_volume(&crate_box, crate_world, light),
        ),
    ]
}

pub struct ShadowVolume {
    lights: [Light; 3],
    room_frame: FrameBinding,
    draw_in_shadow: wgpu::RenderPipeline,
    /// One pipeline (two-sided), or two (front faces, then back faces).
    count_volumes: Vec<wgpu::RenderPipeline>,
    add_key_light: wgpu::RenderPipeline,
    see_volumes: Option<wgpu::RenderPipeline>,
    volumes: Vec<VolumeBuffer>,
    caps: bool,
}

impl Lesson for ShadowVolume {
    const NAME: &'static str = "shadow-volume";
    const TITLE: &'static str = "Lesson 14: the shadow volume";
    const KNOBS: &'static [Knob] = KNOBS;
    /// From the front and to the left, above the skull's shadow.
    const CAMERA: Camera = Camera {
        yaw: -15.0,
        pitch: 30.0,
        distance: 11.0,
    };

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        Self::lit_by(gpu, scene, knobs, KEY)
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        // The camera's view with the far plane at infinity, where the volumes end.
        let view = View {
            projection: Camera::projection_to_infinity(frame.view.aspect()),
            ..frame.view
        };
        (self.room_frame).write(&frame.gpu.queue, &view, &self.lights, Default::default());
        frame.clear();

        // The room as it looks in shadow, and its depth.
        frame.step("draw the room in shadow", |pass| {
            pass.set_pipeline(&self.draw_in_shadow);
            self.room_frame.bind(pass);
            for object in scene.whole_room() {
                object.draw(pass);
            }
        });
        // Each pixel counts the volumes' faces between the eye and its visible point (z-pass)
        // or behind it (z-fail): the count is how many volumes that point lies in.
        frame.step("count the volumes", |pass| {
            for count in &self.count_volumes {
                pass.set_pipeline(count);
                self.room_frame.bind(pass);
                for volume in &self.volumes {
                    volume.draw(pass, self.caps);
                }
            }
        });
        // The key light, added where the count is 0: outside every volume.
        frame.step("add the key light", |pass| {
            pass.set_pipeline(&self.add_key_light);
            pass.set_stencil_reference(0);
            self.room_frame.bind(pass);
            for object in scene.whole_room() {
                object.draw(pass);
            }
        });
        if let Some(see_volumes) = &self.see_volumes {
            frame.step("see the volumes", |pass| {
                pass.set_pipeline(see_volumes);
                self.room_frame.bind(pass);
                for volume in &self.volumes {
                    volume.draw(pass, true);
                }
            });
        }
    }
    // ANCHOR_END: render
}

impl ShadowVolume {
    /// The lesson with the key light `key` (the lesson's is [`KEY`]).
    pub fn lit_by(
        gpu: &Gpu,
        scene: &Scene,
        knobs: &Knobs,
        key: LightSource,
    ) -> anyhow::Result<Self> {
        let count = count_volumes(knobs);
        let counts = match knobs.get("faces") {
            "two-passes" => two_passes(&count).to_vec(),
            _ => vec![count],
        };
        Self::counting_with(gpu, scene, knobs, key, &counts)
    }

    /// The lesson lit by `key`, its volumes counted by `counts`, one pass each.
    pub fn counting_with(
        gpu: &Gpu,
        scene: &Scene,
        knobs: &Knobs,
        key: LightSource,
        counts: &[Recipe],
    ) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let lights = lights(key);
        let shader = scene.shader_with(device, "shadow_volume.wgsl", SHADER);
        let room = |recipe: &Recipe, fragment| {
            scene.pipeline_in(device, recipe, (&shader, "vs_main", fragment))
        };
        let points = |recipe: &Recipe| {
            scene.pipeline_for_vertices(
                device,
                recipe,
                (&shader, "vs_volume", "fs_volume"),
                &POINTS,
            )
        };
        Ok(Self {
            lights,
            room_frame: scene.frame_binding(device, "room to infinity"),
            draw_in_shadow: room(&DRAW_IN_SHADOW, "fs_in_shadow"),
            count_volumes: counts.iter().map(points).collect(),
            add_key_light: room(&ADD_KEY_LIGHT, "fs_key_light"),
            see_volumes: knobs.is_on("see-volumes").then(|| points(&SEE_VOLUMES)),
            volumes: (volumes(scene, key).iter())
                .map(|(name, volume)| VolumeBuffer::new(device, name, volume))
                .collect(),
            caps: knobs.is_on("caps"),
        })
    }
}
