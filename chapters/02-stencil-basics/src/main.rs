fn main() -> std::process::ExitCode {
    workbook::main::<stencil_basics::StencilBasics>()
}
