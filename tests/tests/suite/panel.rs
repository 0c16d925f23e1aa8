//! The window's side panel driven as a user drives it, without a window: `egui_kittest` finds the
//! widgets by their accessible names and clicks them. What the panel asks for is then carried out as
//! the window does, and the lesson's render compared with the command line's.

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use lessons::reflect_skull;
use workbook::app::headless::{Headless, Request};
use workbook::app::workbench::headless::HeadlessWorkbench;
use workbook::app::workbench::panel::{self, Action, Book, Cost, Model};
use workbook::room::camera::BOOK_POSE;
use workbook::{Knob, Knobs, Lesson, Show};
use workbook_tests::shots::{self, ForLesson, LESSONS};

/// The panel of a lesson with these knobs and this cost, in a harness that keeps what it asked for.
fn harness(
    knob_list: &'static [Knob],
    knobs: Knobs,
    cost: Option<Cost>,
) -> Harness<'static, Vec<Action>> {
    let steps = vec!["clear", "draw the room"];
    let poses = vec![("lesson".to_string(), BOOK_POSE)];
    let app = move |ui: &mut egui::Ui, asked: &mut Vec<Action>| {
        let model = Model {
            title: "a lesson",
            knob_list,
            knobs: &knobs,
            steps: &steps,
            step: 2,
            show: Show::Color,
            draws: &[],
            draw: None,
            can_show_depth: true,
            thumbnails: None,
            cost: cost.as_ref(),
            adapter: "an adapter",
            camera: BOOK_POSE,
            poses: &poses,
            book_shots: &[],
            book: &Book::NoMatch,
            show_difference: false,
            message: None,
            picked: None,
            half_resolution: Some(true),
        };
        asked.extend(panel::show(ui, &model));
    };
    Harness::builder()
        .with_size(egui::vec2(1280.0, 2000.0))
        .build_ui_state(app, Vec::new())
}

/// The panel shows one dropdown per knob, named as `--list-knobs` names them, in its order.
#[test]
fn the_panel_lists_exactly_the_knobs_of_list_knobs() {
    for lesson in LESSONS {
        let knob_list = shots::knobs(lesson).unwrap();
        let harness = harness(knob_list, Knobs::defaults(knob_list), None);
        let listed = workbook::lesson::knobs::describe(knob_list);
        for (index, knob) in knob_list.iter().enumerate() {
            assert!(listed.contains(knob.name));
            harness.get_by_label(&format!("[{}] {}", index + 1, knob.name));
        }
        let dropdowns = harness.query_all_by_role(Role::ComboBox).count();
        assert_eq!(dropdowns, knob_list.len(), "{lesson}");
    }
}

/// Choosing `compare = always` in stencil-basics' panel, then building the lesson with what the panel
/// asked for as the window does, renders exactly what `--set compare=always` renders.
#[test]
fn choosing_a_knob_in_the_panel_renders_as_set_does() {
    struct Drive;
    impl ForLesson for Drive {
        type Output = ();
        fn run<L: Lesson>(self) {
            let (name, value) = ("compare", "always");
            let index = L::KNOBS.iter().position(|k| k.name == name).unwrap();
            let mut harness = harness(L::KNOBS, Knobs::defaults(L::KNOBS), None);
            harness
                .get_all_by_role(Role::ComboBox)
                .nth(index)
                .unwrap()
                .click();
            harness.run();
            harness.get_by_label(value).click();
            harness.run();
            assert_eq!(harness.state(), &[Action::Knob(index, value)]);

            let mut request = Request::new::<L>(&[] as &[&str]).unwrap();
            (request.width, request.height) = (320, 180);
            let mut window = Headless::<L>::new(&request).unwrap();
            let mut knobs = Knobs::defaults(L::KNOBS);
            for action in harness.state() {
                if let Action::Knob(index, value) = action {
                    knobs
                        .apply(&format!("{}={value}", L::KNOBS[*index].name))
                        .unwrap();
                }
            }
            window.set_knobs(knobs).unwrap();
            let from_panel = window.capture().unwrap().color;
            let mut set = Request::new::<L>(&[format!("{name}={value}")]).unwrap();
            (set.width, set.height) = (320, 180);
            let from_set = workbook::app::headless::render::<L>(&set).unwrap().color;
            let default = workbook::app::headless::render::<L>(&request)
                .unwrap()
                .color;
            assert!(from_panel == from_set, "the panel's render is not --set's");
            assert!(
                from_panel != default,
                "the knob changed nothing: the test proves nothing"
            );
            let flip = workbook::book::flip::compare(&from_set, &from_panel).unwrap();
            assert_eq!(flip.mean, 0.0);
        }
    }
    shots::for_lesson("stencil-basics", Drive).unwrap();
}

