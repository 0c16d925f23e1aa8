fn main() -> std::process::ExitCode {
    workbook::main::<floor_mirror::FloorMirror>()
}
