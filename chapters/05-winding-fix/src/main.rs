fn main() -> std::process::ExitCode {
    workbook::main::<winding_fix::WindingFix>()
}
