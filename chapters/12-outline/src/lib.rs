//! Lesson 12: the outline.
//!
//! The selected skull is drawn marking its pixels in the stencil buffer; then a copy of it, grown
//! along its normals, is drawn where the mark is absent: only the band around the skull remains.
//! The mirror's mark and the selection share the buffer as two bits, 0b01 and 0b10, so the read and
//! write masks keep each test to its own bit — and the skull's image in the mirror is outlined too.

use workbook::glam::{Mat4, Vec3};
use workbook::gpu::states;
use workbook::room::scene::Placed;
use workbook::room::scene::mirror_reflection;
use workbook::wgpu::{self, CompareFunction, StencilFaceState, StencilOperation, StencilState};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Pass, Recipe, Scene, lesson::knobs};

pub mod screen_space;
use screen_space::ScreenSpace;

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "outline-stencil",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether the grown copy is drawn only where the selection bit is clear; off, it covers the skull",
    },
    Knob {
        name: "grow",
        values: &["normals", "scale"],
        default: "normals",
        meaning: "how the copy is made bigger: each vertex moved along its normal on the screen, or the skull scaled about its origin",
    },
    Knob {
        name: "masks",
        values: &["bits", "whole-byte"],
        default: "bits",
        meaning: "each test reads and writes its own bit (mirror 0b01, selection 0b10), or the whole byte",
    },
    Knob {
        name: "outline-depth",
        values: &["always", "less"],
        default: "always",
        meaning: "the outline's depth test: seen through whatever stands in front of the skull, or hidden by it",
    },
    Knob {
        name: "reflected-outline",
        values: knobs::ON_OFF,
        default: "on",
        meaning: "whether the skull's image in the mirror is outlined too",
    },
    Knob {
        name: "way",
        values: &["stencil", "screen-space"],
        default: "stencil",
        meaning: "the band as a grown copy where the selection bit is clear, or found on the screen around a mask of the selection",
    },
];
// ANCHOR_END: knobs

// ANCHOR: bits
/// The mirror's mark: bit 0 of the stencil value.
pub const MIRROR_BIT: u32 = 0b01;
/// The selection: bit 1. A pixel of the skull's image in the mirror holds both, 0b11.
pub const SELECTION_BIT: u32 = 0b10;
// ANCHOR_END: bits

/// The lesson's two shader entries, `vs_grown` and `fs_outline`, to append to the room's shader
/// ([`Scene::shader_with`]).
pub const SHADER: &str = include_str!("outline.wgsl");

/// How much bigger the scaled copy is (grow=scale): 10 %, so that its band is as wide as the
/// grown copy's where the skull is widest — and wider or missing elsewhere.
pub const SCALE: f32 = 1.1;

// ANCHOR: recipes
/// The stencil face state: test `compare` against the reference, and write the reference where the
/// fragment passes both tests (the write mask says which bits of it).
fn face(compare: CompareFunction, pass_op: StencilOperation) -> StencilFaceState {
    StencilFaceState {
        compare,
        fail_op: StencilOperation::Keep,
        depth_fail_op: StencilOperation::Keep,
        pass_op,
    }
}

/// Both faces alike, through these masks — or, with masks=whole-byte, through 0xff both.
fn stencil(face: StencilFaceState, read_mask: u32, write_mask: u32, bits: bool) -> StencilState {
    let (read_mask, write_mask) = match bits {
        true => (read_mask, write_mask),
        false => (0xff, 0xff),
    };
    StencilState {
        front: face,
        back: face,
        read_mask,
        write_mask,
    }
}

/// The lesson's recipes, for these knob values: what each step draws with.
pub struct Recipes {
    pub select: Recipe,
    pub mark_mirror: Recipe,
    pub draw_reflection: Recipe,
    pub outline_reflection: Recipe,
    pub outline: Recipe,
}

