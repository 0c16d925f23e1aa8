fn main() -> std::process::ExitCode {
    workbook::main::<planar_shadow::PlanarShadow>()
}
