//! The benchmark's timing code: on an adapter with timestamp queries every step's GPU time is
//! positive and the steps sum to no more than the frame's wall time; the benchmark runs in its quick
//! form and its CSV has the columns the book's page reads.

use workbook_tests::bench::{self, CSV_HEADER, PANEL_CSV_HEADER, Plan};
use workbook_tests::shots::LESSONS;

#[test]
fn step_times_are_positive_and_fit_in_the_frame() {
    let plan = Plan {
        sizes: vec![(160, 90)],
        warm_up: 1,
        frames: 3,
        defaults_only: true,
    };
    let mut results = Vec::new();
    for case in [
        bench::case("drawing-order", &[]),
        bench::case("render-to-texture", &[]),
        bench::case("two-mirrors", &["depth=2"]),
    ] {
        let measured = bench::measure(&case, (160, 90), &plan).unwrap();
        let Some(total) = measured.gpu_ms else {
            eprintln!("skipped: this adapter has no timestamp queries");
            return;
        };
        for (step, times) in &measured.steps {
            assert!(
                times[0] > 0.0,
                "{}: step `{step}` took {} ms",
                case.lesson,
                times[0]
            );
        }
        assert!(
            total[0] <= measured.frame_ms[0],
            "{}: the steps' {} ms exceed the frame's {} ms",
            case.lesson,
            total[0],
            measured.frame_ms[0]
        );
        results.push(measured);
    }
    let csv = bench::csv(&results);
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some(CSV_HEADER));
    let columns = CSV_HEADER.split(',').count();
    for line in lines {
        // Quoted fields hold no commas but the adapter's name: count outside quotes.
        let mut inside = false;
        let commas = line
            .chars()
            .filter(|&c| {
                if c == '"' {
                    inside = !inside;
                }
                c == ',' && !inside
            })
            .count();
        assert_eq!(commas + 1, columns, "{line}");
    }
}

/// The benchmark measures every lesson, its defaults once and in the book's order, and each variant
/// it lists is of a lesson.
#[test]
fn the_benchmark_measures_every_lesson() {
    let cases = bench::cases();
    let defaults: Vec<&str> = cases
        .iter()
        .filter(|c| c.label().is_empty())
        .map(|c| c.lesson)
        .collect();
    assert_eq!(defaults, LESSONS);
    for variant in bench::VARIANTS {
        assert!(
            LESSONS.contains(&variant.lesson),
            "a variant of `{}`, which is no lesson",
            variant.lesson
        );
    }
}

/// The book's cost page shows what the benchmark wrote: each CSV there has the benchmark's columns
/// and is linked from the page, and each adapter's main figures have their plots.
#[test]
fn the_cost_page_shows_benchmark_output() {
    use workbook_tests::launches::{START_UP_CSV_HEADER, WINDOW_CSV_HEADER};
    let dir = workbook_tests::workspace().join("book/src/cost");
    let page = std::fs::read_to_string(dir.with_extension("md")).unwrap();
    let mut found = 0;
    for entry in std::fs::read_dir(&dir).unwrap().flatten() {
        let path = entry.path();
        if path.extension().is_none_or(|e| e != "csv") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        assert!(
            page.contains(&format!("(cost/{stem}.csv)")),
            "the cost page does not link cost/{stem}.csv"
        );
        // The window's panel, start-up and the window's frames/s: one row per lesson (start-up:
        // one per lesson and profile).
        let parts = [
            ("-panel", PANEL_CSV_HEADER, 1),
            ("-start-up", START_UP_CSV_HEADER, 2),
            ("-window", WINDOW_CSV_HEADER, 1),
        ];
        if let Some((_, header, rows)) = parts.iter().find(|(suffix, ..)| stem.ends_with(suffix)) {
            assert_eq!(text.lines().next(), Some(*header), "{}", path.display());
            assert_eq!(
                text.lines().count(),
                LESSONS.len() * rows + 1,
                "{}",
                path.display()
            );
            continue;
        }
        assert_eq!(text.lines().next(), Some(CSV_HEADER), "{}", path.display());
        assert!(
            text.lines().count() > 50,
            "{}: too few rows",
            path.display()
        );
        for size in ["1280x720", "1920x1080"] {
            assert!(
                dir.join(format!("{stem}-{size}.svg")).exists(),
                "{stem}-{size}.svg"
            );
        }
        found += 1;
    }
    assert!(
        found >= 2,
        "the cost page needs lavapipe's and a real GPU's figures"
    );
}

