//! What a mirror costs, measured: every lesson (and the knob values that change the work) rendered
//! headless, frame after frame, with the GPU time of each step from timestamp queries, the CPU time
//! to record and submit a frame, frames per second and peak memory. `cargo bench-lessons` prints the
//! table and writes the CSV and the plot the book's cost page shows.

use std::fmt::Write as _;

use anyhow::{Context, Result, bail};
use workbook::Lesson;
use workbook::app::headless::{FrameTiming, Headless, Request};
use workbook::gpu::timing::StepTimer;
use workbook::room::scene::DEFAULT_ANISOTROPY;

use crate::shots::{ForLesson, LESSONS, for_lesson};

/// One thing to measure: a lesson with knob settings, its textures filtered with `anisotropy`.
#[derive(Clone, Copy)]
pub struct Case {
    pub lesson: &'static str,
    pub settings: &'static [&'static str],
    pub anisotropy: u16,
}

/// A lesson with knob settings and the default filtering.
pub const fn case(lesson: &'static str, settings: &'static [&'static str]) -> Case {
    Case {
        lesson,
        settings,
        anisotropy: DEFAULT_ANISOTROPY,
    }
}

impl Case {
    /// The knobs as `--set` takes them, and `--anisotropy` where it is not the default.
    pub fn label(&self) -> String {
        let mut parts: Vec<String> = self.settings.iter().map(|s| s.to_string()).collect();
        if self.anisotropy != DEFAULT_ANISOTROPY {
            parts.push(format!("--anisotropy {}", self.anisotropy));
        }
        parts.join(" ")
    }
}

/// Every lesson ([`LESSONS`], in the book's order) with its default knobs, each followed by its
/// [`VARIANTS`].
pub fn cases() -> Vec<Case> {
    let mut cases = Vec::new();
    for lesson in LESSONS {
        let variants = VARIANTS.iter().filter(|c| c.lesson == *lesson);
        if !variants.clone().any(|c| c.label().is_empty()) {
            cases.push(case(lesson, &[]));
        }
        cases.extend(variants);
    }
    cases
}

/// The knob values that change a lesson's work, measured besides its defaults; lesson 1 and the
/// whole mirror scene (lesson 7) also with cheaper texture filtering, which is most of a software
/// GPU's time. A lesson's defaults are measured first, unless listed here among its variants
/// (two-mirrors' default depth, 3, in its place among the depths).
pub const VARIANTS: &[Case] = &[
    Case {
        anisotropy: 1,
        ..case("depth-test", &[])
    },
    Case {
        anisotropy: 2,
        ..case("depth-test", &[])
    },
    Case {
        anisotropy: 4,
        ..case("depth-test", &[])
    },
    Case {
        anisotropy: 1,
        ..case("drawing-order", &[])
    },
    case("render-to-texture", &["resolution=half"]),
    case("render-to-texture", &["resolution=quarter"]),
    case("render-to-texture", &["technique=stencil"]),
    case("planar-shadow", &["reflect-shadow=off"]),
    case("two-mirrors", &["depth=0"]),
    case("two-mirrors", &["depth=1"]),
    case("two-mirrors", &["depth=2"]),
    case("two-mirrors", &[]),
    case("two-mirrors", &["depth=4"]),
    case("two-mirrors", &["depth=5"]),
    case("two-mirrors", &["depth=6"]),
    case("outline", &["reflected-outline=off"]),
    case("outline", &["grow=scale"]),
    case("outline", &["way=screen-space"]),
    case("depth-complexity", &["count=passed-depth"]),
    case("depth-complexity", &["way=blend"]),
    case("shadow-volume", &["faces=two-passes"]),
    case("shadow-volume", &["method=z-pass"]),
    case("shadow-volume", &["caps=off"]),
    case("capping", &["count=invert"]),
    case("capping", &["crate=through"]),
    case("portal", &["depth=1"]),
    case("portal", &["clip=oblique"]),
    case("portal", &["clip=off"]),
];

/// How to measure.
#[derive(Debug, Clone)]
pub struct Plan {
    pub sizes: Vec<(u32, u32)>,
    pub warm_up: usize,
    pub frames: usize,
    /// Only the lessons' default knobs.
    pub defaults_only: bool,
}

/// Medians and spread of one case at one size.
#[derive(Debug, Clone)]
pub struct Measured {
    pub lesson: &'static str,
    pub settings: String,
    pub size: (u32, u32),
    pub adapter: String,
    /// Per step: name, and the median, 10th and 90th percentile of its GPU time in ms.
    pub steps: Vec<(&'static str, [f64; 3])>,
    /// Whole-frame GPU time (the steps summed), CPU record+submit in µs, frame wall time in ms.
    pub gpu_ms: Option<[f64; 3]>,
    pub cpu_us: [f64; 3],
    /// Of the CPU time, the submission's (the driver's share, mostly), µs.
    pub submit_us: [f64; 3],
    pub frame_ms: [f64; 3],
    /// GPU memory the lesson's device holds after its frames (its allocator's report: textures,
    /// buffers, targets), MiB; `None` where the backend gives no report (GL).
    pub gpu_memory_mib: Option<f64>,
    /// The CPU's record+submit time in µs and the frame's wall time in ms with the frame's steps
    /// in one render pass (as a screenshot records it), no timestamps.
    pub one_pass_cpu_us: [f64; 3],
    pub one_pass_frame_ms: [f64; 3],
}

impl Measured {
    pub fn fps(&self) -> f64 {
        1000.0 / self.frame_ms[0]
    }
}

/// Measures one case.
pub fn measure(case: &Case, size: (u32, u32), plan: &Plan) -> Result<Measured> {
    struct Run<'a>(&'a Case, (u32, u32), &'a Plan);
    impl ForLesson for Run<'_> {
        type Output = Result<Measured>;
        fn run<L: Lesson>(self) -> Self::Output {
            let Run(case, size, plan) = self;
            let mut request = Request::new::<L>(case.settings)?;
            (request.width, request.height) = size;
            request.scene.anisotropy = case.anisotropy;
            let headless = Headless::<L>::new(&request)?;
            // The measured frames after the warm-up ones.
            let run = |timer: Option<&StepTimer>| -> Result<Vec<FrameTiming>> {
                let frames = (0..plan.warm_up + plan.frames).map(|_| headless.timed_frame(timer));
                Ok(frames.collect::<Result<Vec<_>>>()?.split_off(plan.warm_up))
            };
            let timer = headless.timer();
            let frames = run(timer.as_ref())?;
            // The same frames recorded as a screenshot or the window without its panel records
            // them: every step in one render pass, no timestamps.
            let one_pass = run(None)?;
            let steps = frames[0].steps.clone();
            let gpu_memory_mib = headless
                .device()
                .generate_allocator_report()
                .map(|report| report.total_allocated_bytes as f64 / (1024.0 * 1024.0));
            let gpu = |pick: &dyn Fn(&[f64]) -> f64| -> Option<Vec<f64>> {
                frames
                    .iter()
                    .map(|f| f.gpu_ms.as_deref().map(pick))
                    .collect()
            };
            let step_times = (0..steps.len())
                .map(|i| {
                    let times = gpu(&|ms: &[f64]| ms.get(i).copied().unwrap_or(0.0));
                    (steps[i], times.map_or([0.0; 3], |t| spread(&t)))
                })
                .collect();
            let totals = gpu(&|ms: &[f64]| ms.iter().sum());
            let info = headless.device_info();
            Ok(Measured {
                lesson: case.lesson,
                settings: case.label(),
                size,
                adapter: info,
                steps: step_times,
                gpu_ms: totals.map(|t| spread(&t)),
                cpu_us: spread_of(&frames, |f| micros(f.record_and_submit)),
                submit_us: spread_of(&frames, |f| micros(f.submit)),
                frame_ms: spread_of(&frames, |f| millis(f.frame)),
                gpu_memory_mib,
                one_pass_cpu_us: spread_of(&one_pass, |f| micros(f.record_and_submit)),
                one_pass_frame_ms: spread_of(&one_pass, |f| millis(f.frame)),
            })
        }
    }
    for_lesson(case.lesson, Run(case, size, plan))?
        .with_context(|| format!("{} {}", case.lesson, case.label()))
}

/// The window's panel, measured: a lesson's window frame drawn by the workbench into a texture
/// (the window's own code, without a display: a real GPU's machine has none), with the panel and
/// with it hidden (`H`), each frame waited for as a window waits for the display.
#[derive(Debug, Clone)]
pub struct PanelCost {
    pub lesson: &'static str,
    pub size: (u32, u32),
    pub adapter: String,
    /// Wall time per frame in ms, median, 10th and 90th percentile: the lesson alone, and with
    /// the panel.
    pub without: [f64; 3],
    pub with: [f64; 3],
    /// The process's CPU time per frame, all its threads, in ms: the lesson alone and with the
    /// panel. On a software GPU this is the GPU's work too, and steadier than wall time on a busy
    /// machine. Where the system does not say (not Linux), `None`.
    pub cpu: Option<(f64, f64)>,
    /// The CPU's time to build, record and submit the frame (the median, ms): the lesson alone,
    /// and with the panel (egui's layout and painting included).
    pub recorded: (f64, f64),
}

/// The CPU time this process's threads have used so far, in ms (Linux: each thread's
/// `/proc/self/task/*/schedstat`, in nanoseconds; threads that ended are not counted, and the
/// software GPU's threads live as long as the process).
fn process_cpu_ms() -> Option<f64> {
    let mut total_ns = 0u64;
    for task in std::fs::read_dir("/proc/self/task").ok()? {
        let stat = std::fs::read_to_string(task.ok()?.path().join("schedstat")).ok()?;
        total_ns += stat.split_whitespace().next()?.parse::<u64>().ok()?;
    }
    Some(total_ns as f64 / 1e6)
}

impl PanelCost {
    /// What the panel adds, as a share of the frame without it.
    pub fn added(&self) -> f64 {
        self.with[0] / self.without[0] - 1.0
    }
}

/// Measures the panel's cost in one lesson (default knobs).
pub fn measure_panel(lesson: &'static str, size: (u32, u32), plan: &Plan) -> Result<PanelCost> {
    struct Run<'a>(&'static str, (u32, u32), &'a Plan);
    impl ForLesson for Run<'_> {
        type Output = Result<PanelCost>;
        fn run<L: Lesson>(self) -> Self::Output {
            use workbook::app::args::Args;
            use workbook::app::workbench::headless::HeadlessWorkbench;
            let Run(lesson, size, plan) = self;
            let size_arg = format!("{}x{}", size.0, size.1);
            // At full resolution on every adapter: the panel's cost is measured on the frame the
            // lesson draws in a screenshot, not on a software GPU's quarter of it.
            let arguments = [L::NAME, "--size", &size_arg, "--resolution", "full"];
            let args = Args::parse_for::<L>(arguments)?;
            let mut bench = HeadlessWorkbench::<L>::new(&args)?;
            // The panel compares the view with the book's picture when they match: a thread of
            // its own, once. Warm up until it is done, and both ways.
            let mut warm_up = 0;
            while warm_up < plan.warm_up || bench.workbench.comparing() {
                bench.set_panel(warm_up % 2 == 1);
                bench.frame()?;
                warm_up += 1;
            }
            // Then in rounds, the lesson alone and with the panel taking turns, so that a machine
            // busier at one moment than at another weighs on both alike. The first frames after
            // a turn resize the view: not counted.
            const ROUNDS: usize = 4;
            const SETTLE: usize = 2;
            let (mut times, mut cpu) = ([Vec::new(), Vec::new()], [Some(0.0); 2]);
            let mut recorded = [Vec::new(), Vec::new()];
            for _ in 0..ROUNDS {
                for (shown, ((times, cpu), recorded)) in times
                    .iter_mut()
                    .zip(&mut cpu)
                    .zip(&mut recorded)
                    .enumerate()
                {
                    bench.set_panel(shown == 1);
                    for _ in 0..SETTLE {
                        bench.frame()?;
                    }
                    let cpu_from = process_cpu_ms();
                    for _ in 0..plan.frames.div_ceil(ROUNDS) {
                        let start = std::time::Instant::now();
                        recorded.push(bench.frame()?);
                        times.push(start.elapsed().as_secs_f64() * 1e3);
                    }
                    let used = cpu_from.zip(process_cpu_ms()).map(|(from, to)| to - from);
                    *cpu = cpu.zip(used).map(|(sum, used)| sum + used);
                }
            }
            let per_frame =
                |total: Option<f64>, times: &Vec<f64>| total.map(|t| t / times.len() as f64);
            let (without, with) = (spread(&times[0]), spread(&times[1]));
            let (cpu_without, cpu_with) =
                (per_frame(cpu[0], &times[0]), per_frame(cpu[1], &times[1]));
            let info = bench.runner.gpu.adapter.get_info();
            Ok(PanelCost {
                lesson,
                size,
                adapter: format!("{} ({:?}, {})", info.name, info.backend, info.driver_info),
                without,
                with,
                cpu: cpu_without.zip(cpu_with),
                recorded: (spread(&recorded[0])[0], spread(&recorded[1])[0]),
            })
        }
    }
    for_lesson(lesson, Run(lesson, size, plan))?.with_context(|| format!("{lesson} with its panel"))
}