/// The cost section says where its times come from: the GPU's timestamps, or the CPU alone.
#[test]
fn the_panel_says_gpu_time_or_cpu_time() {
    let gpu = Cost {
        steps_ms: Some(vec![0.5, 2.0]),
        cpu_ms: 1.0,
        frame_ms: Some(4.0),
        fps: Some(250.0),
    };
    let harness_gpu = harness(&[], Knobs::defaults(&[]), Some(gpu));
    harness_gpu.get_by_label("GPU time per step (timestamp queries):");
    harness_gpu.get_by_label("   2.500 ms");
    let cpu = Cost {
        steps_ms: None,
        cpu_ms: 1.0,
        frame_ms: None,
        fps: None,
    };
    let harness_cpu = harness(&[], Knobs::defaults(&[]), Some(cpu));
    harness_cpu.get_by_label_contains("CPU time only");
    assert!(
        harness_cpu
            .query_by_label_contains("GPU time per step")
            .is_none()
    );
}

/// The hide button asks to hide, and clicking a step asks to stop there.
#[test]
fn the_panel_asks_for_steps_and_hiding() {
    let mut harness = harness(&[], Knobs::defaults(&[]), None);
    harness.get_by_label("1. clear").click();
    harness.run();
    harness.get_by_label("Hide").click();
    harness.run();
    assert_eq!(harness.state(), &[Action::Step(1), Action::Hide]);
}

/// On a software GPU the panel says the lesson is drawn at half resolution, and its box asks for
/// full resolution.
#[test]
fn the_panel_says_a_software_gpu_draws_at_half_resolution_and_switches() {
    let mut harness = harness(&[], Knobs::defaults(&[]), None);
    harness
        .get_by_label("software GPU: drawing at half resolution (R)")
        .click();
    harness.run();
    assert_eq!(harness.state(), &[Action::HalfResolution(false)]);
}

/// The panel's cost section, from the real workbench drawn headless frame after frame (the window's
/// code, a texture for its surface): on an adapter with timestamp queries every step's GPU time is
/// positive and the steps sum to no more than the frame time; without, there are no step times
/// (and the panel says "CPU time only", as the test above shows).
#[test]
fn the_panels_step_times_are_positive_and_fit_in_the_frame() {
    use lessons::reflect_skull::ReflectSkull;
    use workbook::app::args::Args;
    use workbook::wgpu;

    let args = Args::parse_for::<ReflectSkull>(["reflect-skull", "--size", "640x360"]).unwrap();
    let mut bench = HeadlessWorkbench::<ReflectSkull>::new(&args).unwrap();
    // Until the panel has a frame time (three frames within a second and a half) and the times of
    // a frame the GPU finished.
    for _ in 0..40 {
        bench.frame().unwrap();
        if bench
            .cost()
            .is_some_and(|c| c.frame_ms.is_some() && c.steps_ms.is_some())
        {
            break;
        }
    }
    let steps = bench.runner.steps();
    let timestamps = bench
        .runner
        .gpu
        .device
        .features()
        .contains(wgpu::Features::TIMESTAMP_QUERY);
    let cost = bench.cost().expect("a cost after a frame");
    let frame_ms = cost
        .frame_ms
        .expect("frames drawn one after another have a frame time");
    match &cost.steps_ms {
        None => assert!(
            !timestamps,
            "the adapter has timestamp queries, the panel no times"
        ),
        Some(times) => {
            assert!(timestamps);
            assert_eq!(times.len(), steps.len(), "one time per step: {steps:?}");
            for (step, ms) in steps.iter().zip(times) {
                assert!(*ms > 0.0, "{step}: {ms} ms");
            }
            let sum: f64 = times.iter().sum();
            assert!(
                sum <= frame_ms,
                "the steps take {sum:.3} ms of GPU time, more than the frame's {frame_ms:.3} ms"
            );
        }
    }
}

