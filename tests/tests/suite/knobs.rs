//! Every value of every knob of every lesson renders without a wgpu error.

use workbook_tests::shots::{self, LESSONS};

#[test]
fn every_knob_value_renders_cleanly() {
    for lesson in LESSONS {
        for knob in shots::knobs(lesson).unwrap() {
            for value in knob.values {
                let setting = format!("{}={value}", knob.name);
                shots::render(lesson, &[setting.as_str()], |request| {
                    (request.width, request.height) = (96, 54);
                })
                .unwrap_or_else(|e| panic!("{lesson} --set {setting}: {e:#}"));
            }
        }
    }
}

#[test]
fn bad_knob_settings_are_refused_with_the_allowed_values() {
    let error = shots::render("depth-test", &["depth=sometimes"], |_| {}).unwrap_err();
    assert!(error.to_string().contains("less-equal"), "{error}");
    let error = shots::render("depth-test", &["stencil=on"], |_| {}).unwrap_err();
    assert!(error.to_string().contains("unknown knob"), "{error}");
}
