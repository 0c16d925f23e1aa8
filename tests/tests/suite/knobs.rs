//! Every value of every knob of every lesson renders without a wgpu error.

use workbook_tests::shots::{self, LESSONS};

/// Every value of every knob, one knob at a time. Of the 256 values of a byte knob (a stencil
/// reference or mask) the test takes the ones at the edges and a few between: they all run the
/// same code, and 768 renders would cost minutes on a software GPU.
#[test]
fn every_knob_value_renders_cleanly() {
    for lesson in LESSONS {
        let each = shots::every_knob_value(lesson).unwrap();
        shots::render_each(lesson, &each, |request| {
            (request.width, request.height) = (96, 54);
        })
        .unwrap_or_else(|e| panic!("{lesson}: {e:#}"));
    }
}

#[test]
fn bad_knob_settings_are_refused_with_the_allowed_values() {
    let error = shots::render("depth-test", &["depth=sometimes"], |_| {}).unwrap_err();
    assert!(error.to_string().contains("less-equal"), "{error}");
    let error = shots::render("depth-test", &["stencil=on"], |_| {}).unwrap_err();
    assert!(error.to_string().contains("unknown knob"), "{error}");
}
