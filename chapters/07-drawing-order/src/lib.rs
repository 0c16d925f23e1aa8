//! Lesson 7: the drawing order.
//!
//! The whole scene: opaque objects, a wire-fence crate and a pool of water (both see-through), the
//! mirror, and everything seen in it. Transparent objects write depth, so what is drawn before what
//! decides the picture. The order that works draws the mirror's world first (MKXJun's five steps).

use workbook::glam::Vec3;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene, Start, scene::Drawable, states};

pub struct DrawingOrder {
    draw_opaque: wgpu::RenderPipeline,
    draw_transparent: wgpu::RenderPipeline,
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
            draw_reflection: pipeline(&states::CULL_CLOCKWISE),
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
        let mut pass = frame.pass("drawing order", Start::Cleared);

        if self.mirror_first {
            // 1. Mark the mirror in the stencil buffer (nothing is drawn yet: all of it is marked).
            self.mark_mirror(&mut pass, scene);
            // 2. The mirror's world, opaque objects first, where the stencil is 1.
            // 3. Then its transparent objects, then the transparent mirror over all of it.
            self.draw_reflected_world(&mut pass, scene, &mirrored);
            // 4. The room's opaque objects: the depth test puts the crate and the skull in front
            //    of the mirror's world, where they belong.
            self.draw_opaque(&mut pass, scene, &opaque);
            // 5. The room's transparent objects, farthest first.
            self.draw_transparent(&mut pass, &transparent);
        } else {
            // order=luna: the room first, transparent objects included (they write depth) ...
            self.draw_opaque(&mut pass, scene, &opaque);
            self.draw_transparent(&mut pass, &transparent);
            // ... then the mirror: its mark fails wherever a transparent object wrote a nearer
            // depth, and there the mirror's world is never drawn.
            self.mark_mirror(&mut pass, scene);
            self.draw_reflected_world(&mut pass, scene, &mirrored);
        }
    }
    // ANCHOR_END: render
}

// ANCHOR: steps
impl DrawingOrder {
    /// MARK_MIRROR: 1 into the stencil wherever the mirror passes the depth test.
    fn mark_mirror(&self, pass: &mut wgpu::RenderPass<'_>, scene: &Scene) {
        pass.set_pipeline(&self.mark_mirror);
        pass.set_stencil_reference(1);
        scene.mirror.draw(pass);
    }

    /// The mirror images where the stencil holds 1 — opaque, then transparent — lit by reflected
    /// lights, and the mirror's glass blended over them.
    fn draw_reflected_world(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        scene: &Scene,
        world: &MirrorWorld<'_>,
    ) {
        scene.bind_reflected_frame(pass);
        pass.set_pipeline(&self.draw_reflection);
        for object in world.opaque {
            object.draw_reflected(pass);
        }
        pass.set_pipeline(&self.draw_reflected_transparent);
        for object in world.transparent {
            object.draw_reflected(pass);
        }
        scene.bind_frame(pass);
        pass.set_pipeline(&self.draw_mirror);
        scene.mirror.draw(pass);
    }

    fn draw_opaque(&self, pass: &mut wgpu::RenderPass<'_>, scene: &Scene, opaque: &[&Drawable]) {
        scene.bind_frame(pass);
        pass.set_pipeline(&self.draw_opaque);
        for object in opaque {
            object.draw(pass);
        }
    }

    fn draw_transparent(&self, pass: &mut wgpu::RenderPass<'_>, transparent: &[&Drawable]) {
        pass.set_pipeline(&self.draw_transparent);
        for object in transparent {
            object.draw(pass);
        }
    }
}
// ANCHOR_END: steps

/// The objects the mirror shows, to be drawn reflected.
struct MirrorWorld<'a> {
    opaque: [&'a Drawable; 3],
    /// Farthest first, by where their mirror images stand.
    transparent: [&'a Drawable; 2],
}

/// Transparent objects sorted farthest from the camera first, so each is blended over what lies
/// behind it; `position` says where an object stands (itself, or its mirror image).
fn farthest_first<'a, const N: usize>(
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