/// A frame with no input and nothing new to show is not laid out again (egui's pass costs as much as
/// the lesson's frame on a fast GPU's machine): the panel's last picture is copied. Input, or a
/// knob changed, lays it out again.
#[test]
fn idle_frames_keep_the_panels_layout() {
    use lessons::reflect_skull::ReflectSkull;
    use workbook::app::args::Args;

    let args = Args::parse_for::<ReflectSkull>(["reflect-skull", "--size", "640x360"]).unwrap();
    let mut bench = HeadlessWorkbench::<ReflectSkull>::new(&args).unwrap();
    // egui animates its widgets in for the first fraction of a second and asks for a frame
    // meanwhile (a fast GPU draws 20 frames within it): those frames are laid out, rightly.
    let start = std::time::Instant::now();
    while start.elapsed().as_secs_f64() < 1.5 {
        bench.frame().unwrap();
    }
    // Idle: laid out only when the cost and the small buffers refresh, twice a second (the
    // panel's promise, written here rather than read from the workbench: a workbench refreshing
    // more often must fail). A refresh may take more than one layout (the new figures, egui's
    // passes after them): measured beside a busy machine, up to 3 layouts in 20 frames of 0.30 and
    // 0.45 s, each spanning one refresh (2 of 13 runs; the others 1). Frames spanning T seconds
    // meet at most T / 0.5 + 1 refreshes. (A panel laid out every idle frame: 20.)
    const REFRESH_S: f64 = 0.5;
    let (before, frames) = (bench.workbench.layouts, 20);
    let start = std::time::Instant::now();
    for _ in 0..frames {
        bench.frame().unwrap();
    }
    let seconds = start.elapsed().as_secs_f64();
    let refreshes = 1 + (seconds / REFRESH_S) as u64;
    let idle = bench.workbench.layouts - before;
    assert!(
        idle <= 3 * refreshes,
        "{idle} layouts in {frames} idle frames, {seconds:.2} s: at most three for each of \
         {refreshes} refreshes"
    );
    // A pointer moving over the window: laid out at once.
    let before = bench.workbench.layouts;
    let moved = egui::Event::PointerMoved(egui::pos2(600.0, 100.0));
    bench.frame_with(vec![moved]).unwrap();
    assert_eq!(
        bench.workbench.layouts,
        before + 1,
        "input must be laid out"
    );
    // A knob changed from outside the panel (a key in the window): laid out at once.
    let before = bench.workbench.layouts;
    let knobs = workbook::Knobs::from_settings(ReflectSkull::KNOBS, &["stencil=off"]).unwrap();
    bench.runner.set_knobs(knobs).unwrap();
    bench.frame().unwrap();
    assert_eq!(
        bench.workbench.layouts,
        before + 1,
        "a new knob must be laid out"
    );
}

/// A right-click on the view picks a pixel: the panel tells its story, the one `--pixel` tells for
/// the view's size and the same settings, and follows a knob changed in the panel.
#[test]
fn a_picked_pixel_s_story_is_the_one_pixel_tells() {
    use lessons::mark_mirror::MarkMirror;
    use workbook::app::args::Args;
    use workbook_tests::stories::skeleton;

    let arguments = ["mark-mirror", "--size", "960x360", "--resolution", "full"];
    let args = Args::parse_for::<MarkMirror>(arguments).unwrap();
    let mut bench = HeadlessWorkbench::<MarkMirror>::new(&args).unwrap();
    bench.frame().unwrap();
    assert!(
        !bench.workbench.pick((950.0, 100.0)),
        "the panel is no pixel of the view"
    );
    let pixel = (250, 120);
    assert!(
        bench
            .workbench
            .pick((pixel.0 as f64 + 0.5, pixel.1 as f64 + 0.5))
    );
    bench.frame().unwrap();
    let told = |bench: &HeadlessWorkbench<MarkMirror>| {
        let story = bench
            .workbench
            .story()
            .expect("a story once a pixel is picked");
        story.as_ref().expect("a story told").text()
    };
    let (width, height) = bench.workbench.view_size();
    let tell = |settings: &[&str]| {
        let mut request = Request::new::<MarkMirror>(settings).unwrap();
        (request.width, request.height) = (width, height);
        let headless = Headless::<MarkMirror>::new(&request).unwrap();
        headless.story(pixel, settings.join(" ")).unwrap().text()
    };
    assert_eq!(skeleton(&told(&bench)), skeleton(&tell(&[])));
    let knobs = Knobs::from_settings(MarkMirror::KNOBS, &["mark-depth-test=off"]).unwrap();
    workbook::app::workbench::set_knobs(&mut bench.runner, &mut bench.viewing, knobs).unwrap();
    bench.frame().unwrap();
    assert_eq!(
        skeleton(&told(&bench)),
        skeleton(&tell(&["mark-depth-test=off"]))
    );
}

