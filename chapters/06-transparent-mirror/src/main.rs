fn main() -> std::process::ExitCode {
    workbook::main::<transparent_mirror::TransparentMirror>()
}
