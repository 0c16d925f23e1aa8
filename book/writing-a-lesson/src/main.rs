fn main() -> std::process::ExitCode {
    workbook::main::<my_lesson::MyLesson>()
}
