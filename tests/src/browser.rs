//! The web edition in a real browser: the built book served on 127.0.0.1, Debian's Chromium driven
//! over the DevTools protocol (`headless_chrome`), a lesson page's "Run" clicked, its controls set
//! as a reader sets them, and its canvas read back. `cargo web-test` runs the checks.
//!
//! Chromium here has no GPU: both of its backends run on its software renderer, SwiftShader. The
//! flags that make each one work headless were measured on Chromium 156 (see the web issue): WebGL2
//! needs `--enable-unsafe-swiftshader`; WebGPU needs Vulkan on SwiftShader, or its canvas reads back
//! blank.

use std::ffi::OsStr;
use std::io::{BufRead, BufReader, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Duration;

use anyhow::{Context, Result, anyhow, bail};
use base64::Engine;
use headless_chrome::{Browser, LaunchOptions, Tab};
use image::RgbaImage;

/// One of the browser's two backends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WebBackend {
    WebGpu,
    WebGl2,
}

impl WebBackend {
    pub const BOTH: [WebBackend; 2] = [WebBackend::WebGpu, WebBackend::WebGl2];

    /// The page's name for it (`?backend=`), as the module's `Backend::parse` reads it.
    pub fn name(self) -> &'static str {
        match self {
            Self::WebGpu => "webgpu",
            Self::WebGl2 => "webgl2",
        }
    }

    /// What the page says runs it.
    pub fn shown(self) -> &'static str {
        match self {
            Self::WebGpu => "WebGPU",
            Self::WebGl2 => "WebGL2",
        }
    }

    fn flags(self) -> &'static [&'static str] {
        match self {
            Self::WebGpu => &[
                "--enable-unsafe-webgpu",
                "--enable-features=NetworkService,NetworkServiceInProcess,Vulkan",
                "--use-vulkan=swiftshader",
                "--use-angle=swiftshader",
            ],
            Self::WebGl2 => &["--enable-unsafe-swiftshader", "--use-angle=swiftshader"],
        }
    }
}

/// Serves the folder `root` on 127.0.0.1 at a free port, on threads of its own, for as long as the
/// process lives; returns the site's address, e.g. `http://127.0.0.1:40123`.
pub fn serve(root: &Path) -> Result<String> {
    let listener = TcpListener::bind("127.0.0.1:0").context("cannot listen on 127.0.0.1")?;
    let address = format!("http://{}", listener.local_addr()?);
    let root = root.to_path_buf();
    std::thread::spawn(move || {
        for stream in listener.incoming().flatten() {
            let root = root.clone();
            std::thread::spawn(move || {
                let _ = answer(&root, stream);
            });
        }
    });
    Ok(address)
}