/// The panel's table: one line per lesson.
pub fn panel_table(results: &[PanelCost]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<20} {:>9} {:>9} {:>9} {:>6} {:>11} {:>11} {:>11} {:>11}",
        "lesson",
        "size",
        "alone ms",
        "panel ms",
        "added",
        "CPU alone",
        "CPU panel",
        "rec. alone",
        "rec. panel"
    );
    for m in results {
        let cpu = match m.cpu {
            Some((alone, with)) => format!("{alone:>11.2} {with:>11.2}"),
            None => format!("{:>11} {:>11}", "n/a", "n/a"),
        };
        let _ = writeln!(
            out,
            "{:<20} {:>9} {:>9.2} {:>9.2} {:>5.0}% {cpu} {:>11.3} {:>11.3}",
            m.lesson,
            format!("{}x{}", m.size.0, m.size.1),
            m.without[0],
            m.with[0],
            m.added() * 100.0,
            m.recorded.0,
            m.recorded.1
        );
    }
    out
}

/// The panel's CSV header: one row per lesson.
pub const PANEL_CSV_HEADER: &str = "adapter,lesson,width,height,alone_ms_median,alone_ms_p10,alone_ms_p90,panel_ms_median,panel_ms_p10,panel_ms_p90,added,cpu_alone_ms,cpu_panel_ms,record_alone_ms,record_panel_ms";

