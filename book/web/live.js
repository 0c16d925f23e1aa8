// The web edition: a lesson live in its book page. Each lesson page has, above its first figure,
//
//     <div class="live" data-lesson="reflect-skull"></div>
//
// which this script turns into a "Run" bar. Nothing is loaded until the reader clicks it: then the
// workbook's WebAssembly module (built by `cargo web` into live/) starts the lesson in a canvas, on
// WebGPU where the browser has it, else WebGL2, and the controls below the canvas are made from the
// lesson's own data (its knobs, the frame's steps, the buffers): the module's `describe()`.
// A click (not a drag) on the canvas picks a pixel: a cross marks it, and its story through the
// frame, as `--pixel X,Y` tells it, is shown under the controls and told again after every change.
//
// Where the browser has neither backend, the status line says which browsers run the lessons and
// gives the native command; a lost GPU (a reset, a tab put away on a phone) stops the lesson, and
// the status line's "Run again" starts it afresh.
//
// `?backend=webgl2` (or `webgpu`) in the page's address picks the backend. The tests read the
// canvas through `window.workbookLive` (see tests/src/web.rs).
//
// The page's own words are in the book's language (`WORDS`, chosen by the page's `lang`); the
// program's words (knob names and values, step names, buffers, the command line, a pixel's story,
// the program's errors) stay as the program prints them, as the book quotes them.
(function () {
  "use strict";

  // The book's size: the canvas draws the very picture of the book's figures.
  const WIDTH = 800;
  const HEIGHT = 450;
  const root = typeof path_to_root === "string" ? path_to_root : "";
  const live = (window.workbookLive = window.workbookLive || {});
  let module = null;

  // The page's own words, by language; each language has every key (`cargo web-test` checks).
  const WORDS = {
    en: {
      run: (lesson) => "▶ Run " + lesson + " live in this page (WebGPU, or WebGL2)",
      starting: (lesson) => "starting " + lesson + "…",
      cannot: (why) =>
        "This browser cannot run the lesson here (" + why + "): the figures below show its pictures.",
      running: (backend, adapter, seconds) =>
        backend + " on " + adapter + " · first frame " + seconds + " s after Run",
      anAdapter: "this browser's adapter",
      error: (why) => "error: " + why,
      pickAPixel: (touch) =>
        (touch ? "Tap" : "Click") + " a pixel of the picture to read its story through the frame.",
      told: (x, y, touch) =>
        "Pixel " + x + "," + y + " (" + (touch ? "tap" : "click") + " another, or drag to orbit). " +
        "The same on your machine: add --pixel " + x + "," + y + " to the command line above.",
      noStory: (x, y, why) => "No story for pixel " + x + "," + y + ": " + why,
      byDefault: " (default)",
      step: "step ",
      stepTitle: "stop the frame after a step, as --step",
      wholeFrame: "the whole frame",
      after: (number, name) => "after " + number + ". " + name,
      buffer: "buffer ",
      bufferTitle: "the buffer shown, as --show",
      draw: "draw ",
      drawTitle: "the draw whose fragments the test map paints, as --draw",
      everyDraw: "every draw of the step",
      lessonsView: "the lesson's view",
      lessonsViewTitle: "put the camera back where the lesson starts",
      copy: "copy",
      copied: "copied",
      selectToCopy: "select the line to copy it",
      same: "The same on your machine: ",
      noBackend: (lesson, why) =>
        "Neither WebGPU nor WebGL2 runs in this browser (" + why + "), so the lesson cannot run here: " +
        "the figures below show its pictures. The lessons run live in Chrome and Edge 113 or later, " +
        "Firefox 141 or later and Safari 26 or later on WebGPU, and in any browser since Chrome 56, " +
        "Firefox 51 and Safari 15 on WebGL2, with hardware acceleration turned on (in Chrome: " +
        "Settings → System; on Linux, WebGPU behind chrome://flags/#enable-unsafe-webgpu). Or on your " +
        "machine: cargo run -p " + lesson,
      lost: (why) => "The GPU was lost (" + why + "): the lesson stopped. ",
      runAgain: "▶ Run again",
    },
    "zh-CN": {
      run: (lesson) => "▶ 在本页中运行 " + lesson + "（WebGPU，或 WebGL2）",
      starting: (lesson) => "正在启动 " + lesson + "…",
      cannot: (why) => "此浏览器无法在这里运行本课（" + why + "）：下面的插图就是它的画面。",
      running: (backend, adapter, seconds) =>
        backend + "，运行在 " + adapter + " 上 · 点击运行后 " + seconds + " 秒画出第一帧",
      anAdapter: "此浏览器的适配器",
      error: (why) => "错误：" + why,
      pickAPixel: (touch) => (touch ? "轻点" : "点击") + "画面上的一个像素，读它在这一帧中的故事。",
      told: (x, y) =>
        "像素 " + x + "," + y + "（可以再点一个，或拖动画面环绕旋转）。在你的机器上：在上面的命令行末尾加上 --pixel " +
        x + "," + y + "。",
      noStory: (x, y, why) => "像素 " + x + "," + y + " 没有故事：" + why,
      byDefault: "（默认）",
      step: "步骤 ",
      stepTitle: "让帧停在某一步之后，相当于 --step",
      wholeFrame: "整个帧",
      after: (number, name) => "第 " + number + " 步之后：" + name,
      buffer: "缓冲区 ",
      bufferTitle: "显示的缓冲区，相当于 --show",
      draw: "绘制 ",
      drawTitle: "测试图为哪一次绘制的片元着色，相当于 --draw",
      everyDraw: "这一步的每一次绘制",
      lessonsView: "回到本课的视角",
      lessonsViewTitle: "把摄像机放回本课开始时的位置",
      copy: "复制",
      copied: "已复制",
      selectToCopy: "请选中这一行来复制",
      same: "在你的机器上运行：",
      noBackend: (lesson, why) =>
        "此浏览器既不能运行 WebGPU，也不能运行 WebGL2（" + why + "），所以本课无法在这里运行：" +
        "下面的插图就是它的画面。能在页面中运行本书各课的浏览器：WebGPU 需要 Chrome 和 Edge 113 及以上、" +
        "Firefox 141 及以上、Safari 26 及以上；WebGL2 则 Chrome 56、Firefox 51、Safari 15 以来的浏览器都有；" +
        "都要打开硬件加速（Chrome：设置 → 系统；在 Linux 上，WebGPU 要在 chrome://flags/#enable-unsafe-webgpu 中打开）。" +
        "也可以在你的机器上运行：cargo run -p " + lesson,
      lost: (why) => "GPU 丢失了（" + why + "）：本课已停止。",
      runAgain: "▶ 重新运行",
    },
  };
  const words = WORDS[document.documentElement.lang] || WORDS.en;
  // For the tests: every language's words missing from it, by language (none, or a word shows in
  // English on that language's pages).
  live.untranslated = Object.fromEntries(
    Object.keys(WORDS).map((lang) => [lang, Object.keys(WORDS.en).filter((key) => !(key in WORDS[lang]))]),
  );


  function element(tag, attributes, children) {
    const node = document.createElement(tag);
    for (const [name, value] of Object.entries(attributes || {})) {
      if (name === "text") node.textContent = value;
      else node.setAttribute(name, value);
    }
    for (const child of children || []) node.append(child);
    return node;
  }

  // An error of the lesson's, said in the status line (marked for the tests: `data-failed`).
  function fail(status, error) {
    status.textContent = words.error(error.message || error);
    status.dataset.failed = "";
  }

  function loadModule() {
    if (!module) {
      const url = (file) => new URL(root + "live/" + file, document.baseURI).href;
      module = import(url("workbook_web.js")).then(async (bindings) => {
        // The module's memory and its Rust heap (`heap_bytes`), which the tests watch over a long
        // session.
        live.wasm = await bindings.default({ module_or_path: url("workbook_web_bg.wasm") });
        live.bindings = bindings;
        return bindings;
      });
    }
    return module;
  }

  // wgpu 30.0.1's WebGPU backend leaves `occlusionQuerySet` out of every render pass it begins
  // (`begin_render_pass` in its src/backend/webgpu.rs), and a pixel's story asks each draw with an
  // occlusion query whether it reaches the pixel and whether it passes. While a story is read
  // (`live.probing`: nothing else is drawn then), every pass begun gets the occlusion query set
  // made last, the story's. To go once wgpu passes the set on; `cargo web-test` tells stories.
  function passOcclusionQueriesOn() {
    if (typeof GPUDevice === "undefined" || GPUDevice.prototype.createQuerySet.workbook) return;
    let latest = null;
    const create = GPUDevice.prototype.createQuerySet;
    GPUDevice.prototype.createQuerySet = function (descriptor) {
      const set = create.call(this, descriptor);
      if (descriptor && descriptor.type === "occlusion") latest = set;
      return set;
    };
    GPUDevice.prototype.createQuerySet.workbook = true;
    const begin = GPUCommandEncoder.prototype.beginRenderPass;
    GPUCommandEncoder.prototype.beginRenderPass = function (descriptor) {
      if (live.probing && latest && descriptor && !descriptor.occlusionQuerySet) {
        descriptor.occlusionQuerySet = latest;
      }
      return begin.call(this, descriptor);
    };
  }

  // The WebGPU device a lesson starts with, kept for its `lost` promise: the page learns of a lost
  // GPU (a reset, a driver's update, a tab put away on a phone) only from it. The device is made
  // inside wgpu (`requestDevice`), so the one made while a lesson starts is caught on its way out.
  function catchDevices() {
    if (typeof GPUAdapter === "undefined" || GPUAdapter.prototype.requestDevice.workbook) return;
    const request = GPUAdapter.prototype.requestDevice;
    GPUAdapter.prototype.requestDevice = async function (descriptor) {
      const device = await request.call(this, descriptor);
      if (live.starting) live.starting.device = device;
      return device;
    };
    GPUAdapter.prototype.requestDevice.workbook = true;
  }

  // The backends this browser has, by name: WebGPU where it gives an adapter, WebGL2 where a canvas
  // gives its context.
  async function backendsHere() {
    const found = [];
    try {
      if (navigator.gpu && (await navigator.gpu.requestAdapter())) found.push("WebGPU");
    } catch (error) {
      // none
    }
    try {
      if (document.createElement("canvas").getContext("webgl2")) found.push("WebGL2");
    } catch (error) {
      // none
    }
    return found;
  }

  // Whether the reader's pointer is a finger (the page then says "tap", not "click").
  function onATouchScreen() {
    return window.matchMedia("(pointer: coarse)").matches;
  }

  function wanted_backend() {
    return new URLSearchParams(window.location.search).get("backend") || "any";
  }

  async function run(container, bar) {
    const lesson = container.dataset.lesson;
    const started = performance.now();
    const status = element("p", { class: "live-status", text: words.starting(lesson) });
    bar.replaceWith(status);
    const canvas = element("canvas", { width: WIDTH, height: HEIGHT, class: "live-canvas" });
    canvas.setAttribute("tabindex", "0");
    const cross = element("div", { class: "live-cross", hidden: "" });
    const view = element("div", { class: "live-view" }, [canvas, cross]);
    const starting = (live.starting = {});
    let page;
    try {
      const bindings = await loadModule();
      passOcclusionQueriesOn();
      catchDevices();
      container.prepend(view);
      page = await bindings.start(canvas, lesson, root + "live/assets", wanted_backend());
      page.draw();
    } catch (error) {
      view.remove();
      const why = String(error.message || error);
      const here = await backendsHere();
      status.textContent = here.length ? words.cannot(why) : words.noBackend(lesson, why);
      status.dataset.failed = "";
      live[lesson] = { error: why, backends: here };
      return;
    } finally {
      live.starting = null;
    }
    const firstFrame = (performance.now() - started) / 1000;
    const info = JSON.parse(page.describe());
    const adapter = (await adapterName(info)) || words.anAdapter;
    status.textContent = words.running(info.backend, adapter, firstFrame.toFixed(2));
    // `telling`: the promise of a pixel's story being read; the lesson is busy until it is.
    // `lost`: why the GPU was lost, once it is; nothing is drawn or told after.
    const state = { page, dirty: false, firstFrame, controls: null, telling: null, pixel: null };
    state.device = starting.device || null;
    const redraw = () => {
      if (!state.dirty && !state.lost) {
        state.dirty = true;
        requestAnimationFrame(function frame() {
          if (state.telling) return void state.telling.then(() => requestAnimationFrame(frame));
          state.dirty = false;
          if (state.lost) return;
          try {
            page.draw();
          } catch (error) {
            fail(status, error);
          }
        });
      }
    };
    state.redraw = redraw;
    const controls = element("div", { class: "live-controls" });
    const story = element("div", { class: "live-story" }, [
      element("p", { text: words.pickAPixel(onATouchScreen()) }),
    ]);
    container.append(controls, story);
    state.story = story;
    state.tell = () => tell(state, canvas, cross, story);
    // A change waits while a story is read (the lesson is busy), then is made.
    const whenFree = (work) => (state.telling ? state.telling.then(() => whenFree(work)) : work());
    const refresh = () => {
      if (state.lost) return;
      build(controls, page, status, redraw, refresh, whenFree);
      if (state.pixel) state.tell();
    };
    state.controls = controls;
    state.refresh = refresh;
    build(controls, page, status, redraw, refresh, whenFree);
    orbitWithThePointer(canvas, state);
    whenLost(container, state, status, [view, controls, story]);
    // Last: the tests wait for this, and then find the page complete.
    live[lesson] = state;
  }

  // A lost GPU stops the lesson: the status line says why, and its button starts the lesson again
  // on a new canvas (a lost WebGL2 context stays lost on its own) with a new device. The old
  // lesson is freed once no pixel's story holds it.
  function whenLost(container, state, status, shown) {
    const lesson = container.dataset.lesson;
    const lost = (why) => {
      if (state.lost) return;
      state.lost = why || "?";
      live[lesson] = { lost: state.lost };
      const again = element("button", { type: "button", class: "live-run", text: words.runAgain });
      status.replaceChildren(words.lost(state.lost), again);
      status.dataset.lost = "";
      again.addEventListener(
        "click",
        () => {
          const restart = () => {
            shown.forEach((node) => node.remove());
            state.page.free();
            run(container, status);
          };
          if (state.telling) state.telling.then(restart);
          else restart();
        },
        { once: true },
      );
    };
    if (state.device) state.device.lost.then((info) => lost(info.message || info.reason));
    const canvas = shown[0].querySelector("canvas");
    // Not `preventDefault()`: that would ask the browser for the context back, on a canvas that
    // wgpu's objects no longer fit; the lesson starts again on a new one instead.
    canvas.addEventListener("webglcontextlost", () => lost("WebGL2: webglcontextlost"));
  }

  // WebGPU keeps the adapter's description to itself in most browsers; its vendor and architecture
  // say enough (e.g. "google swiftshader").
  async function adapterName(info) {
    if (info.adapter || info.backend !== "WebGPU" || !navigator.gpu) return info.adapter;
    try {
      const adapter = await navigator.gpu.requestAdapter();
      const about = (adapter && adapter.info) || {};
      return [about.vendor, about.architecture].filter(Boolean).join(" ");
    } catch (error) {
      return "";
    }
  }

  // Drag to orbit, wheel to zoom, as in the window; a click that does not drag picks a pixel. On a
  // touch screen the same with a finger (a tap picks), and two fingers pinch to zoom.
  // While a pixel's story is read the lesson is busy: the pointer waits.
  function orbitWithThePointer(canvas, state) {
    const { page } = state;
    // The canvas may be drawn smaller than its pixels: move as if at full size.
    const scale = () => canvas.width / canvas.getBoundingClientRect().width;
    const down = new Map();
    let last = null;
    let dragged = 0;
    // The two fingers' distance at the last move, while they pinch.
    let pinch = null;
    const spread = () => {
      const [a, b] = [...down.values()];
      return Math.hypot(a[0] - b[0], a[1] - b[1]);
    };
    canvas.addEventListener("pointerdown", (event) => {
      if (state.telling) return;
      down.set(event.pointerId, [event.clientX, event.clientY]);
      canvas.setPointerCapture(event.pointerId);
      if (down.size === 2) {
        // A pinch, not a drag: no pixel is picked when its fingers lift.
        pinch = spread();
        dragged = Infinity;
        return;
      }
      last = [event.clientX, event.clientY];
      dragged = 0;
    });
    canvas.addEventListener("pointermove", (event) => {
      if (!down.has(event.pointerId) || state.telling) return;
      down.set(event.pointerId, [event.clientX, event.clientY]);
      if (pinch !== null && down.size === 2) {
        // The camera's distance follows the fingers' (a step of the wheel is a factor of 0.9).
        const now = spread();
        if (now > 0 && pinch > 0) page.zoom(Math.log(now / pinch) / -Math.log(0.9));
        pinch = now;
        state.redraw();
        return;
      }
      if (!last) return;
      const [dx, dy] = [event.clientX - last[0], event.clientY - last[1]];
      dragged += Math.abs(dx) + Math.abs(dy);
      page.orbit(dx * scale(), dy * scale());
      last = [event.clientX, event.clientY];
      state.redraw();
    });
    // When a drag ends the pose is rounded as `--camera` writes it, so that the command line
    // below draws exactly the picture on the canvas.
    const stop = (event) => {
      if (!down.delete(event.pointerId)) return;
      if (down.size > 0) {
        last = null;
        return;
      }
      pinch = null;
      if (dragged < 3 && event.type === "pointerup") {
        state.touched = event.pointerType === "touch";
        const box = canvas.getBoundingClientRect();
        const x = Math.floor((event.clientX - box.left) * scale());
        const y = Math.floor((event.clientY - box.top) * (canvas.height / box.height));
        if (x >= 0 && y >= 0 && x < canvas.width && y < canvas.height) state.pixel = [x, y];
      }
      last = null;
      page.set_camera(JSON.parse(page.describe()).camera);
      state.redraw();
      state.refresh();
    };
    canvas.addEventListener("pointerup", stop);
    canvas.addEventListener("pointercancel", stop);
    zoomWithTheWheel(canvas, state);
  }

  function zoomWithTheWheel(canvas, state) {
    const { page } = state;
    canvas.addEventListener(
      "wheel",
      (event) => {
        event.preventDefault();
        if (state.telling) return;
        page.zoom(-event.deltaY / 100);
        page.set_camera(JSON.parse(page.describe()).camera);
        state.redraw();
        state.refresh();
      },
      { passive: false },
    );
  }

  // Reads the picked pixel's story (again: after every change) and shows it under the controls,
  // the pixel marked with a cross. A story asked for while one is read waits for it.
  function tell(state, canvas, cross, story) {
    if (state.lost) return Promise.resolve("error: " + state.lost);
    if (state.telling) {
      state.again = true;
      return state.telling;
    }
    const [x, y] = state.pixel;
    cross.style.left = ((x + 0.5) / canvas.width) * 100 + "%";
    cross.style.top = ((y + 0.5) / canvas.height) * 100 + "%";
    cross.hidden = false;
    live.probing = true;
    state.telling = state.page.story(x, y).then(
      (text) => {
        const pre = element("pre", { class: "live-story-text", text });
        story.replaceChildren(
          element("p", { text: words.told(x, y, state.touched) }),
          pre,
        );
        return text;
      },
      (error) => {
        story.replaceChildren(
          element("p", { "data-failed": "", text: words.noStory(x, y, error.message || error) }),
        );
        return "error: " + (error.message || error);
      },
    ).finally(() => {
      live.probing = false;
      state.telling = null;
      if (state.again) {
        state.again = false;
        tell(state, canvas, cross, story);
      }
    });
    return state.telling;
  }

  // The controls, made again from the lesson's description after every change (a knob may change
  // the frame's steps).
  function build(controls, page, status, redraw, refresh, whenFree) {
    const info = JSON.parse(page.describe());
    const apply = (change) =>
      whenFree(() => {
        try {
          change();
        } catch (error) {
          fail(status, error);
        }
        redraw();
        refresh();
      });
    const rows = [];
    for (const knob of info.knobs) {
      const select = element("select", { "data-knob": knob.name, title: knob.meaning });
      for (const value of knob.values) {
        const why = knob.unavailable[value];
        const label = value + (value === knob.default ? words.byDefault : "");
        const option = element("option", { value, text: label });
        if (why) {
          option.disabled = true;
          option.title = why;
          option.textContent = label + " — " + why;
        }
        option.selected = value === knob.chosen;
        select.append(option);
      }
      select.addEventListener("change", () => apply(() => page.set_knob(knob.name, select.value)));
      rows.push(element("label", { title: knob.meaning }, [knob.name + " ", select]));
    }
    const step = element("select", { "data-control": "step", title: words.stepTitle });
    step.append(element("option", { value: "0", text: words.wholeFrame }));
    info.steps.forEach((name, index) => {
      step.append(element("option", { value: String(index + 1), text: words.after(index + 1, name) }));
    });
    step.value = String(info.step);
    step.addEventListener("change", () => apply(() => page.set_step(Number(step.value))));
    rows.push(element("label", {}, [words.step, step]));
    const show = element("select", { "data-control": "show", title: words.bufferTitle });
    for (const buffer of info.shows) {
      const option = element("option", { value: buffer.name, text: buffer.name });
      if (buffer.unavailable) {
        option.disabled = true;
        option.title = buffer.unavailable;
        option.textContent = buffer.name + " — " + buffer.unavailable;
      }
      show.append(option);
    }
    show.value = info.show;
    show.addEventListener("change", () => apply(() => page.set_show(show.value)));
    rows.push(element("label", {}, [words.buffer, show]));
    if (info.show === "tests") rows.push(drawChoice(info, page, apply));

    const reset = element("button", { type: "button", class: "live-reset", text: words.lessonsView });
    reset.title = words.lessonsViewTitle;
    reset.addEventListener("click", () => apply(() => page.reset_camera()));
    rows.push(reset);

    const command = element("code", { class: "live-command", text: info.command });
    const copy = element("button", { type: "button", text: words.copy });
    copy.addEventListener("click", () => {
      navigator.clipboard.writeText(info.command).then(
        () => (copy.textContent = words.copied),
        () => (copy.textContent = words.selectToCopy),
      );
    });
    const same = element("p", { class: "live-same" }, [
      words.same,
      command,
      " ",
      copy,
    ]);
    controls.replaceChildren(element("div", { class: "live-knobs" }, rows), same);
  }

  // With the test map shown: which of the step's draws it maps (as --draw), or every one.
  function drawChoice(info, page, apply) {
    const draw = element("select", { "data-control": "draw", title: words.drawTitle });
    draw.append(element("option", { value: "0", text: words.everyDraw }));
    info.draws.forEach((name, index) => {
      draw.append(element("option", { value: String(index + 1), text: name }));
    });
    draw.value = String(info.draw);
    draw.addEventListener("change", () => apply(() => page.set_draw(Number(draw.value))));
    return element("label", {}, [words.draw, draw]);
  }

  function setUp(container) {
    const bar = element("button", { type: "button", class: "live-run" }, [
      words.run(container.dataset.lesson),
    ]);
    bar.addEventListener("click", () => run(container, bar), { once: true });
    container.append(bar);
  }

  function setUpAll() {
    document.querySelectorAll("div.live[data-lesson]").forEach(setUp);
  }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", setUpAll);
  else setUpAll();
})();