/// Answers one request: GET of a file under `root`, with the content type a browser needs (a
/// module script must be JavaScript, a module compiled while it streams must be `application/wasm`).
fn answer(root: &Path, mut stream: TcpStream) -> std::io::Result<()> {
    let mut reader = BufReader::new(stream.try_clone()?);
    let mut request = String::new();
    reader.read_line(&mut request)?;
    // The headers are not needed; read them so the client is not cut off mid-request.
    let mut header = String::new();
    while reader.read_line(&mut header)? > 2 {
        header.clear();
    }
    let path = request.split_whitespace().nth(1).unwrap_or("/");
    let path = path.split(['?', '#']).next().unwrap_or("/");
    let relative = path.trim_start_matches('/');
    let relative = if relative.is_empty() {
        "index.html"
    } else {
        relative
    };
    let file = root.join(relative);
    let body = if relative.split('/').any(|part| part == "..") {
        None
    } else {
        std::fs::read(&file).ok()
    };
    let Some(body) = body else {
        let message = b"not found";
        write!(
            stream,
            "HTTP/1.1 404 Not Found\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
            message.len()
        )?;
        return stream.write_all(message);
    };
    let kind = match file.extension().and_then(OsStr::to_str).unwrap_or("") {
        "html" => "text/html; charset=utf-8",
        "js" => "text/javascript",
        "wasm" => "application/wasm",
        "css" => "text/css",
        "png" => "image/png",
        "svg" => "image/svg+xml",
        "json" => "application/json",
        "woff2" => "font/woff2",
        "woff" => "font/woff",
        _ => "application/octet-stream",
    };
    write!(
        stream,
        "HTTP/1.1 200 OK\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    )?;
    stream.write_all(&body)
}

/// Debian's Chromium, or the one `CHROMIUM` names.
pub fn chromium() -> Result<PathBuf> {
    if let Some(path) = std::env::var_os("CHROMIUM") {
        return Ok(PathBuf::from(path));
    }
    [
        "/usr/bin/chromium",
        "/usr/bin/chromium-browser",
        "/usr/bin/google-chrome",
    ]
    .iter()
    .map(PathBuf::from)
    .find(|path| path.exists())
    .context("no Chromium: `sudo apt-get install chromium` (or set CHROMIUM to its path)")
}

/// A headless Chromium with one backend's flags.
pub struct WebBrowser {
    browser: Browser,
    pub backend: WebBackend,
}

impl WebBrowser {
    pub fn launch(backend: WebBackend) -> Result<Self> {
        let mut args: Vec<&OsStr> = backend.flags().iter().map(OsStr::new).collect();
        args.push(OsStr::new("--no-sandbox"));
        let options = LaunchOptions {
            headless: true,
            sandbox: false,
            // Otherwise headless_chrome adds --disable-gpu, and a WebGPU canvas shows nothing.
            enable_gpu: true,
            path: Some(chromium()?),
            window_size: Some((1200, 1000)),
            idle_browser_timeout: Duration::from_secs(600),
            // The defaults' --enable-features is this backend's, which adds Vulkan to it.
            ignore_default_args: vec![OsStr::new(
                "--enable-features=NetworkService,NetworkServiceInProcess",
            )],
            args,
            ..LaunchOptions::default()
        };
        let browser = Browser::new(options).map_err(|e| anyhow!("cannot start Chromium: {e}"))?;
        Ok(Self { browser, backend })
    }

    /// Opens `lesson`'s page of the book at `site`, clicks "Run" and waits for the first frame.
    pub fn open(&self, site: &str, lesson: &str) -> Result<LivePage> {
        let tab = self.browser.new_tab().map_err(|e| anyhow!("no tab: {e}"))?;
        self.open_in(tab, site, lesson)
    }

    /// [`Self::open`] on a phone: a 390×844 screen of three pixels a point, touch and no mouse.
    pub fn open_on_a_phone(&self, site: &str, lesson: &str) -> Result<LivePage> {
        use headless_chrome::protocol::cdp::Emulation;
        let tab = self.browser.new_tab().map_err(|e| anyhow!("no tab: {e}"))?;
        let metrics: Emulation::SetDeviceMetricsOverride =
            serde_json::from_value(serde_json::json!({
                "width": 390, "height": 844, "deviceScaleFactor": 3, "mobile": true,
            }))?;
        tab.call_method(metrics)
            .map_err(|e| anyhow!("no phone's screen: {e}"))?;
        let touch = Emulation::SetTouchEmulationEnabled {
            enabled: true,
            max_touch_points: Some(5),
        };
        tab.call_method(touch)
            .map_err(|e| anyhow!("no touch: {e}"))?;
        self.open_in(tab, site, lesson)
    }

    fn open_in(&self, tab: Arc<Tab>, site: &str, lesson: &str) -> Result<LivePage> {
        let mut page = self.run_in(tab, site, lesson)?;
        let started = page.started()?;
        page.first_frame = match started.strip_prefix("first frame ") {
            Some(seconds) => seconds.parse::<f64>().unwrap_or(f64::NAN),
            None => bail!("{lesson} on {}: {started}", self.backend.shown()),
        };
        Ok(page)
    }

    /// Opens `lesson`'s page with `before` run in it ahead of the page's own scripts (to take
    /// away what the browser has), clicks "Run", and returns what the status line says once the
    /// lesson has failed to start (an error if it started).
    pub fn open_failing(&self, site: &str, lesson: &str, before: &str) -> Result<String> {
        use headless_chrome::protocol::cdp::Page;
        let tab = self.browser.new_tab().map_err(|e| anyhow!("no tab: {e}"))?;
        let script: Page::AddScriptToEvaluateOnNewDocument =
            serde_json::from_value(serde_json::json!({ "source": before }))?;
        tab.call_method(script)
            .map_err(|e| anyhow!("cannot add a script to the page: {e}"))?;
        let page = self.run_in(tab, site, lesson)?;
        let started = page.started()?;
        if !started.starts_with("error: ") {
            bail!("{lesson} started where it should have failed: {started}");
        }
        page.status()
    }

    /// Opens `lesson`'s page of the book at `site` in `tab` and clicks "Run".
    fn run_in(&self, tab: Arc<Tab>, site: &str, lesson: &str) -> Result<LivePage> {
        tab.set_default_timeout(Duration::from_secs(120));
        let url = format!("{site}/{lesson}.html?backend={}", self.backend.name());
        tab.navigate_to(&url)
            .and_then(|tab| tab.wait_until_navigated())
            .map_err(|e| anyhow!("cannot open {url}: {e}"))?;
        let page = LivePage {
            tab,
            lesson: lesson.to_string(),
            first_frame: 0.0,
        };
        let clicked = page.evaluate(&format!(
            "(() => {{ const run = document.querySelector('div.live[data-lesson=\"{lesson}\"] button.live-run');
                 if (!run) return 'no Run button';
                 run.click(); return 'ok'; }})()"
        ))?;
        if clicked != "ok" {
            bail!("{lesson}: {clicked}");
        }
        Ok(page)
    }
}