/// The panel's part of the benchmark, quick: both frame times positive, the CSV row of the
/// header's columns.
#[test]
fn the_panels_cost_is_measured() {
    let plan = Plan {
        sizes: vec![(640, 360)],
        warm_up: 2,
        frames: 4,
        defaults_only: true,
    };
    let measured = bench::measure_panel("stencil-basics", (640, 360), &plan).unwrap();
    assert!(
        measured.without[0] > 0.0 && measured.with[0] > 0.0,
        "{measured:?}"
    );
    assert!(
        measured.recorded.0 > 0.0 && measured.recorded.1 > 0.0,
        "{measured:?}"
    );
    let csv = bench::panel_csv(&[measured]);
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some(PANEL_CSV_HEADER));
    let row = lines.next().unwrap();
    let outside_quotes = row.rsplit('"').next().unwrap();
    assert_eq!(
        outside_quotes.split(',').count(),
        PANEL_CSV_HEADER.split(',').count(),
        "{row}"
    );
}

/// The window's frames/s is the 60 frames between a short and a long run over the time between
/// them; where the long run took no longer (the start-up's noise is larger than the frames) there
/// is no rate, rather than a huge one.
#[test]
fn a_window_rate_needs_the_longer_run_to_take_longer() {
    use workbook_tests::launches::frame_rate;
    let rate = frame_rate(1.0, 2.2).expect("60 frames in 1.2 s");
    assert!((rate - 50.0).abs() < 1e-9, "{rate}");
    assert_eq!(frame_rate(1.0, 1.0), None);
    assert_eq!(frame_rate(1.0, 0.9), None, "the long run was the faster");
    assert_eq!(
        frame_rate(1.0, 1.000_001),
        None,
        "60 frames in a microsecond"
    );
    assert!(
        frame_rate(1.0, 1.07).is_some(),
        "60 frames in 70 ms: 857 a second"
    );
}

/// What the benchmark's CSVs are checked for when it writes them (CI's quick run): a rate out of
/// noise, a zero, a NaN where a measure was due, a lesson missing, a column lost — each refused.
#[test]
fn the_benchmark_s_csvs_are_checked_for_figures() {
    use workbook_tests::bench::check_csv;
    use workbook_tests::launches::WINDOW_CSV_HEADER;
    let window = |rows: &str| format!("{WINDOW_CSV_HEADER}\n{rows}");
    let good = window("depth-test,1280,720,26.3,50.5\nstencil-basics,1280,720,25.2,46.4\n");
    assert_eq!(
        check_csv(&good, WINDOW_CSV_HEADER, &["depth-test"]).unwrap(),
        2
    );
    for (bad, why) in [
        (window("depth-test,1280,720,0.0,50.5\n"), "a zero rate"),
        (window("depth-test,1280,720,NaN,50.5\n"), "a NaN rate"),
        (window("depth-test,1280,720,inf,50.5\n"), "an infinite rate"),
        (window("depth-test,1280,720,26.3\n"), "a column lost"),
        (
            window("stencil-basics,1280,720,25.2,46.4\n"),
            "depth-test missing",
        ),
        ("lesson,full_fps\n".to_string(), "another header"),
    ] {
        assert!(
            check_csv(&bad, WINDOW_CSV_HEADER, &["depth-test"]).is_err(),
            "{why} passed"
        );
    }
    // The adapter's name holds commas inside its quotes; GPU figures may be NaN (not measured),
    // the panel's share may be negative.
    let panel = format!(
        "{PANEL_CSV_HEADER}\n\"llvmpipe (LLVM 15.0.6, 256 bits) (Vulkan)\",depth-test,1280,720,\
         29.3,27.6,33.7,27.0,25.9,30.7,-0.080,54.96,50.13,0.1849,0.2176\n"
    );
    assert_eq!(
        check_csv(&panel, PANEL_CSV_HEADER, &["depth-test"]).unwrap(),
        1
    );
    let frames = format!(
        "{CSV_HEADER}\n\"an adapter\",depth-test,\"\",160,90,\"frame\",NaN,NaN,NaN,250.4,65.4,\
         63.561,15.7,NaN,205.7,66.574\n"
    );
    assert_eq!(check_csv(&frames, CSV_HEADER, &["depth-test"]).unwrap(), 1);
    let no_rate = frames.replace(",15.7,", ",NaN,");
    assert!(check_csv(&no_rate, CSV_HEADER, &["depth-test"]).is_err());
}
