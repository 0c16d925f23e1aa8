fn main() -> std::process::ExitCode {
    workbook::main::<two_mirrors::TwoMirrors>()
}