pub fn recipes(knobs: &Knobs) -> Recipes {
    use CompareFunction::{Always, Equal, NotEqual};
    use StencilOperation::{Keep, Replace};
    let bits = knobs.get("masks") == "bits";
    let outline_depth = match knobs.get("outline-depth") {
        "less" => CompareFunction::Less,
        _ => Always,
    };
    let outline_test = match knobs.is_on("outline-stencil") {
        true => NotEqual,
        false => Always,
    };
    Recipes {
        // The skull, drawn as usual, sets the selection bit (reference 0b10, write mask 0b10)
        // wherever it is, in front of what is there or behind it: the band goes round the whole
        // skull, also where the crate hides it.
        select: Recipe {
            name: "SELECT",
            stencil: stencil(
                StencilFaceState {
                    depth_fail_op: Replace,
                    ..face(Always, Replace)
                },
                0,
                SELECTION_BIT,
                bits,
            ),
            ..states::OPAQUE
        },
        // Lesson 3's mark, through write mask 0b01: it sets the mirror's bit, keeps the selection's.
        mark_mirror: Recipe {
            name: "MARK_MIRROR",
            stencil: stencil(face(Always, Replace), 0, MIRROR_BIT, bits),
            ..states::MARK_MIRROR
        },
        // The mirror image where the mirror's bit is set (read mask 0b01, reference 0b11), setting
        // the selection bit there too (write mask 0b10): 0b01 becomes 0b11.
        draw_reflection: Recipe {
            name: "DRAW_REFLECTION",
            stencil: stencil(face(Equal, Replace), MIRROR_BIT, SELECTION_BIT, bits),
            ..states::FRONT_CLOCKWISE
        },
        // The image's outline: where the mirror's bit is set and the selection's is not (read
        // mask 0b11, reference 0b01). Colour only.
        outline_reflection: Recipe {
            name: "OUTLINE_REFLECTION",
            depth_write: false,
            depth_compare: outline_depth,
            stencil: stencil(face(Equal, Keep), MIRROR_BIT | SELECTION_BIT, 0, bits),
            ..states::FRONT_CLOCKWISE
        },
        // The outline: wherever the stencil is not the selected skull in the room, 0b10 (read mask
        // 0b11: the skull's image, 0b11, is not it). Colour only.
        outline: Recipe {
            name: "OUTLINE",
            depth_write: false,
            depth_compare: outline_depth,
            stencil: stencil(
                face(outline_test, Keep),
                MIRROR_BIT | SELECTION_BIT,
                0,
                bits,
            ),
            ..states::OPAQUE
        },
    }
}
// ANCHOR_END: recipes

pub struct Outline {
    draw_room: wgpu::RenderPipeline,
    select: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
    draw_reflection: wgpu::RenderPipeline,
    draw_glass: wgpu::RenderPipeline,
    way: Way,
    reflected_outline: bool,
}

/// How the band is found (the knob `way`).
enum Way {
    /// A grown copy drawn where the selection bit is clear: OUTLINE_REFLECTION and OUTLINE, and
    /// with grow=scale the copy scaled about the skull's origin and its mirror image (with
    /// grow=normals the vertex shader grows the skull itself).
    Stencil {
        outline_reflection: wgpu::RenderPipeline,
        outline: wgpu::RenderPipeline,
        scaled: Option<[Placed; 2]>,
    },
    /// The selection drawn into a mask, and the band found around it on the screen.
    ScreenSpace(Box<ScreenSpace>),
}

impl Lesson for Outline {
    const NAME: &'static str = "outline";
    const TITLE: &'static str = "Lesson 12: the outline";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let recipes = recipes(knobs);
        let way = match knobs.get("way") {
            "screen-space" => Way::ScreenSpace(Box::new(ScreenSpace::new(gpu, scene))),
            _ => Way::stencil(gpu, scene, knobs, &recipes),
        };
        Ok(Self {
            draw_room: scene.pipeline(device, &states::OPAQUE),
            select: scene.pipeline(device, &recipes.select),
            mark_mirror: scene.pipeline(device, &recipes.mark_mirror),
            draw_reflection: scene.pipeline(device, &recipes.draw_reflection),
            draw_glass: scene.pipeline(device, &states::TRANSPARENT),
            way,
            reflected_outline: knobs.is_on("reflected-outline"),
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let skull = &scene.skull;
        frame.clear();
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            for object in [&scene.floor, &scene.wall, &scene.crate_box] {
                object.draw(pass);
            }
        });

