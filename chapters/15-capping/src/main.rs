fn main() -> std::process::ExitCode {
    workbook::main::<capping::Capping>()
}
