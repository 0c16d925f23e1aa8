// The search in Chinese. mdBook's search (elasticlunr) cuts a query at spaces, which Chinese does
// not write, and its trimmer keeps only [A-Za-z0-9_] at a word's ends: a Chinese query found
// nothing. A Chinese book's index holds its Chinese as characters and overlapping pairs of
// characters (book/po/cjk-search.py, run by book/build.sh); this cuts a query the same way: each run
// of CJK characters into its pairs (模板缓冲区: 模板 板缓 缓冲 冲区; a single character stays one), the
// rest of a word that holds them at them and at CJK punctuation, and every other word as before.
// The pairs skip the pipeline (trimmer, stop words, stemmer), as they did going into the index.
// A query without CJK characters goes through elasticlunr's own tokenizer and pipeline untouched,
// so English search does not change; the originals stay at `elasticlunr.tokenizer.original` and
// `elasticlunr.Pipeline.prototype.run.original` (cargo book-test compares the two).
(function () {
  "use strict";

  const lunr = window.elasticlunr;
  if (!lunr || lunr.tokenizer.original) return;

  // As in cjk-search.py: kana, CJK ideographs and Hangul syllables; punctuation that parts words.
  const CJK = "\u3040-\u30ff\u3400-\u4dbf\u4e00-\u9fff\uf900-\ufaff\uac00-\ud7af";
  const SEPARATORS = "\u2010-\u2027\u2030-\u205e\u3000-\u303f\ufe10-\ufe1f\ufe30-\ufe4f\uff00-\uffef";
  const hasCjk = new RegExp(`[${CJK}]`);
  const onlyCjk = new RegExp(`^[${CJK}]+$`);
  const pieces = new RegExp(`([${CJK}]+)|[${SEPARATORS}]+`);

  // A run of CJK characters as the query's words: its overlapping pairs, or the one character.
  function pairs(run) {
    if (run.length < 2) return [run];
    const out = [];
    for (let i = 0; i + 1 < run.length; i++) out.push(run.slice(i, i + 2));
    return out;
  }

  const tokenizer = lunr.tokenizer;
  function tokenize() {
    const words = tokenizer.apply(this, arguments);
    if (!words.some((word) => hasCjk.test(word))) return words;
    const out = [];
    for (const word of words) {
      if (!hasCjk.test(word)) {
        out.push(word);
        continue;
      }
      // split() with a group: the text between matches at even places, the group at odd ones.
      word.split(pieces).forEach((piece, i) => {
        if (piece) out.push(...(i % 2 ? pairs(piece) : [piece]));
      });
    }
    return out;
  }
  // The separator and its setters: elasticlunr reads them from `elasticlunr.tokenizer`.
  Object.assign(tokenize, tokenizer, { original: tokenizer });
  lunr.tokenizer = tokenize;

  // The pipeline is looked up when a query runs, not when the index is loaded: so it also holds for
  // an index loaded before this script ran.
  const run = lunr.Pipeline.prototype.run;
  function runPipeline(tokens) {
    if (!Array.isArray(tokens) || !tokens.some((token) => onlyCjk.test(token))) {
      return run.apply(this, arguments);
    }
    const out = [];
    for (const token of tokens) {
      if (onlyCjk.test(token)) out.push(token);
      else out.push(...run.call(this, [token]));
    }
    return out;
  }
  runPipeline.original = run;
  lunr.Pipeline.prototype.run = runPipeline;

  // mdBook loads its index when the search opens, which a page's address (?search=) does while the
  // page loads: the index may have come, and the query been searched with elasticlunr's tokenizer,
  // before this script ran. Then search again (mdBook does not search the same words twice in a row,
  // hence the empty-looking query between).
  const bar = document.getElementById("mdbook-searchbar");
  const term = bar ? bar.value.trim() : "";
  if (window.search && window.search.index && hasCjk.test(term)) {
    const again = (value) => {
      bar.value = value;
      bar.dispatchEvent(new KeyboardEvent("keyup"));
    };
    again("\u200b");
    again(term);
  }
})();
