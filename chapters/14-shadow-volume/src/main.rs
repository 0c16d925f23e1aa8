fn main() -> std::process::ExitCode {
    workbook::main::<shadow_volume::ShadowVolume>()
}
