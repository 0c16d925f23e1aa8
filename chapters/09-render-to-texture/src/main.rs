fn main() -> std::process::ExitCode {
    workbook::main::<render_to_texture::RenderToTexture>()
}