/// `--resolution auto`, the default, draws a software GPU's window at half resolution and any other
/// GPU's at full (the decision itself: `Resolution::half`'s unit test).
#[test]
fn auto_resolution_follows_the_adapter() {
    use lessons::reflect_skull::ReflectSkull;
    use workbook::app::args::Args;

    let args = Args::parse_for::<ReflectSkull>(["reflect-skull", "--size", "640x360"]).unwrap();
    let mut bench = HeadlessWorkbench::<ReflectSkull>::new(&args).unwrap();
    bench.frame().unwrap();
    let info = bench.runner.gpu.adapter.get_info();
    let software = info.device_type == workbook::wgpu::DeviceType::Cpu;
    assert_eq!(
        bench.workbench.half_resolution, software,
        "{} ({:?})",
        info.name, info.device_type
    );
}

/// A headless workbench of reflect-skull at 640x360 and this `--resolution`, two frames drawn.
fn workbench_at(resolution: &str) -> HeadlessWorkbench<reflect_skull::ReflectSkull> {
    use workbook::app::args::Args;
    let arguments = [
        "reflect-skull",
        "--size",
        "640x360",
        "--resolution",
        resolution,
    ];
    let args = Args::parse_for::<reflect_skull::ReflectSkull>(arguments).unwrap();
    let mut bench = HeadlessWorkbench::new(&args).unwrap();
    bench.frame().unwrap();
    bench.frame().unwrap();
    bench
}

/// At half resolution (a software GPU's window, `--resolution half`) the lesson draws a quarter of
/// the view's pixels beside the panel, and a quarter of the window's without it: the window then
/// shows the lesson's render at half the size, scaled up.
///
/// Each of the lesson's pixels is made four (sampled nearest: a picked pixel is one of those
/// blocks), so the window is the half-size render scaled up on the CPU, pixel for pixel.
#[test]
fn half_resolution_draws_a_quarter_of_the_pixels() {
    let (full, mut half) = (workbench_at("full"), workbench_at("half"));
    let (width, height) = full.workbench.view_size();
    assert_eq!(
        half.workbench.view_size(),
        (width.div_ceil(2), height.div_ceil(2))
    );
    assert_eq!(half.runner.depth_stencil.size(), half.workbench.view_size());
    half.set_panel(false);
    half.frame().unwrap();
    assert_eq!(half.runner.depth_stencil.size(), (320, 180));
    let window = half.picture().unwrap();
    let mut request = Request::new::<reflect_skull::ReflectSkull>(&[] as &[&str]).unwrap();
    (request.width, request.height) = (320, 180);
    let lesson = workbook::app::headless::render::<reflect_skull::ReflectSkull>(&request)
        .unwrap()
        .color;
    let scaled = image::imageops::resize(&lesson, 640, 360, image::imageops::FilterType::Nearest);
    let differ = scaled.pixels().zip(window.pixels()).filter(|(a, b)| a != b);
    let differ = differ.count();
    assert_eq!(
        differ, 0,
        "the window at half resolution is not the half-size render scaled up: {differ} pixels differ"
    );
}

/// At half resolution a pixel picked in the window is one of the lesson's half-size render, the
/// one under the cursor: its story is the one `--pixel` tells for that pixel at that size.
#[test]
fn a_pixel_picked_at_half_resolution_is_the_half_size_render_s() {
    use workbook_tests::stories::skeleton;
    let mut bench = workbench_at("half");
    let (width, height) = bench.workbench.view_size();
    // Lesson 4's mirror, at half of the 640x360 window's view.
    let pixel = (110, 60);
    let cursor = (2.0 * pixel.0 as f64 + 1.5, 2.0 * pixel.1 as f64 + 1.5);
    assert!(bench.workbench.pick(cursor));
    bench.frame().unwrap();
    let story = bench
        .workbench
        .story()
        .expect("a story once a pixel is picked");
    let told = story.as_ref().expect("a story told").text();
    let mut request = Request::new::<reflect_skull::ReflectSkull>(&[] as &[&str]).unwrap();
    (request.width, request.height) = (width, height);
    let headless = Headless::<reflect_skull::ReflectSkull>::new(&request).unwrap();
    let native = headless.story(pixel, String::new()).unwrap().text();
    assert_eq!(skeleton(&told), skeleton(&native), "{told}");
    assert!(
        told.contains(&format!("({}, {})", pixel.0, pixel.1)),
        "{told}"
    );
}

