//! Every lesson on the other backend: every knob value renders on GL (Mesa's llvmpipe) with no wgpu
//! error, and each lesson's picture there agrees with Vulkan's by FLIP. GL cannot read the depth
//! buffer in a shader: `--show depth` says so in one line instead.

use workbook_tests::flip;
use workbook_tests::shots::{self, LESSONS, STRICT};

const SIZE: (u32, u32) = (160, 90);

#[test]
fn every_knob_value_renders_on_gl() {
    for lesson in LESSONS {
        let each = shots::every_knob_value(lesson).unwrap();
        shots::render_each(lesson, &each, |request| {
            (request.width, request.height) = (96, 54);
            request.backend = Some("gl".into());
        })
        .unwrap_or_else(|e| panic!("{lesson} on GL: {e:#}"));
    }
}

/// Measured with Mesa 22.3 at 160x90: every lesson's default picture on GL is Vulkan's to a FLIP
/// mean of at most 0.00013 (two-mirrors), with no pixel visibly different; the screenshot threshold
/// holds with room.
#[test]
fn gl_and_vulkan_draw_the_same_pictures() {
    for lesson in LESSONS {
        let render = |backend: &str| {
            shots::render(lesson, &[], |request| {
                (request.width, request.height) = SIZE;
                request.backend = Some(backend.into());
            })
            .unwrap_or_else(|e| panic!("{lesson} on {backend}: {e:#}"))
            .color
        };
        let comparison = flip::compare(&render("vulkan"), &render("gl")).unwrap();
        assert!(
            comparison.passes(STRICT),
            "{lesson}: {}",
            comparison.summary()
        );
    }
}

#[test]
fn gl_says_plainly_what_it_cannot_show() {
    let error = shots::render("depth-test", &[], |request| {
        (request.width, request.height) = SIZE;
        request.backend = Some("gl".into());
        request.show = workbook::Show::Depth;
    })
    .unwrap_err();
    assert!(
        format!("{error:#}").contains("GL backend cannot read the depth buffer"),
        "{error:#}"
    );
}