/// What a page holds in memory.
#[derive(Debug, Clone, Copy)]
pub struct PageMemory {
    /// The JavaScript heap's live bytes (V8's; the DOM's nodes are counted apart).
    pub js_heap: u64,
    /// The DOM's nodes alive, in the page and detached but held.
    pub dom_nodes: u64,
    /// The JavaScript event listeners registered.
    pub listeners: u64,
    /// The bytes live on the module's Rust heap (its counting allocator's).
    pub rust_heap: u64,
    /// The WebAssembly module's memory in bytes (it only grows, by 64 KiB pages).
    pub wasm: u64,
}

/// A lesson running in its page.
pub struct LivePage {
    tab: Arc<Tab>,
    pub lesson: String,
    /// Seconds from the click on "Run" to the first frame drawn, as the page measured it.
    pub first_frame: f64,
}

/// Runs a script in a tab; its value (awaited if a promise) as a string.
fn evaluate_in(tab: &Tab, script: &str) -> Result<String> {
    let result = tab
        .evaluate(script, true)
        .map_err(|e| anyhow!("script failed: {e}"))?;
    Ok(match result.value {
        Some(serde_json::Value::String(text)) => text,
        Some(other) => other.to_string(),
        None => result.description.unwrap_or_default(),
    })
}

/// A PNG of what a tab shows: the page's viewport, or the `clip` rectangle of the page.
fn screenshot_of(
    tab: &Tab,
    clip: Option<headless_chrome::protocol::cdp::Page::Viewport>,
) -> Result<Vec<u8>> {
    tab.capture_screenshot(
        headless_chrome::protocol::cdp::Page::CaptureScreenshotFormatOption::Png,
        None,
        clip,
        true,
    )
    .map_err(|e| anyhow!("no screenshot: {e}"))
}