/// The window shows the lesson beside its panel pixel for pixel: in the first frame (laid out and
/// painted) and in idle ones (the view and the panel's picture copied into place), the view is the
/// headless render at the view's size, of whichever buffer it shows; the panel is beside it.
#[test]
fn the_view_beside_the_panel_is_the_lessons_render() {
    use lessons::reflect_skull::ReflectSkull;
    use workbook::app::args::Args;

    for (show, shown) in [("color", Show::Color), ("stencil", Show::Stencil)] {
        let arguments = [
            "reflect-skull",
            "--size",
            "640x360",
            "--resolution",
            "full",
            "--show",
            show,
        ];
        let args = Args::parse_for::<ReflectSkull>(arguments).unwrap();
        let mut bench = HeadlessWorkbench::<ReflectSkull>::new(&args).unwrap();
        bench.frame().unwrap();
        let first = bench.picture().unwrap();
        // egui animates the panel in for a fraction of a second: the first frame after it that is
        // not laid out again.
        let start = std::time::Instant::now();
        loop {
            let before = bench.workbench.layouts;
            bench.frame().unwrap();
            if bench.workbench.layouts == before {
                break;
            }
            assert!(start.elapsed().as_secs() < 10, "{show}: no idle frame");
        }
        let idle = bench.picture().unwrap();
        let (width, height) = bench.workbench.view_size();
        assert!(width < 640 && height == 360, "a view beside the panel");
        let mut request = Request::new::<ReflectSkull>(&[] as &[&str]).unwrap();
        (request.width, request.height, request.show) = (width, height, shown);
        let lesson = workbook::app::headless::render::<ReflectSkull>(&request)
            .unwrap()
            .color;
        for (frame, picture) in [("first", &first), ("idle", &idle)] {
            let view = image::imageops::crop_imm(picture, 0, 0, width, height).to_image();
            assert!(
                view == lesson,
                "{show}, {frame} frame: the view is not the lesson's render"
            );
            let panel = image::imageops::crop_imm(picture, width, 0, 640 - width, height);
            let panel = panel.to_image();
            let lit = panel.pixels().filter(|p| p.0[..3] != [0, 0, 0]).count();
            assert!(
                lit > 1000,
                "{show}, {frame} frame: no panel beside the view"
            );
        }
    }
}

/// A texture egui makes and lets go of within one frame (an image shown once: its handle dropped
/// in the pass that painted it) is in that frame's shapes and in its list of textures to free. The
/// panel's painter frees it only after the frame is submitted, as egui-wgpu's own painter does:
/// destroyed before, the frame's commands use a destroyed texture, which wgpu's validation rejects.
#[test]
fn a_texture_made_and_dropped_in_one_frame_is_freed_after_the_frame() {
    use workbook::app::workbench::painter::PanelPainter;
    let gpu = workbook::Gpu::shared_headless(None, false).unwrap();
    let format = workbook::gpu::HEADLESS_FORMAT;
    let size = (64, 48);
    let target = workbook::gpu::target_texture(
        &gpu.device,
        "painter test target",
        format,
        size,
        wgpu::TextureUsages::COPY_SRC,
    );
    let view = target.create_view(&Default::default());
    let mut painter = PanelPainter::new(&gpu.device, format);
    let ctx = egui::Context::default();
    let input = egui::RawInput {
        screen_rect: Some(egui::Rect::from_min_size(
            egui::Pos2::ZERO,
            egui::vec2(64.0, 48.0),
        )),
        ..Default::default()
    };
    let output = ctx.run_ui(input, |ui| {
        let picture = egui::ColorImage::new([4, 4], vec![egui::Color32::RED; 16]);
        let once = ui
            .ctx()
            .load_texture("shown once", picture, Default::default());
        ui.image((once.id(), egui::vec2(32.0, 32.0)));
    });
    let mut output = output;
    let jobs = ctx.tessellate(output.shapes.clone(), output.pixels_per_point);
    let drawn = jobs.iter().any(|job| match &job.primitive {
        egui::epaint::Primitive::Mesh(mesh) => mesh.texture_id != egui::TextureId::default(),
        egui::epaint::Primitive::Callback(_) => false,
    });
    let freed = !output.textures_delta.free.is_empty();
    if !(drawn && freed) {
        output.textures_delta.clear();
        panic!("the frame should paint a texture it frees (painted {drawn}, freed {freed})");
    }
    gpu.scoped(|| {
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        painter.update_textures(&gpu, &output.textures_delta);
        let ppp = output.pixels_per_point;
        painter.paint(&gpu, &ctx, &mut encoder, output.shapes, ppp, (&view, size));
        painter.submit(&gpu, encoder, output.textures_delta);
        gpu.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(anyhow::Error::from)?;
        Ok(())
    })
    .expect("painting a texture freed in the same frame");
}
