// lightlab's learner loop around the in-page checker (lightlab-exercise.js, which calls the
// hooks registered in window.LIGHTLAB_EXERCISE_HOOKS):
//
// - Saved work. Each shader exercise's editor text is kept in localStorage under
//   `lightlab:v1:exercise:<id>`: keyed by the exercise id, not by the page's URL or the box's
//   place, so it survives a rebuild, a reordered chapter and a change of language (file://
//   pages share one storage in Chromium, whatever their directory). Saved on input (after a
//   pause) and when the page is left, restored when the box is built, removed by Reset.
// - Progress. A check that agrees sets `lightlab:v1:passed:<id>`; the exercises chapter's
//   list (generated/live/progress.html, by src/live/exercises.rs) marks those exercises.
// - A link to share. "Copy link" makes `#x=<id>:<payload>`, the payload being the shader as
//   UTF-8, deflated (CompressionStream 'deflate-raw'), in base64url. Opening a page with such
//   a fragment loads the shader into that exercise's editor and checks it; a fragment that
//   does not decode, names no exercise of the page, inflates past MAX_SHARED_BYTES or holds a
//   NUL or a script tag is refused with a message. Nothing from the URL reaches innerHTML.
//
// Storage can be off, full or refused (private windows, file:// rules): every access is
// caught, and the page works on without saving, with a note in the box.
//
// Test-only URL parameters (they only pick texts the crate shipped; nothing of theirs is shown):
//   ?exercise-try=ID:M   put mutant M of exercise ID (or `solution`, `probe`, `slow`) into its
//                        editor, save it and press Check (screenshots, tests/browser.rs)
//   ?exercise-link=ID:M  the same, then write the link's fragment into <pre id="lightlab-exercise-link">
//   ?exercise-state      write {id: {text, verdict, mistake, note, message, timing}}, the link's
//                        refusal and `ticks` into <pre id="lightlab-exercise-state"> once the
//                        page's link was handled
//   ?ticks               with ?exercise-state: a timer counts its turns (`ticks`; `check_ticks`:
//                        those during the link's check, so the page stayed responsive if > 0)
//   ?exercise-keys       with ?exercise-state: Tab and Esc-then-Tab pressed in the first editor
//   ?press-hints         with ?exercise-state: the hint button of each box pressed until it is
//                        gone; `hints` records, before each press, the button's label and the
//                        hints shown, then the hints shown at the end
//   ?exercise-verdicts   load generated/live/verdict-shaders.js, which a test writes into its copy
//                        of the book ({exercise id: {name: shader}}), check each shader in its
//                        exercise and write {id: {name: {verdict, rule, error, never_read, fixed,
//                        catalogue: {drawn, kept} (the diagnosis's mutant runs drawn, and kept from
//                        an earlier check), diagnosis: [{id, site, title}]}}} into
//                        <pre id="lightlab-verdicts"> (tests/browser.rs, the verdict parity test)
(function () {
  'use strict';

  var text = window.lightlabText || { T: function (s) { return s; }, TF: function (s) { return s; } };
  var T = text.T, TF = text.TF;
  var query = new URLSearchParams(window.location.search);
  var ticks = 0; // ?ticks: a timer's turns, counted until the state is written
  var checkTicks = null; // the turns it ran during the shared link's check
  var ticking = query.has('ticks') ? setInterval(function () { ticks++; }, 10) : null;
  var PREFIX = 'lightlab:v1:';
  var MAX_SHARED_BYTES = 64 * 1024; // a shared shader's largest inflated size (the starters are under 4 KiB)
  var MAX_FRAGMENT_CHARS = 128 * 1024; // a fragment longer than this is refused before decoding
  var SAVE_DELAY_MS = 500;

  function el(tag, attrs, content) {
    var e = document.createElement(tag);
    for (var k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (content !== undefined) e.textContent = content;
    return e;
  }

  // ------------------------------------------------------------------ storage

  // The stored value under `key`, or null (nothing stored, or no storage here).
  function load(key) {
    try { return window.localStorage.getItem(PREFIX + key); } catch (e) { return null; }
  }

  // Stores `value` under `key` (null removes it); false when the browser refuses.
  function store(key, value) {
    try {
      if (value === null) window.localStorage.removeItem(PREFIX + key);
      else window.localStorage.setItem(PREFIX + key, value);
      return true;
    } catch (e) {
      return false;
    }
  }

  // A one-line note under an exercise's buttons (replaced by the next one).
  function note(x, message, kind) {
    var n = x.box.querySelector('.lightlab-learner-note');
    if (!n) {
      n = el('p', { 'class': 'lightlab-learner-note', role: 'status' });
      var result = x.box.querySelector('.lightlab-exercise-result');
      x.box.insertBefore(n, result);
    }
    n.className = 'lightlab-learner-note' + (kind ? ' lightlab-learner-' + kind : '');
    n.textContent = message;
  }

  // Saves the editor's text now (the starter itself is not kept).
  function saveNow(x) {
    clearTimeout(x.learnerTimer);
    var value = x.text.value === x.data.starter ? null : x.text.value;
    if (!store('exercise:' + x.data.id, value) && !x.learnerWarned) {
      x.learnerWarned = true;
      note(x, T('This browser does not let the page save your work (storage is off or full): copy your shader before you leave.'), 'error');
    }
  }

  // Saved work back in the editor, and saving from now on.
  function attachSaved(x) {
    var saved = load('exercise:' + x.data.id);
    if (saved !== null && saved !== x.text.value) {
      x.type(saved);
      note(x, T('Your shader saved on this browser is back in the editor; Reset goes back to the starter.'));
    }
    x.text.addEventListener('input', function () {
      clearTimeout(x.learnerTimer);
      x.learnerTimer = setTimeout(function () { saveNow(x); }, SAVE_DELAY_MS);
    });
    window.addEventListener('pagehide', function () { saveNow(x); });
  }

  // ------------------------------------------------------------------ keyboard

  // Tab in a shader editor indents (two spaces; Shift+Tab takes up to two back from the
  // line's start), as in a code editor; Esc then Tab (or Shift+Tab) leaves the editor, as
  // the accessible code editors do, so the keyboard is never trapped. A line under the
  // editor says so, and the editor points at it (aria-describedby).
  var editorUid = 0;
  function attachKeys(textarea) {
    if (!textarea || textarea.lightlabKeys) return;
    textarea.lightlabKeys = true;
    var help = el('p', { 'class': 'lightlab-editor-help', id: 'lightlab-editor-help-' + (editorUid++) },
      T('Tab indents; press Esc, then Tab, to leave the editor.'));
    var area = textarea.parentNode;
    area.parentNode.insertBefore(help, area.nextSibling);
    textarea.setAttribute('aria-describedby', help.id);
    var escaped = false;
    textarea.addEventListener('blur', function () { escaped = false; });
    textarea.addEventListener('keydown', function (e) {
      if (e.key === 'Escape') { escaped = true; return; }
      var plainTab = e.key === 'Tab' && !e.ctrlKey && !e.altKey && !e.metaKey;
      if (plainTab && !escaped) {
        e.preventDefault();
        if (e.shiftKey) outdent(textarea); else insertText(textarea, '  ');
      }
      escaped = false;
    });
  }

  // Types `s` at the selection as the reader would (undo keeps it; an input event follows).
  function insertText(textarea, s) {
    if (!document.execCommand || !document.execCommand('insertText', false, s)) {
      textarea.setRangeText(s, textarea.selectionStart, textarea.selectionEnd, 'end');
      textarea.dispatchEvent(new Event('input'));
    }
  }

  // Removes up to two spaces at the start of the caret's line.
  function outdent(textarea) {
    var v = textarea.value, at = textarea.selectionStart;
    var start = v.lastIndexOf('\n', at - 1) + 1;
    var n = v.substr(start, 2) === '  ' ? 2 : v.charAt(start) === ' ' ? 1 : 0;
    if (!n) return;
    textarea.setSelectionRange(start, start + n);
    insertText(textarea, '');
    if (textarea.value.length === v.length) { // insertText('') deletes nothing in some browsers
      textarea.setRangeText('', start, start + n, 'end');
      textarea.dispatchEvent(new Event('input'));
    }
    textarea.setSelectionRange(Math.max(start, at - n), Math.max(start, at - n));
  }

  // The figures' shader editors (lightlab-live.js) get the same keys.
  function attachFigureEditors() {
    document.querySelectorAll('.lightlab-editor textarea').forEach(attachKeys);
  }

  // ------------------------------------------------------------------ links

  function toBase64Url(bytes) {
    var s = '';
    for (var i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(s).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  }

  // The bytes of a base64url text, or null when it is not one.
  function fromBase64Url(s) {
    if (!/^[A-Za-z0-9_-]+$/.test(s) || s.length % 4 === 1) return null;
    var b = s.replace(/-/g, '+').replace(/_/g, '/');
    while (b.length % 4) b += '=';
    var raw;
    try { raw = atob(b); } catch (e) { return null; }
    var out = new Uint8Array(raw.length);
    for (var i = 0; i < raw.length; i++) out[i] = raw.charCodeAt(i);
    return out;
  }

  function canCompress() {
    return typeof CompressionStream === 'function' && typeof DecompressionStream === 'function';
  }

  // A promise of the deflate-raw bytes of `bytes`.
  function deflate(bytes) {
    var stream = new Blob([bytes]).stream().pipeThrough(new CompressionStream('deflate-raw'));
    return new Response(stream).arrayBuffer().then(function (b) { return new Uint8Array(b); });
  }

  // A promise of the inflated bytes, rejected ('too-big') as soon as they pass `cap`, so a
  // small link that inflates to gigabytes is stopped early; a stream that is not deflate
  // rejects with the browser's error.
  function inflateCapped(bytes, cap) {
    var reader = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate-raw')).getReader();
    var chunks = [], total = 0;
    function pump() {
      return reader.read().then(function (r) {
        if (r.done) {
          var out = new Uint8Array(total), at = 0;
          chunks.forEach(function (c) { out.set(c, at); at += c.length; });
          return out;
        }
        total += r.value.length;
        if (total > cap) {
          reader.cancel().catch(function () {});
          throw new Error('too-big');
        }
        chunks.push(r.value);
        return pump();
      });
    }
    return pump();
  }

  // A promise of the link (page address with `#x=<id>:<payload>`) to exercise x's shader.
  function linkFor(x) {
    if (!canCompress()) return Promise.reject(new Error(T('this browser cannot compress a link (no CompressionStream)')));
    return deflate(new TextEncoder().encode(x.text.value)).then(function (packed) {
      var page = window.location.href.split('#')[0];
      return page + '#x=' + x.data.id + ':' + toBase64Url(packed);
    });
  }

  // "Copy link": the link in a read-only field to copy by hand, and on the clipboard when
  // the browser allows it. The page's own address is left alone: a reload must bring back
  // the saved work, not the shader as it was when the link was made.
  function attachShare(x) {
    var buttons = x.box.querySelector('.lightlab-exercise-buttons');
    var button = el('button', { type: 'button', 'class': 'lightlab-copy-link', 'aria-label': TF('Copy a link to your shader for {}', [T(x.data.title)]) }, T('Copy link'));
    var field = el('input', { type: 'text', readonly: 'readonly', 'class': 'lightlab-share-link', 'aria-label': T('a link to your shader, to copy by hand') });
    field.hidden = true;
    button.addEventListener('click', function () {
      saveNow(x);
      linkFor(x).then(function (link) {
        field.value = link;
        field.hidden = false;
        field.select();
        var copied = navigator.clipboard && navigator.clipboard.writeText ? navigator.clipboard.writeText(link) : Promise.reject();
        return copied.then(function () { note(x, T('Link copied: whoever opens it sees your shader in this exercise, checked.')); },
          function () { note(x, T('Copy the link above by hand (this browser does not let the page use the clipboard).')); });
      }).catch(function (e) { note(x, String(e && e.message || e), 'error'); });
    });
    buttons.appendChild(button);
    x.box.insertBefore(field, buttons.nextSibling);
  }

  // Why a shared fragment was refused (a key of sharedShader's), in the reader's words.
  function refusedText(key) {
    var why = {
      form: T('the link is not of the form #x=exercise:shader'),
      id: T('the link names no exercise of this page'),
      base64: T('the link is damaged (not base64url)'),
      deflate: T('the link is damaged (its shader does not decompress)'),
      big: T('the shader in the link is larger than 64 KiB'),
      utf8: T('the shader in the link is not UTF-8 text'),
      nul: T('the shader in the link holds NUL characters'),
      script: T('the shader in the link holds a script tag'),
      browser: T('this browser cannot decompress a link (no DecompressionStream)')
    }[key];
    return TF('This link cannot be opened: {}.', [why || T('the link is not of the form #x=exercise:shader')]);
  }

  // A promise of {x, source} for the page's `#x=` fragment, rejected with a refusedText key;
  // null when the page has no such fragment.
  function sharedShader(all) {
    var hash = window.location.hash;
    if (hash.indexOf('#x=') !== 0) return null;
    var m = /^#x=([a-z0-9-]{1,64}):([A-Za-z0-9_-]+)$/.exec(hash.length <= MAX_FRAGMENT_CHARS ? hash : '');
    if (!m) return Promise.reject('form');
    var x = all.filter(function (e) { return e.data.id === m[1] && e.text; })[0];
    if (!x) return Promise.reject('id');
    var bytes = fromBase64Url(m[2]);
    if (!bytes) return Promise.reject({ key: 'base64', x: x });
    if (!canCompress()) return Promise.reject({ key: 'browser', x: x });
    return inflateCapped(bytes, MAX_SHARED_BYTES).then(function (raw) {
      var source;
      try { source = new TextDecoder('utf-8', { fatal: true }).decode(raw); } catch (e) { throw { key: 'utf8', x: x }; }
      if (source.indexOf('\u0000') >= 0) throw { key: 'nul', x: x };
      if (/<\s*\/?\s*script/i.test(source)) throw { key: 'script', x: x };
      return { x: x, source: source };
    }, function (e) {
      throw { key: e && e.message === 'too-big' ? 'big' : 'deflate', x: x };
    });
  }

  var linkRefusal = null; // for ?exercise-state

  // Opens the page's shared link, if any: the shader in its exercise's editor, checked; or
  // the refusal in that exercise's box (at the top of the page when no box is named).
  function openSharedLink(all) {
    var pending = sharedShader(all);
    if (!pending) return Promise.resolve();
    return pending.then(function (shared) {
      shared.x.type(shared.source);
      note(shared.x, T('This shader comes from a shared link; your own saved work is kept until you edit.'));
      // checked, and a pass recorded, but not saved over the reader's own work
      var before = ticks;
      var checked = Promise.resolve(shared.x.check()).then(function (r) {
        checkTicks = ticks - before;
        if (r.verdict === 'agrees') store('passed:' + shared.x.data.id, new Date().toISOString());
      });
      // once the reader edits it, the text is theirs (and saved): the address drops the link,
      // so that a reload brings back their work instead of the link's shader
      var edited = function () {
        shared.x.text.removeEventListener('input', edited);
        try { window.history.replaceState(null, '', window.location.href.split('#')[0]); } catch (e) { /* file:// may refuse */ }
      };
      shared.x.text.addEventListener('input', edited);
      shared.x.box.scrollIntoView();
      return checked;
    }, function (why) {
      var key = typeof why === 'string' ? why : why && why.key || 'form';
      linkRefusal = refusedText(key);
      if (why && why.x) {
        note(why.x, linkRefusal, 'error');
        return;
      }
      var main = document.querySelector('main') || document.body;
      main.insertBefore(el('p', { 'class': 'lightlab-learner-note lightlab-learner-error', role: 'alert' }, linkRefusal), main.firstChild);
    });
  }

  // ------------------------------------------------------------------ test parameters

  // The source a test names for exercise x: a mutant's id, `solution`, `probe` or `slow`.
  function namedSource(x, name) {
    var m = (x.data.mutants || []).filter(function (mm) { return mm.id === name; })[0];
    if (m) return m.shader;
    if (name === 'solution') return x.data.solution || x.data.reference || null;
    if (name === 'probe') return x.data.probe ? x.data.probe.shader : null;
    if (name === 'slow') return x.data.slow_probe || null;
    return null;
  }

  var pendingChecks = []; // the checks tryNamed started (a check runs in chunks: a promise)

  // ?exercise-try / ?exercise-link: the named shader typed into its editor and checked;
  // the box moved to the top of the page (headless screenshots capture the top).
  function tryNamed(all, param) {
    var m = /^([\w-]+):([\w-]+)$/.exec(query.get(param) || '');
    if (!m) return null;
    var x = all.filter(function (e) { return e.data.id === m[1] && e.text; })[0];
    var source = x && namedSource(x, m[2]);
    if (!source) return null;
    x.type(source);
    saveNow(x);
    pendingChecks.push(Promise.resolve(x.check()).then(function (r) { LEARNER_HOOK.checked(x, r); }));
    var main = document.querySelector('main');
    if (main) main.insertBefore(x.box, main.firstChild);
    return x;
  }

  function writePre(id, value) {
    var pre = el('pre', { id: id, hidden: 'hidden' }, JSON.stringify(value));
    document.body.appendChild(pre);
  }

  // ?exercise-keys: the keys of the first shader editor, pressed as synthetic events (which
  // have no default action, so "leaves" means the handler let the browser's Tab through).
  function keysProbe(all) {
    var x = all.filter(function (e) { return e.text; })[0];
    if (!x) return null;
    var t = x.text, before = t.value;
    var press = function (key) {
      var e = new KeyboardEvent('keydown', { key: key, bubbles: true, cancelable: true });
      t.dispatchEvent(e);
      return e.defaultPrevented;
    };
    t.focus();
    t.setSelectionRange(0, 0);
    var held = press('Tab');
    var indented = t.value === '  ' + before;
    press('Escape');
    var heldAfterEsc = press('Tab');
    var out = { tab_indents: held && indented, esc_tab_leaves: !heldAfterEsc && t.value === '  ' + before };
    x.type(before);
    return out;
  }

  // ?press-hints: the box's hint button pressed as a reader would, one press at a time until
  // it is gone (at most 10 presses), as [{label, shown}, ...] then {label: null, shown} at the end.
  function hintPresses(box) {
    var steps = [];
    var shown = function () {
      var list = box.querySelector('.lightlab-hints');
      return list ? Array.prototype.map.call(list.children, function (li) { return li.textContent; }) : [];
    };
    for (var i = 0; i < 10; i++) {
      var button = box.querySelector('.lightlab-hint-button');
      steps.push({ label: button ? button.textContent : null, shown: shown() });
      if (!button) break;
      button.click();
    }
    return steps;
  }

  // {id: {text, verdict, mistake, note, message, timing}} for ?exercise-state (message: the
  // result's text; timing: the checker's time guard measurement).
  function state(all) {
    var out = { exercises: {}, link_refused: linkRefusal, keys: query.has('exercise-keys') ? keysProbe(all) : null, ticks: ticks, check_ticks: checkTicks };
    if (ticking !== null) clearInterval(ticking);
    all.forEach(function (x) {
      var result = x.box.querySelector('.lightlab-exercise-result');
      var mistake = x.box.querySelector('[data-mistake]');
      var n = x.box.querySelector('.lightlab-learner-note');
      out.exercises[x.data.id] = {
        text: x.text ? x.text.value : null,
        verdict: (/lightlab-(agrees|disagrees|error)/.exec(result ? result.className : '') || [])[1] || null,
        mistake: mistake ? mistake.getAttribute('data-mistake') : null,
        note: n ? n.textContent : null,
        message: result ? result.textContent : null,
        timing: x.timing || null,
        hints: query.has('press-hints') ? hintPresses(x.box) : null
      };
    });
    return out;
  }

  // ?exercise-verdicts: the test's shaders checked one by one (see the top of this file).
  function verdictsOf(all) {
    return new Promise(function (resolve) {
      var s = el('script', { src: 'generated/live/verdict-shaders.js' });
      s.onload = function () { resolve(window.LIGHTLAB_VERDICT_SHADERS || null); };
      s.onerror = function () { resolve(null); };
      document.head.appendChild(s);
    }).then(function (shaders) {
      if (!shaders) return { error: 'generated/live/verdict-shaders.js did not load' };
      var out = {};
      var chain = Promise.resolve();
      all.forEach(function (x) {
        if (!x.text || !Object.prototype.hasOwnProperty.call(shaders, x.data.id)) return;
        var named = shaders[x.data.id], seen = out[x.data.id] = {};
        Object.keys(named).forEach(function (name) {
          chain = chain.then(function () {
            x.type(named[name]);
            return Promise.resolve(x.check());
          }).then(function (r) {
            seen[name] = { verdict: r.verdict, rule: r.rule || null, error: r.error || null, never_read: r.never_read || [],
              fixed: r.fixed || [], catalogue: r.catalogue || null,
              diagnosis: (r.diagnosis || []).map(function (f) { return { id: f.id, site: f.site || null, title: f.title }; }) };
          });
        });
        chain = chain.then(function () { x.type(x.data.starter); });
      });
      return chain.then(function () { return out; });
    });
  }

  // ------------------------------------------------------------------ progress

  // The exercises chapter's list: each exercise this browser saw pass marked "passed".
  function showProgress() {
    document.querySelectorAll('.lightlab-progress li[data-exercise]').forEach(function (li) {
      var passed = load('passed:' + li.getAttribute('data-exercise')) !== null;
      li.className = passed ? 'lightlab-passed' : 'lightlab-not-yet';
      var mark = li.querySelector('.lightlab-progress-mark');
      if (mark) mark.textContent = passed ? T('passed') : T('not yet');
    });
  }

  // ------------------------------------------------------------------ hooks

  var LEARNER_HOOK = {
    attach: function (x) {
      if (x.learnerAttached) return;
      x.learnerAttached = true;
      if (!x.text) return; // a number or a choice: nothing to save or share
      attachKeys(x.text);
      attachSaved(x);
      attachShare(x);
    },
    checked: function (x, r) {
      if (x.text) saveNow(x);
      if (r && r.verdict === 'agrees') store('passed:' + x.data.id, new Date().toISOString());
    },
    reset: function (x) {
      store('exercise:' + x.data.id, null);
      note(x, T('Back to the starter; your saved shader was discarded.'));
    },
    ready: function (all) {
      tryNamed(all, 'exercise-try');
      var linked = tryNamed(all, 'exercise-link');
      var made = linked ? linkFor(linked).then(function (link) { writePre('lightlab-exercise-link', link.split('#')[1]); })
        : Promise.resolve();
      var opened = openSharedLink(all);
      if (query.has('exercise-verdicts')) verdictsOf(all).then(function (v) { writePre('lightlab-verdicts', v); });
      if (query.has('exercise-state')) {
        Promise.all([made, opened].concat(pendingChecks)).then(function () { writePre('lightlab-exercise-state', state(all)); },
          function (e) { writePre('lightlab-exercise-state', { error: String(e && e.message || e) }); });
      }
    }
  };

  var hooks = window.LIGHTLAB_EXERCISE_HOOKS = window.LIGHTLAB_EXERCISE_HOOKS || [];
  hooks.push(LEARNER_HOOK);
  // the checker may have built its boxes before this script ran (?selftest starts it early)
  var built = window.LIGHTLAB_EXERCISES && window.LIGHTLAB_EXERCISES.started && window.LIGHTLAB_EXERCISES.started();
  if (built) {
    built.forEach(LEARNER_HOOK.attach);
    LEARNER_HOOK.ready(built);
  }
  function whenBuilt() {
    showProgress();
    attachFigureEditors();
  }
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', whenBuilt);
  else whenBuilt();
  window.addEventListener('load', attachFigureEditors); // figures built late get the keys too
})();
