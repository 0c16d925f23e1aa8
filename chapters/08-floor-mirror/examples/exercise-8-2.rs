//! Lesson 8, exercise 2: stand the wire-fence crate on the stone (it is at `FENCE_CENTRE`, over the
//! stone's left end): draw it in the room and its mirror image in the floor, with the recipes for
//! see-through objects, in an order that blends each over what lies behind it.

use floor_mirror::{FloorMirror, floor_plane, reflected, room};
use workbook::gpu::states::{self, Clip};
use workbook::room::camera::Camera;
use workbook::room::mirror_world::MirrorWorld;
use workbook::wgpu;
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    draw_room: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
    draw_reflection: wgpu::RenderPipeline,
    draw_reflected_fence: wgpu::RenderPipeline,
    draw_stone: wgpu::RenderPipeline,
    draw_fence: wgpu::RenderPipeline,
    mirror_world: MirrorWorld,
}

impl Lesson for Solution {
    const NAME: &'static str = "floor-mirror-exercise-2";
    const TITLE: &'static str = "Lesson 8, exercise 2: the wire-fence crate on the stone";
    /// The stencil recipe, clipped by discarding: the lesson's defaults.
    const KNOBS: &'static [Knob] = &[];
    const CAMERA: Camera = FloorMirror::CAMERA;

    fn new(gpu: &Gpu, scene: &Scene, _knobs: &Knobs) -> anyhow::Result<Self> {
        let knobs = Knobs::defaults(floor_mirror::KNOBS);
        let pipeline = |recipe: &Recipe| scene.pipeline(&gpu.device, recipe);
        let mut objects = reflected(scene).to_vec();
        objects.push(&scene.fence_box);
        Ok(Self {
            draw_room: pipeline(&states::OPAQUE),
            mark_mirror: pipeline(&states::MARK_MIRROR),
            draw_reflection: pipeline(&floor_mirror::draw_reflection(&knobs)),
            // Both sides, blended, where the mark is, cut at the floor.
            draw_reflected_fence: pipeline(&Recipe {
                clip: Clip::Discard,
                ..states::REFLECTED_TRANSPARENT
            }),
            draw_stone: pipeline(&states::BLEND_OVER_MARK),
            draw_fence: pipeline(&states::TRANSPARENT_NO_CULL),
            mirror_world: MirrorWorld::new(gpu, scene, floor_plane(), &objects),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        self.mirror_world.update(frame, false);
        frame.clear();
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            room(scene).iter().for_each(|object| object.draw(pass));
        });
        frame.step("mark the floor mirror", |pass| {
            pass.set_pipeline(&self.mark_mirror);
            pass.set_stencil_reference(1);
            scene.floor_mirror.draw(pass);
        });
        frame.step("draw the reflection", |pass| {
            pass.set_pipeline(&self.draw_reflection);
            pass.set_stencil_reference(1);
            self.mirror_world.bind(pass);
            for object in reflected(scene) {
                self.mirror_world.draw(pass, object);
            }
        });
        // ANCHOR: solution
        // The fence's image after the opaque images behind it, before the stone over both.
        frame.step("reflect the wire-fence crate", |pass| {
            pass.set_pipeline(&self.draw_reflected_fence);
            pass.set_stencil_reference(1);
            self.mirror_world.bind(pass);
            self.mirror_world.draw(pass, &scene.fence_box);
        });
        frame.step("draw the stone", |pass| {
            pass.set_pipeline(&self.draw_stone);
            pass.set_stencil_reference(1);
            scene.floor_mirror.draw(pass);
        });
        // The fence itself last, over the finished stone.
        frame.step("draw the wire-fence crate", |pass| {
            pass.set_pipeline(&self.draw_fence);
            scene.fence_box.draw(pass);
        });
        // ANCHOR_END: solution
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
