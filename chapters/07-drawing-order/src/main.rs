fn main() -> std::process::ExitCode {
    workbook::main::<drawing_order::DrawingOrder>()
}
