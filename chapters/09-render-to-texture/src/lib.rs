//! Lesson 9: the mirror as a texture.
//!
//! The other way to make a mirror (Rastertek's tutorial 27): render the room from the camera
//! reflected in the mirror's plane into a texture, then draw the mirror's surface looking that texture
//! up with projective texture coordinates. The same floor mirror as lesson 8 — and, with a knob,
//! lesson 8's stencil frame, to compare the two in one lesson.

use std::cell::RefCell;

use workbook::glam::Vec3;
use workbook::gpu::Offscreen;
use workbook::gpu::states::{self, Clip};
use workbook::lesson::mirror::StencilMirror;
use workbook::math::reflect::{Plane, reflection};
use workbook::room::camera::{Camera, TARGET, View};
use workbook::room::scene::{Drawable, FrameBinding, LIGHTS, mirror_plane};
use workbook::room::texture_mirror::TextureMirror;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Pass, Recipe, Scene};

use floor_mirror::{FloorMirror, floor_plane, sink_skull};

pub struct RenderToTexture {
    technique: Technique,
    plane: Plane,
    on_floor: bool,
    draw_room: wgpu::RenderPipeline,
    /// The room seen from the reflected camera, into the texture.
    pub draw_reflected_view: wgpu::RenderPipeline,
    reflected_camera: FrameBinding,
    texture_mirror: TextureMirror,
    texture: RefCell<Option<Offscreen>>,
    stencil_mirror: StencilMirror,
    knobs: Settings,
}

/// The knob values the frame reads.
struct Settings {
    resolution: &'static str,
    rastertek: bool,
    clip: bool,
    blend: f32,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Technique {
    RenderToTexture,
    Stencil,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "technique",
        values: &["render-to-texture", "stencil"],
        default: "render-to-texture",
        meaning: "the mirror from a texture rendered by a reflected camera, or lesson 8's stencil frame",
    },
    Knob {
        name: "resolution",
        values: &["full", "half", "quarter", "64"],
        default: "full",
        meaning: "the reflection texture's size: the frame's, half, a quarter, or 64 pixels wide",
    },
    Knob {
        name: "clip",
        values: &["on", "off"],
        default: "on",
        meaning: "whether the reflected camera's view is cut at the mirror's plane",
    },
    Knob {
        name: "camera",
        values: &["matrix", "rastertek"],
        default: "matrix",
        meaning: "the reflected camera: view · R (any plane), or Rastertek's y → 2h − y (floors only)",
    },
    Knob {
        name: "plane",
        values: &["floor", "wall"],
        default: "floor",
        meaning: "which mirror: lesson 8's stone in the floor, or the wall mirror",
    },
    Knob {
        name: "blend",
        values: &["0.15", "0.5", "1"],
        default: "0.5",
        meaning: "how much of the reflection is mixed over the surface (Rastertek: 0.15)",
    },
    floor_mirror::SINK,
];
// ANCHOR_END: knobs

