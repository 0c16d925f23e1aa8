fn main() -> std::process::ExitCode {
    workbook::main::<depth_complexity::DepthComplexity>()
}