impl WebBrowser {
    /// Opens any page of the book (not run: a page as a reader first sees it).
    pub fn page(&self, url: &str) -> Result<BookPage> {
        let tab = self.browser.new_tab().map_err(|e| anyhow!("no tab: {e}"))?;
        tab.set_default_timeout(Duration::from_secs(60));
        tab.navigate_to(url)
            .and_then(|tab| tab.wait_until_navigated())
            .map_err(|e| anyhow!("cannot open {url}: {e}"))?;
        Ok(BookPage { tab })
    }
}

/// A page of the book in a tab.
pub struct BookPage {
    tab: Arc<Tab>,
}

impl BookPage {
    /// Runs a script in the page; its value (awaited if a promise) as a string.
    pub fn evaluate(&self, script: &str) -> Result<String> {
        evaluate_in(&self.tab, script)
    }

    /// Runs a script that makes the page go elsewhere (a click on a link), and waits for the new
    /// page; its address.
    pub fn follow(&self, script: &str) -> Result<String> {
        // The click is run after the script has returned: a script that navigates away from its own
        // page never returns a value.
        self.evaluate(&format!("setTimeout(() => {{ {script} }}, 0); 'ok'"))?;
        std::thread::sleep(Duration::from_millis(300));
        self.tab
            .wait_until_navigated()
            .map_err(|e| anyhow!("no new page: {e}"))?;
        self.evaluate("location.href")
    }

    /// A screenshot of the page's viewport as the browser shows it.
    pub fn screenshot(&self) -> Result<Vec<u8>> {
        screenshot_of(&self.tab, None)
    }
}

impl LivePage {
    /// Runs a script in the page; its value (awaited if a promise) as a string.
    pub fn evaluate(&self, script: &str) -> Result<String> {
        evaluate_in(&self.tab, script)
    }

    fn state(&self) -> String {
        format!("window.workbookLive['{}']", self.lesson)
    }

    /// Draws a frame and reads the canvas back.
    pub fn capture(&self) -> Result<RgbaImage> {
        let url = self.evaluate(&format!(
            "(() => {{ try {{ return {}.page.capture(); }} catch (e) {{ return 'error: ' + (e.message || e); }} }})()",
            self.state()
        ))?;
        let Some(encoded) = url.strip_prefix("data:image/png;base64,") else {
            bail!("{}: the canvas did not come back: {url}", self.lesson);
        };
        let png = base64::engine::general_purpose::STANDARD
            .decode(encoded)
            .context("the canvas's PNG is not base64")?;
        Ok(image::load_from_memory(&png)?.to_rgba8())
    }

