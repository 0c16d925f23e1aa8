fn main() -> std::process::ExitCode {
    workbook::main::<reflect_skull::ReflectSkull>()
}