        // The skull, drawn as usual, setting the selection bit: its pixels hold 0b10.
        frame.step("draw the skull, selected", |pass| {
            pass.set_pipeline(&self.select);
            pass.set_stencil_reference(SELECTION_BIT);
            skull.draw(pass);
        });

        // The mirror's visible pixels get the mirror's bit: 0b01.
        frame.step("mark the mirror", |pass| {
            pass.set_pipeline(&self.mark_mirror);
            pass.set_stencil_reference(MIRROR_BIT);
            scene.mirror.draw(pass);
        });

        // The skull's image where the mirror's bit is set, selected too: its pixels hold 0b11.
        frame.step("draw the skull's image, selected", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(MIRROR_BIT | SELECTION_BIT);
            scene.bind_reflected_frame(pass);
            skull.draw_reflected(pass);
        });

        // way=screen-space: the skull and its image drawn into a mask of their own.
        if let Way::ScreenSpace(screen_space) = &self.way {
            screen_space.draw_mask(frame);
        }

        // The band around the image, where the mirror holds 0b01.
        if self.reflected_outline {
            frame.step("outline the image", |pass| {
                self.way.outline(pass, scene, true)
            });
        }

        // The glass over all it shows (lesson 6).
        frame.step("draw the glass", |pass| {
            pass.set_pipeline(&self.draw_glass);
            scene.mirror.draw(pass);
        });

        // The band around the skull, wherever the stencil is not 0b10.
        frame.step("outline the skull", |pass| {
            self.way.outline(pass, scene, false)
        });
    }
    // ANCHOR_END: render
}

impl Way {
    fn stencil(gpu: &Gpu, scene: &Scene, knobs: &Knobs, recipes: &Recipes) -> Way {
        let device = &gpu.device;
        // ANCHOR: new
        // The grown copy's vertex shader and the outline's colour, beside the room's shader.
        let shader = scene.shader_with(device, "outline.wgsl", SHADER);
        let grow = knobs.get("grow") == "normals";
        let vertex = if grow { "vs_grown" } else { "vs_main" };
        let outline = |recipe| scene.pipeline_in(device, recipe, (&shader, vertex, "fs_outline"));
        let scaled = (!grow).then(|| {
            let world = scene.skull.world() * Mat4::from_scale(Vec3::splat(SCALE));
            let image = mirror_reflection() * world;
            [
                scene.placed(device, &scene.skull, world),
                scene.placed(device, &scene.skull, image),
            ]
        });
        // ANCHOR_END: new
        Way::Stencil {
            outline_reflection: outline(&recipes.outline_reflection),
            outline: outline(&recipes.outline),
            scaled,
        }
    }

    // ANCHOR: outline
    /// Draws the band around the skull, or around its image (`image`): the grown copy, or the
    /// mask's edge.
    fn outline(&self, pass: &mut Pass<'_, '_>, scene: &Scene, image: bool) {
        let skull = &scene.skull;
        match self {
            Way::ScreenSpace(screen_space) => screen_space.draw_edge(pass, image),
            // The skull's copy wherever the stencil is not 0b10 (OUTLINE).
            Way::Stencil {
                outline, scaled, ..
            } if !image => {
                pass.set_pipeline(outline);
                pass.set_stencil_reference(SELECTION_BIT);
                match scaled {
                    None => skull.draw(pass),
                    Some([copy, _]) => skull.draw_placed(pass, copy),
                }
            }
            // The image's copy where the stencil is 0b01 (OUTLINE_REFLECTION).
            Way::Stencil {
                outline_reflection,
                scaled,
                ..
            } => {
                pass.set_pipeline(outline_reflection);
                pass.set_stencil_reference(MIRROR_BIT);
                scene.bind_reflected_frame(pass);
                match scaled {
                    None => skull.draw_reflected(pass),
                    Some([_, copy]) => skull.draw_placed(pass, copy),
                }
            }
        }
    }
    // ANCHOR_END: outline
}
