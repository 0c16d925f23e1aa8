fn main() -> std::process::ExitCode {
    workbook::main::<mark_mirror::MarkMirror>()
}