pub fn panel_csv(results: &[PanelCost]) -> String {
    let mut out = format!("{PANEL_CSV_HEADER}\n");
    for m in results {
        let _ = writeln!(
            out,
            "\"{}\",{},{},{},{:.3},{:.3},{:.3},{:.3},{:.3},{:.3},{:.3},{},{},{:.4},{:.4}",
            m.adapter,
            m.lesson,
            m.size.0,
            m.size.1,
            m.without[0],
            m.without[1],
            m.without[2],
            m.with[0],
            m.with[1],
            m.with[2],
            m.added(),
            m.cpu.map_or(String::new(), |c| format!("{:.2}", c.0)),
            m.cpu.map_or(String::new(), |c| format!("{:.2}", c.1)),
            m.recorded.0,
            m.recorded.1,
        );
    }
    out
}

/// Median, 10th and 90th percentile.
pub fn spread(values: &[f64]) -> [f64; 3] {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let at = |q: f64| sorted[((sorted.len() - 1) as f64 * q).round() as usize];
    [at(0.5), at(0.1), at(0.9)]
}

/// The median, 10th and 90th percentile of one figure of these frames.
fn spread_of(frames: &[FrameTiming], figure: impl Fn(&FrameTiming) -> f64) -> [f64; 3] {
    spread(&frames.iter().map(figure).collect::<Vec<_>>())
}

