fn main() -> std::process::ExitCode {
    workbook::main::<portal::Portal>()
}
