//! The `portal` binary as a learner runs it (bad input in general is tested once, on `depth-test`).

#[test]
fn the_binary_lists_renders_refuses_and_opens_a_window() {
    workbook::app::testing::check_lesson_binary(
        std::path::Path::new(env!("CARGO_BIN_EXE_portal")),
        &std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("portal-cli"),
    );
}
