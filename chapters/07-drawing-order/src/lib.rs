//! Lesson 7: the drawing order.
//!
//! The whole scene: opaque objects, a wire-fence crate and a pool of water (both see-through), the
//! mirror, and everything seen in it. Transparent objects write depth, so what is drawn before what
//! decides the picture. The order that works draws the mirror's world first (MKXJun's five steps).

use workbook::glam::Vec3;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene, gpu::states, room::scene::Drawable};

pub struct DrawingOrder {
    draw_opaque: wgpu::RenderPipeline,
    pub draw_transparent: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
    draw_reflection: wgpu::RenderPipeline,
    draw_reflected_transparent: wgpu::RenderPipeline,
    draw_mirror: wgpu::RenderPipeline,
    mirror_first: bool,
}

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[Knob {
    name: "order",
    values: &["mirror-first", "luna"],
    default: "mirror-first",
    meaning: "draw the mirror's world first (MKXJun), or the room first and the mirror last (Luna)",
}];
// ANCHOR_END: knobs

impl Lesson for DrawingOrder {
    const NAME: &'static str = "drawing-order";
    const TITLE: &'static str = "Lesson 7: the drawing order";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let pipeline = |recipe| scene.pipeline(&gpu.device, recipe);
        Ok(Self {
            draw_opaque: pipeline(&states::OPAQUE),
            draw_transparent: pipeline(&states::TRANSPARENT_NO_CULL),
            mark_mirror: pipeline(&states::MARK_MIRROR),
            draw_reflection: pipeline(&states::FRONT_CLOCKWISE),
            draw_reflected_transparent: pipeline(&states::REFLECTED_TRANSPARENT),
            draw_mirror: pipeline(&states::TRANSPARENT),
            mirror_first: knobs.get("order") == "mirror-first",
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        let opaque = [&scene.floor, &scene.wall, &scene.crate_box, &scene.skull];
        let transparent = [&scene.fence_box, &scene.water];
        // The mirror's world: what stands in front of the mirror. (The wall is behind its plane.)
        let mirrored = MirrorWorld {
            opaque: [&scene.floor, &scene.crate_box, &scene.skull],
            transparent: farthest_first(frame, transparent, Drawable::reflected_centre),
        };
        let transparent = farthest_first(frame, transparent, Drawable::centre);
        frame.clear();

        if self.mirror_first {
            // MKXJun's five steps. Mark the mirror in the stencil buffer (nothing is drawn yet:
            // all of it is marked).
            self.mark_mirror(frame);
            // The mirror's world where the stencil is 1: its opaque objects, then its transparent
            // ones, then the transparent mirror over all of it.
            self.draw_reflected_world(frame, &mirrored);
            // The room's opaque objects: the depth test puts the crate and the skull in front of
            // the mirror's world, where they belong.
            self.draw_opaque(frame, &opaque);
            // The room's transparent objects, farthest first.
            self.draw_transparent(frame, &transparent);
        } else {
            // order=luna: the room first, transparent objects included (they write depth) ...
            self.draw_opaque(frame, &opaque);
            self.draw_transparent(frame, &transparent);
            // ... then the mirror: its mark fails wherever a transparent object wrote a nearer
            // depth, and there the mirror's world is never drawn.
            self.mark_mirror(frame);
            self.draw_reflected_world(frame, &mirrored);
        }
    }
    // ANCHOR_END: render
}

// ANCHOR: steps
impl DrawingOrder {
    /// MARK_MIRROR: 1 into the stencil wherever the mirror passes the depth test.
    pub fn mark_mirror(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.step("mark the mirror", |pass| {
            pass.set_pipeline(&self.mark_mirror);
            pass.set_stencil_reference(1);
            scene.mirror.draw(pass);
        });
    }

    /// The mirror images where the stencil holds 1 — opaque, then transparent — lit by reflected
    /// lights, and the mirror's glass blended over them.
    pub fn draw_reflected_world(&self, frame: &mut Frame<'_>, world: &MirrorWorld<'_>) {
        let scene = frame.scene;
        frame.step("reflect the opaque objects", |pass| {
            scene.bind_reflected_frame(pass);
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            for object in world.opaque {
                object.draw_reflected(pass);
            }
        });
        frame.step("reflect the transparent objects", |pass| {
            scene.bind_reflected_frame(pass);
            pass.set_pipeline(&self.draw_reflected_transparent);
            pass.set_stencil_reference(1);
            for object in world.transparent {
                object.draw_reflected(pass);
            }
        });
        frame.step("draw the glass", |pass| {
            pass.set_pipeline(&self.draw_mirror);
            scene.mirror.draw(pass);
        });
    }

    pub fn draw_opaque(&self, frame: &mut Frame<'_>, opaque: &[&Drawable]) {
        frame.step("draw the opaque objects", |pass| {
            pass.set_pipeline(&self.draw_opaque);
            for object in opaque {
                object.draw(pass);
            }
        });
    }

    pub fn draw_transparent(&self, frame: &mut Frame<'_>, transparent: &[&Drawable]) {
        frame.step("draw the transparent objects", |pass| {
            pass.set_pipeline(&self.draw_transparent);
            for object in transparent {
                object.draw(pass);
            }
        });
    }
}
// ANCHOR_END: steps

/// The objects the mirror shows, to be drawn reflected.
pub struct MirrorWorld<'a> {
    pub opaque: [&'a Drawable; 3],
    /// Farthest first, by where their mirror images stand.
    pub transparent: [&'a Drawable; 2],
}

/// Transparent objects sorted farthest from the camera first, so each is blended over what lies
/// behind it; `position` says where an object stands (itself, or its mirror image).
pub fn farthest_first<'a, const N: usize>(
    frame: &Frame<'_>,
    mut objects: [&'a Drawable; N],
    position: fn(&Drawable) -> Vec3,
) -> [&'a Drawable; N] {
    let eye = frame.camera.eye();
    objects.sort_by(|a, b| {
        position(b)
            .distance(eye)
            .total_cmp(&position(a).distance(eye))
    });
    objects
}