fn micros(time: std::time::Duration) -> f64 {
    time.as_secs_f64() * 1e6
}

fn millis(time: std::time::Duration) -> f64 {
    time.as_secs_f64() * 1e3
}

/// The CSV's header: one row per case, size and step (the step `frame` is the whole frame).
pub const CSV_HEADER: &str = "adapter,lesson,settings,width,height,step,gpu_ms_median,gpu_ms_p10,gpu_ms_p90,cpu_us_median,submit_us_median,frame_ms_median,fps,gpu_memory_mib,one_pass_cpu_us_median,one_pass_frame_ms_median";

pub fn csv(results: &[Measured]) -> String {
    let mut out = format!("{CSV_HEADER}\n");
    for m in results {
        let row = |step: &str, gpu: [f64; 3]| {
            format!(
                "\"{}\",{},\"{}\",{},{},\"{step}\",{:.4},{:.4},{:.4},{:.1},{:.1},{:.3},{:.1},{:.1},{:.1},{:.3}\n",
                m.adapter,
                m.lesson,
                m.settings,
                m.size.0,
                m.size.1,
                gpu[0],
                gpu[1],
                gpu[2],
                m.cpu_us[0],
                m.submit_us[0],
                m.frame_ms[0],
                m.fps(),
                m.gpu_memory_mib.unwrap_or(f64::NAN),
                m.one_pass_cpu_us[0],
                m.one_pass_frame_ms[0]
            )
        };
        for (step, gpu) in &m.steps {
            out += &row(step, *gpu);
        }
        out += &row("frame", m.gpu_ms.unwrap_or([f64::NAN; 3]));
    }
    out
}

