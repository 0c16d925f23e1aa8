// The book's languages: a picker in the menu bar that keeps the reader on the same page (English
// at the book's root, 简体中文 under zh-CN/), and, in a translated book, mdBook's own interface words
// (the menu bar's titles, the search box and its results, the keyboard help, the page arrows).
// The book's text itself is translated by gettext (book/po); this only covers mdBook's template.
(function () {
  "use strict";

  const LANGUAGES = [
    { code: "en", name: "English", dir: "" },
    { code: "zh-CN", name: "简体中文", dir: "zh-CN/" },
  ];

  // mdBook's interface words, by language: [CSS selector, attribute (null: the text), translation].
  const INTERFACE = {
    "zh-CN": [
      ["#mdbook-sidebar", "aria-label", "目录"],
      ["#mdbook-sidebar-toggle", "title", "显示或隐藏目录"],
      ["#mdbook-sidebar-toggle", "aria-label", "显示或隐藏目录"],
      ["#mdbook-theme-toggle", "title", "更换主题"],
      ["#mdbook-theme-toggle", "aria-label", "更换主题"],
      ["#mdbook-theme-list", "aria-label", "主题"],
      ["#mdbook-theme-default_theme", null, "自动"],
      ["#mdbook-theme-light", null, "亮色"],
      ["#mdbook-theme-rust", null, "Rust"],
      ["#mdbook-theme-coal", null, "煤黑"],
      ["#mdbook-theme-navy", null, "深蓝"],
      ["#mdbook-theme-ayu", null, "Ayu"],
      ["#mdbook-search-toggle", "title", "搜索（`/`）"],
      ["#mdbook-search-toggle", "aria-label", "显示或隐藏搜索栏"],
      ["#mdbook-searchbar", "placeholder", "搜索本书（中文、英文均可）"],
      ["a[href$='print.html']", "title", "打印本书"],
      ["a[href$='print.html']", "aria-label", "打印本书"],
      ["a[rel~='prev']", "title", "上一章"],
      ["a[rel~='prev']", "aria-label", "上一章"],
      ["a[rel~='next']", "title", "下一章"],
      ["a[rel~='next']", "aria-label", "下一章"],
      [".nav-wrapper, .nav-wide-wrapper", "aria-label", "翻页"],
      [".mdbook-help-title", null, "键盘快捷键"],
    ],
  };

  // The keyboard help's sentences and the search results' header, by language.
  const SENTENCES = {
    "zh-CN": {
      help: [
        "按 <kbd>←</kbd> 或 <kbd>→</kbd> 翻到上一章或下一章",
        "按 <kbd>S</kbd> 或 <kbd>/</kbd> 在本书中搜索",
        "按 <kbd>?</kbd> 显示本帮助",
        "按 <kbd>Esc</kbd> 隐藏本帮助",
      ],
      results: (count, term) => `找到 ${count} 条“${term}”的搜索结果：`,
      // The search finds Chinese words by their pairs of characters (web/search.js): what finds
      // nothing is not in the book, or is said otherwise.
      none: (term) => `没有找到“${term}”。试试更短的词，或换用英文术语。`,
    },
  };

  const html = document.documentElement;
  const here = LANGUAGES.find((l) => l.code === html.lang) || LANGUAGES[0];

  // This page's address from the book's root, and the root of each language's book.
  function roots() {
    // path_to_root is "" on a page at the root ("./" is the folder, "" would be the page itself).
    const root = new URL((typeof path_to_root === "string" && path_to_root) || "./", location.href);
    const page = location.href.slice(root.href.length) || "index.html";
    const top = here.dir ? new URL("../", root) : root;
    return { page, top };
  }

  function picker() {
    const bar = document.querySelector("#mdbook-menu-bar .right-buttons");
    if (!bar) return;
    const { page, top } = roots();
    const wrap = document.createElement("div");
    wrap.className = "language-picker";
    const button = document.createElement("button");
    button.id = "language-toggle";
    button.className = "icon-button";
    button.type = "button";
    button.title = here.code === "zh-CN" ? "语言 / Language" : "Language / 语言";
    button.setAttribute("aria-label", button.title);
    button.setAttribute("aria-haspopup", "true");
    button.setAttribute("aria-expanded", "false");
    button.textContent = "文A";
    const list = document.createElement("ul");
    list.id = "language-list";
    list.className = "theme-popup";
    list.setAttribute("role", "menu");
    for (const language of LANGUAGES) {
      const item = document.createElement("li");
      item.setAttribute("role", "none");
      const link = document.createElement("a");
      link.setAttribute("role", "menuitem");
      link.className = "theme" + (language === here ? " theme-selected" : "");
      link.lang = language.code;
      link.hreflang = language.code;
      link.href = new URL(language.dir + page, top).href;
      link.textContent = language.name;
      item.appendChild(link);
      list.appendChild(item);
    }
    // mdBook's popup style hides the list (display: none) until it is shown.
    const show = (open) => {
      list.style.display = open ? "block" : "none";
      button.setAttribute("aria-expanded", String(open));
    };
    button.addEventListener("click", (event) => {
      event.stopPropagation();
      show(list.style.display !== "block");
    });
    document.addEventListener("click", () => show(false));
    wrap.appendChild(button);
    wrap.appendChild(list);
    bar.insertBefore(wrap, bar.firstChild);
  }

  function translateInterface() {
    const words = INTERFACE[here.code];
    const sentences = SENTENCES[here.code];
    if (!words) return;
    for (const [selector, attribute, text] of words) {
      for (const element of document.querySelectorAll(selector)) {
        if (attribute) element.setAttribute(attribute, text);
        else element.textContent = text;
      }
    }
    const help = document.querySelectorAll(".mdbook-help-popup p, #mdbook-help-popup p");
    help.forEach((p, i) => {
      if (sentences.help[i]) p.innerHTML = sentences.help[i];
    });
    const header = document.getElementById("mdbook-searchresults-header");
    if (header) {
      const translate = () => {
        const text = header.textContent;
        let m = text.match(/^(\d+) search results? for '(.*)':$/);
        if (m) header.textContent = sentences.results(m[1], m[2]);
        m = text.match(/^No search results for '(.*)'\.$/);
        if (m) header.textContent = sentences.none(m[1]);
      };
      new MutationObserver(translate).observe(header, {
        childList: true,
        characterData: true,
        subtree: true,
      });
      // A search from the page's address (?search=) may have run before this script.
      translate();
    }
  }

  picker();
  translateInterface();
})();