impl Lesson for RenderToTexture {
    const NAME: &'static str = "render-to-texture";
    const TITLE: &'static str = "Lesson 9: the mirror as a texture";
    const KNOBS: &'static [Knob] = KNOBS;
    const CAMERA: Camera = FloorMirror::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        sink_skull(gpu, scene, knobs)?;
        let on_floor = knobs.get("plane") == "floor";
        let plane = if on_floor {
            floor_plane()
        } else {
            mirror_plane()
        };
        let rastertek = knobs.get("camera") == "rastertek";
        let clip = knobs.is_on("clip");
        let blend: f32 = knobs.get("blend").parse()?;
        // The stencil frame blends the surface over the reflection with the surface's alpha.
        surface(scene, on_floor).set_alpha(&gpu.queue, 1.0 - blend);
        let pipeline = |recipe: &Recipe| scene.pipeline(&gpu.device, recipe);
        let objects = reflected(scene, on_floor);
        Ok(Self {
            technique: match knobs.get("technique") {
                "stencil" => Technique::Stencil,
                _ => Technique::RenderToTexture,
            },
            plane,
            on_floor,
            draw_room: pipeline(&states::OPAQUE),
            draw_reflected_view: pipeline(&reflected_view_recipe(rastertek, clip)),
            reflected_camera: scene.frame_binding(&gpu.device, "reflected camera"),
            texture_mirror: TextureMirror::new(gpu, scene, &states::OPAQUE),
            texture: RefCell::new(None),
            stencil_mirror: StencilMirror::new(
                gpu,
                scene,
                (plane, &objects),
                if clip { Clip::Discard } else { Clip::None },
                // Behind the wall mirror lie the wall's own sides around it; under the floor, a
                // sunk skull.
                !on_floor || knobs.get("sink") != "0",
            ),
            knobs: Settings {
                resolution: knobs.get("resolution"),
                rastertek,
                clip,
                blend,
            },
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let (surface, objects) = (
            surface(scene, self.on_floor),
            reflected(scene, self.on_floor),
        );
        frame.clear();
        if self.technique == Technique::Stencil {
            frame.step("draw the room", |pass| self.draw_room(pass, scene));
            self.stencil_mirror.steps(frame, surface, &objects);
            return;
        }

        // The reflected camera, the clip plane at the mirror (keeping the room's side), and the
        // texture at the size the knob asks for.
        let camera = self.reflected_camera(&frame.view);
        let clip_plane = self.plane.as_vec4() * if self.knobs.clip { 1.0 } else { 0.0 };
        let queue = &frame.gpu.queue;
        self.reflected_camera
            .write(queue, &camera, &LIGHTS, clip_plane);
        self.texture_mirror.update(queue, &camera, self.knobs.blend);
        let texture = self.texture(frame);
        let texture = texture.as_ref().expect("made by texture()");

        // The room as the mirror sees it: from the reflected camera, into the texture.
        frame.step_into("render the reflection into a texture", texture, |pass| {
            pass.set_pipeline(&self.draw_reflected_view);
            self.reflected_camera.bind(pass);
            for object in objects {
                object.draw(pass);
            }
        });

        // The room as usual, all but the mirror's surface.
        frame.step("draw the room", |pass| self.draw_room(pass, scene));

        // The surface, each of its points looking up where it landed in the texture.
        let device = &frame.gpu.device;
        frame.step("draw the mirror with the texture", |pass| {
            self.texture_mirror.bind(device, pass, texture);
            surface.draw(pass);
        });
    }
    // ANCHOR_END: render
}

// ANCHOR: cameras
impl RenderToTexture {
    /// The camera the mirror sees the room from. `view · R` works for any plane: it is the camera's
    /// own view of the world reflected by R. Rastertek's moves the eye and the target to
    /// y → 2h − y and keeps y up — the same picture upside down, for a horizontal mirror at height
    /// h only.
    fn reflected_camera(&self, view: &View) -> View {
        if !self.knobs.rastertek {
            return view.reflected(reflection(self.plane));
        }
        let h = 0.0;
        let below = |p: Vec3| Vec3::new(p.x, 2.0 * h - p.y, p.z);
        View::look_at(below(view.eye), below(TARGET), Vec3::Y, view.projection)
    }
}
// ANCHOR_END: cameras

/// The reflected view's recipe. `view · R` has determinant −1, so the triangles facing the mirror
/// wind clockwise (lesson 5); Rastertek's camera is an ordinary one. Neither may test a stencil: the
/// texture has a stencil buffer of its own, cleared to 0.
pub fn reflected_view_recipe(rastertek: bool, clip: bool) -> Recipe {
    let recipe = if rastertek {
        states::OPAQUE
    } else {
        states::FRONT_CLOCKWISE
    };
    Recipe {
        name: "DRAW_REFLECTED_VIEW",
        stencil: states::NO_STENCIL,
        clip: if clip { Clip::Discard } else { Clip::None },
        ..recipe
    }
}

impl RenderToTexture {
    fn draw_room(&self, pass: &mut Pass<'_, '_>, scene: &Scene) {
        pass.set_pipeline(&self.draw_room);
        for object in room(scene, self.on_floor) {
            object.draw(pass);
        }
    }

    /// The reflection texture at the size the `resolution` knob asks for, made again when the
    /// frame's size changes.
    fn texture(&self, frame: &Frame<'_>) -> std::cell::Ref<'_, Option<Offscreen>> {
        let (width, height) = frame.size();
        let size = match self.knobs.resolution {
            "half" => (width / 2, height / 2),
            "quarter" => (width / 4, height / 4),
            "64" => (64, 64 * height / width),
            _ => (width, height),
        };
        let size = (size.0.max(1), size.1.max(1));
        if self.texture.borrow().as_ref().map(Offscreen::size) != Some(size) {
            let format = frame.scene.color_format;
            let texture = Offscreen::new(&frame.gpu.device, "reflection texture", format, size);
            *self.texture.borrow_mut() = Some(texture);
        }
        self.texture.borrow()
    }
}

/// The mirror's surface: the floor's stone, or the wall's glass.
fn surface(scene: &Scene, on_floor: bool) -> &Drawable {
    if on_floor {
        &scene.floor_mirror
    } else {
        &scene.mirror
    }
}

/// The room around the mirror's surface.
fn room(scene: &Scene, on_floor: bool) -> Vec<&Drawable> {
    if on_floor {
        let around = &scene.floor_around_mirror;
        vec![
            around,
            &scene.wall,
            &scene.mirror,
            &scene.crate_box,
            &scene.skull,
        ]
    } else {
        vec![&scene.floor, &scene.wall, &scene.crate_box, &scene.skull]
    }
}

/// What the mirror shows: the room's objects but the mirror's surface itself. (The wall lies behind
/// the wall mirror's plane: only clipping keeps it out of that mirror.)
pub fn reflected(scene: &Scene, on_floor: bool) -> Vec<&Drawable> {
    if on_floor {
        vec![&scene.skull, &scene.crate_box, &scene.wall, &scene.mirror]
    } else {
        vec![&scene.skull, &scene.crate_box, &scene.floor, &scene.wall]
    }
}