/// The table the terminal shows: one line per case and size.
pub fn table(results: &[Measured]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<20} {:<22} {:>9} {:>8} {:>8} {:>9} {:>9} {:>8} {:>8} {:>10} {:>10}",
        "lesson",
        "knobs",
        "size",
        "GPU ms",
        "CPU µs",
        "submit µs",
        "frame ms",
        "frames/s",
        "GPU MiB",
        "1-pass µs",
        "1-pass ms"
    );
    for m in results {
        let gpu = m
            .gpu_ms
            .map_or("n/a".to_string(), |g| format!("{:.3}", g[0]));
        let _ = writeln!(
            out,
            "{:<20} {:<22} {:>9} {:>8} {:>8.0} {:>9.0} {:>9.2} {:>8.1} {:>8} {:>10.0} {:>10.2}",
            m.lesson,
            if m.settings.is_empty() {
                "(defaults)"
            } else {
                &m.settings
            },
            format!("{}x{}", m.size.0, m.size.1),
            gpu,
            m.cpu_us[0],
            m.submit_us[0],
            m.frame_ms[0],
            m.fps(),
            m.gpu_memory_mib
                .map_or("n/a".to_string(), |mib| format!("{mib:.1}")),
            m.one_pass_cpu_us[0],
            m.one_pass_frame_ms[0]
        );
    }
    out
}

