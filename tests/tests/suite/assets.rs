//! The generator makes the committed assets byte for byte: nothing in assets/ is edited by hand.

#[test]
fn regenerating_the_assets_gives_identical_files() {
    let dir = workbook_tests::workspace().join("assets");
    let files = asset_generator::generate_all().unwrap();
    assert!(!files.is_empty());
    for (name, bytes) in files {
        let committed = std::fs::read(dir.join(name))
            .unwrap_or_else(|e| panic!("assets/{name} is missing ({e}): run `cargo assets`"));
        assert!(
            committed == bytes,
            "assets/{name} differs from what the generator makes: run `cargo assets` and commit"
        );
    }
}