    /// Sets a control of the page as a reader does: picks `value` in the select that `selector`
    /// finds under the lesson's block, and tells the page it changed. Fails if there is no such
    /// select or value, or the value is disabled.
    pub fn choose(&self, selector: &str, value: &str) -> Result<()> {
        let answer = self.evaluate(&format!(
            "(() => {{
                 const select = document.querySelector('div.live[data-lesson=\"{0}\"] {selector}');
                 if (!select) return 'no control {selector}';
                 const option = [...select.options].find((o) => o.value === {value:?});
                 if (!option) return 'no value {value} in {selector}';
                 if (option.disabled) return 'value {value} is disabled: ' + option.title;
                 select.value = {value:?};
                 select.dispatchEvent(new Event('change'));
                 const status = document.querySelector('div.live[data-lesson=\"{0}\"] p.live-status');
                 return 'failed' in status.dataset ? status.textContent : 'ok';
             }})()",
            self.lesson
        ))?;
        if answer != "ok" {
            bail!("{}: {answer}", self.lesson);
        }
        Ok(())
    }

    /// Sets a knob through its select.
    pub fn set_knob(&self, name: &str, value: &str) -> Result<()> {
        self.choose(&format!("select[data-knob=\"{name}\"]"), value)
    }

    /// Stops the frame after step `step` (0: the whole frame) through the step select.
    pub fn set_step(&self, step: usize) -> Result<()> {
        self.choose("select[data-control=\"step\"]", &step.to_string())
    }

    /// Shows a buffer through the buffer select.
    pub fn set_show(&self, buffer: &str) -> Result<()> {
        self.choose("select[data-control=\"show\"]", buffer)
    }

    /// With the test map shown, maps draw `draw` of the step (from 1), or every draw with 0,
    /// through the draw select.
    pub fn set_draw(&self, draw: usize) -> Result<()> {
        self.choose("select[data-control=\"draw\"]", &draw.to_string())
    }

    /// Sets the camera (the page's is the mouse's; this is `--camera`).
    pub fn set_camera(&self, pose: &str) -> Result<()> {
        let answer = self.evaluate(&format!(
            "(() => {{ try {{ {0}.page.set_camera({pose:?}); {0}.redraw(); {0}.refresh(); return 'ok'; }} catch (e) {{ return String(e.message || e); }} }})()",
            self.state()
        ))?;
        if answer != "ok" {
            bail!("{}: {answer}", self.lesson);
        }
        Ok(())
    }

    /// Puts the camera back where the lesson starts, with the page's button.
    pub fn reset_camera(&self) -> Result<()> {
        let answer = self.evaluate(&format!(
            "(() => {{ const b = document.querySelector('div.live[data-lesson=\"{}\"] button.live-reset');
                 if (!b) return 'no button to reset the camera'; b.click(); return 'ok'; }})()",
            self.lesson
        ))?;
        if answer != "ok" {
            bail!("{}: {answer}", self.lesson);
        }
        Ok(())
    }

    /// A screenshot of the page as the browser shows it (through the DevTools protocol, which sees
    /// a WebGPU canvas where Chromium's `--screenshot` does not); with `only_lesson`, of the
    /// lesson's block alone: the canvas and its controls.
    pub fn screenshot(&self, only_lesson: bool) -> Result<Vec<u8>> {
        let rect = self.evaluate(&format!(
            "(() => {{ const block = document.querySelector('div.live[data-lesson=\"{}\"]');
                 block.scrollIntoView();
                 const r = block.getBoundingClientRect();
                 return [r.x + window.scrollX, r.y + window.scrollY, r.width, r.height].map(Math.round).join(','); }})()",
            self.lesson
        ))?;
        let rect: Vec<f64> = rect.split(',').filter_map(|n| n.parse().ok()).collect();
        let clip = (only_lesson && rect.len() == 4).then(|| {
            headless_chrome::protocol::cdp::Page::Viewport {
                x: rect[0] - 8.0,
                y: rect[1] - 8.0,
                width: rect[2] + 16.0,
                height: rect[3] + 16.0,
                scale: 1.0,
            }
        });
        screenshot_of(&self.tab, clip)
    }

    /// The "same on your machine" line the page shows.
    pub fn command_line(&self) -> Result<String> {
        self.evaluate(&format!(
            "document.querySelector('div.live[data-lesson=\"{}\"] code.live-command').textContent",
            self.lesson
        ))
    }

    /// Every knob back at its default, through the knobs' selects.
    pub fn default_knobs(&self) -> Result<()> {
        let description = self.evaluate(&format!("{}.page.describe()", self.state()))?;
        let description: serde_json::Value =
            serde_json::from_str(&description).context("the page's description is not JSON")?;
        let knobs = description["knobs"].as_array().cloned().unwrap_or_default();
        for knob in knobs {
            if let (Some(name), Some(default)) = (knob["name"].as_str(), knob["default"].as_str()) {
                self.set_knob(name, default)?;
            }
        }
        Ok(())
    }

    /// Touches the screen at `points` (CSS pixels of the page's viewport) as `kind` says
    /// (`touchStart`, `touchMove`, `touchEnd`), a finger each.
    pub fn touch(&self, kind: &str, points: &[(f64, f64)]) -> Result<()> {
        use headless_chrome::protocol::cdp::Input;
        let points: Vec<serde_json::Value> = (points.iter().enumerate())
            .map(|(id, (x, y))| serde_json::json!({ "x": x, "y": y, "id": id }))
            .collect();
        let event: Input::DispatchTouchEvent =
            serde_json::from_value(serde_json::json!({ "type": kind, "touchPoints": points }))?;
        self.tab
            .call_method(event)
            .map_err(|e| anyhow!("cannot touch the page: {e}"))?;
        Ok(())
    }

    /// Where the canvas is in the page's viewport: its centre and its width, in CSS pixels,
    /// scrolled into view.
    pub fn canvas_on_screen(&self) -> Result<((f64, f64), f64)> {
        let found = self.evaluate(&format!(
            "(() => {{ const c = document.querySelector('div.live[data-lesson=\"{}\"] canvas');
                 c.scrollIntoView({{ block: 'center' }});
                 const r = c.getBoundingClientRect();
                 return [r.left + r.width / 2, r.top + r.height / 2, r.width].join(','); }})()",
            self.lesson
        ))?;
        let found: Vec<f64> = found.split(',').filter_map(|n| n.parse().ok()).collect();
        match found[..] {
            [x, y, width] => Ok(((x, y), width)),
            _ => bail!("{}: no canvas on the screen", self.lesson),
        }
    }

    /// The camera as the page's command line writes it: yaw, pitch, distance.
    pub fn camera(&self) -> Result<[f64; 3]> {
        let pose = self.evaluate(&format!(
            "JSON.parse({}.page.describe()).camera",
            self.state()
        ))?;
        let pose: Vec<f64> = pose.split(',').filter_map(|n| n.parse().ok()).collect();
        pose.try_into().map_err(|pose| {
            anyhow!(
                "{}: the camera is not yaw,pitch,distance: {pose:?}",
                self.lesson
            )
        })
    }

    /// Clicks pixel (`x`, `y`) of the canvas with the mouse, as a reader does, and returns what the
    /// page then shows under its controls: the pixel's story, or why there is none.
    pub fn click_pixel(&self, x: u32, y: u32) -> Result<String> {
        let point = self.evaluate(&format!(
            "(() => {{ const c = document.querySelector('div.live[data-lesson=\"{}\"] canvas');
                 // What the story shows before the click is not its answer: the click's story
                 // replaces it (a poll that came before the click's events were handled read the
                 // last pixel's story).
                 {}.story.querySelectorAll('*').forEach((e) => (e.dataset.old = ''));
                 c.scrollIntoView({{ block: 'center' }});
                 const r = c.getBoundingClientRect();
                 return [r.left + ({x} + 0.5) * r.width / c.width,
                         r.top + ({y} + 0.5) * r.height / c.height].join(','); }})()",
            self.lesson,
            self.state()
        ))?;
        let point: Vec<f64> = point.split(',').filter_map(|n| n.parse().ok()).collect();
        let [x, y] = point[..] else {
            bail!("{}: no canvas to click", self.lesson);
        };
        self.tab
            .click_point(headless_chrome::browser::tab::point::Point { x, y })
            .map_err(|e| anyhow!("cannot click the canvas: {e}"))?;
        self.story_told()
    }

    /// Taps the canvas at `point` (CSS pixels of the viewport) with a finger, and returns what the
    /// page then shows under its controls, as [`Self::click_pixel`] does.
    pub fn tap(&self, point: (f64, f64)) -> Result<String> {
        self.evaluate(&format!(
            "{}.story.querySelectorAll('*').forEach((e) => (e.dataset.old = ''))",
            self.state()
        ))?;
        self.touch("touchStart", &[point])?;
        self.touch("touchEnd", &[])?;
        self.story_told()
    }

    /// The story told after the last click or tap (not one shown before it), or why there is none.
    fn story_told(&self) -> Result<String> {
        self.evaluate(&format!(
            "new Promise((resolve) => {{
                 const state = {};
                 const t0 = performance.now();
                 (function poll() {{
                     const told = state.story.querySelector('pre:not([data-old])');
                     const failed = state.story.querySelector('[data-failed]:not([data-old])');
                     if (!state.telling && (told || failed))
                         resolve(told ? told.textContent : failed.textContent);
                     else if (performance.now() - t0 > 60000) resolve('no story in 60 s');
                     else setTimeout(poll, 20);
                 }})();
             }})",
            self.state()
        ))
    }

    /// Waits for the lesson clicked to run: `first frame SECONDS` once it has drawn its first
    /// frame, or `error: WHY`.
    fn started(&self) -> Result<String> {
        self.evaluate(&format!(
            "new Promise((resolve) => {{
                 const t0 = performance.now();
                 (function poll() {{
                     const s = {};
                     if (s && s.error) resolve('error: ' + s.error);
                     else if (s && s.page) resolve('first frame ' + s.firstFrame);
                     else if (performance.now() - t0 > 100000) resolve('error: no first frame in 100 s');
                     else setTimeout(poll, 20);
                 }})();
             }})",
            self.state()
        ))
    }

    /// Loses the lesson's GPU as a reset would: the WebGPU device destroyed, or the WebGL2
    /// context lost (`WEBGL_lose_context`). Returns what the status line says then.
    pub fn lose_the_gpu(&self) -> Result<String> {
        let said = self.evaluate(&format!(
            "new Promise((resolve) => {{
                 const state = {state};
                 const canvas = document.querySelector('div.live[data-lesson=\"{lesson}\"] canvas');
                 if (state.device) state.device.destroy();
                 else canvas.getContext('webgl2').getExtension('WEBGL_lose_context').loseContext();
                 const status = document.querySelector('div.live[data-lesson=\"{lesson}\"] p.live-status');
                 const t0 = performance.now();
                 (function poll() {{
                     if ('lost' in status.dataset) resolve(status.textContent);
                     else if (performance.now() - t0 > 10000) resolve('error: the page did not notice in 10 s: ' + status.textContent);
                     else setTimeout(poll, 20);
                 }})();
             }})",
            state = self.state(),
            lesson = self.lesson
        ))?;
        if said.starts_with("error: ") {
            bail!("{}: {said}", self.lesson);
        }
        Ok(said)
    }

    /// Clicks the status line's "Run again" after a lost GPU, and waits for the lesson's first
    /// frame.
    pub fn run_again(&mut self) -> Result<()> {
        let clicked = self.evaluate(&format!(
            "(() => {{ const again = document.querySelector('div.live[data-lesson=\"{}\"] p.live-status button.live-run');
                 if (!again) return 'no Run again button';
                 again.click(); return 'ok'; }})()",
            self.lesson
        ))?;
        if clicked != "ok" {
            bail!("{}: {clicked}", self.lesson);
        }
        let started = self.started()?;
        match started.strip_prefix("first frame ") {
            Some(seconds) => self.first_frame = seconds.parse::<f64>().unwrap_or(f64::NAN),
            None => bail!("{} did not start again: {started}", self.lesson),
        }
        Ok(())
    }

    /// The page's memory, after a garbage collection (see [`PageMemory`]).
    pub fn memory(&self) -> Result<PageMemory> {
        use headless_chrome::protocol::cdp::{HeapProfiler, Memory, Runtime};
        self.tab
            .call_method(HeapProfiler::CollectGarbage(None))
            .map_err(|e| anyhow!("no garbage collection: {e}"))?;
        let heap = (self.tab)
            .call_method(Runtime::GetHeapUsage(None))
            .map_err(|e| anyhow!("no heap usage: {e}"))?;
        let dom = (self.tab)
            .call_method(Memory::GetDOMCounters(None))
            .map_err(|e| anyhow!("no DOM counters: {e}"))?;
        let module = self.evaluate(
            "(() => { const live = window.workbookLive;
                 return live.bindings.heap_bytes() + ',' + live.wasm.memory.buffer.byteLength; })()",
        )?;
        let Some((Ok(rust_heap), Ok(wasm))) = module
            .split_once(',')
            .map(|(heap, wasm)| (heap.parse::<u64>(), wasm.parse::<u64>()))
        else {
            bail!("the module's heap and memory are `{module}`");
        };
        Ok(PageMemory {
            js_heap: heap.used_size as u64,
            dom_nodes: u64::from(dom.nodes),
            listeners: u64::from(dom.js_event_listeners),
            rust_heap,
            wasm,
        })
    }

    /// A screenshot of the viewport as a phone's screen shows it, one pixel a point (the phone
    /// draws three), the lesson's block scrolled to the top.
    pub fn phone_screenshot(&self) -> Result<Vec<u8>> {
        let rect = self.evaluate(&format!(
            "(() => {{ const block = document.querySelector('div.live[data-lesson=\"{}\"]');
                 block.scrollIntoView();
                 return [window.scrollX, window.scrollY, window.innerWidth, window.innerHeight].join(','); }})()",
            self.lesson
        ))?;
        let rect: Vec<f64> = rect.split(',').filter_map(|n| n.parse().ok()).collect();
        let [x, y, width, height] = rect[..] else {
            bail!("no viewport: {rect:?}");
        };
        let clip = headless_chrome::protocol::cdp::Page::Viewport {
            x,
            y,
            width,
            height,
            scale: 1.0 / 3.0,
        };
        screenshot_of(&self.tab, Some(clip))
    }

    /// Turns the lesson's first knob that has another value than its default to that value,
    /// through its select; the knob and the value.
    pub fn a_knob_away_from_its_default(&self) -> Result<(String, String)> {
        let found = self.evaluate(&format!(
            "(() => {{ const info = JSON.parse({}.page.describe());
                 const other = (k) => k.values.find((v) => v !== k.default && !k.unavailable[v]);
                 const knob = info.knobs.find(other);
                 return knob ? knob.name + '=' + other(knob) : ''; }})()",
            self.state()
        ))?;
        let Some((name, value)) = found.split_once('=') else {
            bail!(
                "{}: no knob with another value than its default",
                self.lesson
            );
        };
        self.set_knob(name, value)?;
        Ok((name.to_string(), value.to_string()))
    }

    /// Gives the canvas a new size in pixels, as a page whose layout changed does.
    pub fn resize(&self, width: u32, height: u32) -> Result<()> {
        let done = self.evaluate(&format!(
            "(() => {{ const state = {state};
                 const canvas = document.querySelector('div.live[data-lesson=\"{lesson}\"] canvas');
                 canvas.width = {width}; canvas.height = {height};
                 try {{ state.page.resize({width}, {height}); state.page.draw(); return 'ok'; }}
                 catch (e) {{ return 'error: ' + (e.message || e); }} }})()",
            state = self.state(),
            lesson = self.lesson
        ))?;
        if done != "ok" {
            bail!("{}: {done}", self.lesson);
        }
        Ok(())
    }

    /// Draws `frames` frames as a reader's drag does: the camera orbits a little before each, and
    /// every tenth frame the controls are made again (as when a drag ends); the page's tasks run
    /// in between.
    pub fn draw_frames(&self, frames: u64) -> Result<()> {
        let done = self.evaluate(&format!(
            "(async () => {{ const state = {};
                 try {{
                     for (let i = 1; i <= {frames}; i++) {{
                         state.page.orbit(2, 0);
                         state.page.draw();
                         if (i % 10 === 0) {{
                             state.refresh();
                             await new Promise((resolve) => setTimeout(resolve, 0));
                         }}
                     }}
                     return 'ok';
                 }} catch (e) {{ return 'error: ' + (e.message || e); }} }})()",
            self.state()
        ))?;
        if done != "ok" {
            bail!("{}: {done}", self.lesson);
        }
        Ok(())
    }

    /// The status line (backend and adapter, or an error).
    pub fn status(&self) -> Result<String> {
        self.evaluate(&format!(
            "document.querySelector('div.live[data-lesson=\"{}\"] p.live-status').textContent",
            self.lesson
        ))
    }
}