/// A horizontal bar chart of the GPU time of every case at one size, each bar split into its
/// steps (SVG, no text baked into pixels: the labels are SVG text the browser draws).
pub fn plot(results: &[Measured], size: (u32, u32), title: &str) -> String {
    let rows: Vec<&Measured> = results.iter().filter(|m| m.size == size).collect();
    let longest = rows
        .iter()
        .filter_map(|m| m.gpu_ms.map(|g| g[0]))
        .fold(0.0f64, f64::max)
        .max(1e-6);
    let (left, width, bar, gap) = (260.0, 440.0, 16.0, 6.0);
    let height = 40.0 + rows.len() as f64 * (bar + gap) + 30.0;
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"760\" height=\"{height}\" \
         font-family=\"sans-serif\" font-size=\"12\">\n<text x=\"10\" y=\"20\" font-size=\"14\">{title}</text>\n"
    );
    let palette = [
        "#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948", "#b07aa1",
    ];
    for (row, m) in rows.iter().enumerate() {
        let y = 36.0 + row as f64 * (bar + gap);
        let label = if m.settings.is_empty() {
            m.lesson.to_string()
        } else {
            format!("{} {}", m.lesson, m.settings)
        };
        let _ = writeln!(
            svg,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{label}</text>",
            left - 8.0,
            y + 12.0
        );
        let mut x = left;
        for (index, (step, times)) in m.steps.iter().enumerate() {
            let w = times[0] / longest * width;
            let colour = palette[index % palette.len()];
            let _ = writeln!(
                svg,
                "<rect x=\"{x:.1}\" y=\"{y:.1}\" width=\"{w:.2}\" height=\"{bar}\" fill=\"{colour}\"><title>{step}: {:.3} ms</title></rect>",
                times[0]
            );
            x += w;
        }
        if let Some(gpu) = m.gpu_ms {
            let _ = writeln!(
                svg,
                "<text x=\"{:.1}\" y=\"{}\">{:.2} ms</text>",
                x + 6.0,
                y + 12.0,
                gpu[0]
            );
        }
    }
    svg + "</svg>\n"
}

/// Checks a CSV the benchmark wrote, as read back from its file: the `header` the book's cost page
/// reads, a row for each of `lessons`, and every figure a number that can be one: finite, and
/// greater than zero but for `added` (the panel's share, which noise can make negative). The GPU's
/// figures may be `NaN`, which the benchmark writes where the adapter cannot measure them (no
/// timestamp queries, no memory report). Returns the number of rows.
pub fn check_csv(text: &str, header: &str, lessons: &[&str]) -> Result<usize> {
    const TEXT: [&str; 5] = ["adapter", "lesson", "settings", "step", "profile"];
    let mut lines = text.lines();
    if lines.next() != Some(header) {
        bail!("the header is not `{header}`");
    }
    let names: Vec<&str> = header.split(',').collect();
    let mut seen = Vec::new();
    let mut rows = 0;
    for (number, line) in lines.enumerate() {
        let row = number + 1;
        let fields = csv_fields(line);
        if fields.len() != names.len() {
            bail!("row {row}: {} fields, not {}", fields.len(), names.len());
        }
        for (name, field) in names.iter().zip(&fields) {
            if *name == "lesson" {
                seen.push(field.clone());
            }
            let unmeasured = name.starts_with("gpu_") && field == "NaN";
            if TEXT.contains(name) || unmeasured {
                continue;
            }
            let value: f64 = field
                .parse()
                .map_err(|_| anyhow::anyhow!("row {row}: {name} is `{field}`"))?;
            if !value.is_finite() || (*name != "added" && value <= 0.0) {
                bail!("row {row}: {name} is {field}");
            }
        }
        rows += 1;
    }
    if let Some(missing) = lessons.iter().find(|l| !seen.iter().any(|s| s == *l)) {
        bail!("no row for {missing}");
    }
    Ok(rows)
}

/// A CSV line's fields, a quoted field (which may hold commas) without its quotes.
fn csv_fields(line: &str) -> Vec<String> {
    let (mut fields, mut field, mut quoted) = (Vec::new(), String::new(), false);
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => fields.push(std::mem::take(&mut field)),
            _ => field.push(c),
        }
    }
    fields.push(field);
    fields
}
