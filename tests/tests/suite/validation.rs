//! A wgpu validation error fails the render that caused it — and only that one, although every
//! headless render in the process shares one device.

use workbook::app::headless::{self, Request};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Scene, gpu::states, wgpu};

/// A lesson with a bug: it draws without binding the object's bind group or vertex buffer.
struct Broken(wgpu::RenderPipeline);

impl Lesson for Broken {
    const NAME: &'static str = "broken";
    const TITLE: &'static str = "a lesson with a bug";
    const KNOBS: &'static [Knob] = &[];

    fn new(gpu: &Gpu, scene: &Scene, _: &Knobs) -> anyhow::Result<Self> {
        Ok(Self(scene.pipeline(&gpu.device, &states::OPAQUE)))
    }

    fn render(&self, frame: &mut Frame<'_>) {
        frame.clear();
        frame.step("draw without a vertex buffer", |pass| {
            pass.set_pipeline(&self.0);
            pass.draw(0..3, 0..1);
        });
    }
}

#[test]
fn a_validation_error_fails_the_render() {
    let mut request = Request::new::<Broken>(&[] as &[&str]).unwrap();
    (request.width, request.height) = (64, 36);
    let error = headless::render::<Broken>(&request).unwrap_err();
    assert!(
        error.to_string().contains("wgpu reported an error"),
        "{error:#}"
    );
    // The shared device carries on: the next, correct render passes.
    workbook_tests::shots::render("depth-test", &[], |r| (r.width, r.height) = (64, 36)).unwrap();
}
