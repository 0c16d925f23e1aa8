fn main() -> std::process::ExitCode {
    workbook::main::<outline::Outline>()
}
