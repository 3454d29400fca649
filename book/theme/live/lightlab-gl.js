// lightlab's WebGL2 helpers shared by the live figures (lightlab-live.js) and the exercise
// checker (lightlab-exercise.js): elements, shader compilation, and the guards that keep a
// reader's shader from freezing the page.
//
// The guards apply limits the crate emits (src/live/guard.rs, `guard` in each page's data);
// this file retypes none of their numbers:
// - loopGuard: every `for`/`while` condition of the reader's text also counts iterations
//   against the crate's cap, and the fragment's alpha carries the crate's mark when the cap
//   stopped a loop. In SwiftShader (software WebGL) Chromium runs no GPU watchdog, so an
//   endless loop would hold the GPU process, and with it the tab, for good; with the cap
//   every draw ends.
// - macroRefusal: a source whose `#define`s expand past the crate's token budget is refused
//   before the driver sees it (a macro bomb takes the GPU process past gigabytes).
// - waitForGpu: the time a chunk of draws took, measured by reading one pixel back; callers
//   yield to the event loop between chunks, so the tab stays responsive.
//
// Classic script (no ES modules, no fetch): the book must work when opened from disk.
(function () {
  'use strict';

  var words = window.lightlabText || { T: function (s) { return s; }, TF: function (s) { return s; } };
  var T = words.T, TF = words.TF;

  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    for (var k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  // A driver's info log without the C string's terminating NULs (shown as a box glyph).
  function cleanLog(log) { return String(log).replace(/\u0000/g, '').trim(); }

  // {shader, floated} or {error}: `source` compiled; when the driver refused an integer
  // where a float is wanted, compiled again with those integers written as floats
  // (floatLiterals), as desktop GLSL reads them. `floated` lists the integers so read.
  function compile(gl, type, source) {
    var first = compileOnce(gl, type, source);
    if (first.shader || !INT_FOR_FLOAT.test(first.log)) return outcome(first, []);
    var text = source, log = first.log, floated = [];
    for (var round = 0; round < MAX_FLOAT_ROUNDS; round++) {
      var next = floatLiterals(text, errorLines(log));
      if (!next.changed.length) break;
      floated = floated.concat(next.changed);
      text = next.text;
      var again = compileOnce(gl, type, text);
      if (again.shader) return outcome(again, floated);
      if (!INT_FOR_FLOAT.test(again.log)) break;
      log = again.log;
    }
    // the reader's own error (its line numbers are the reader's), and why
    return outcome(first, []);
  }

  // Retries of compile(): each rewrites the lines of one more round of errors (a driver may
  // stop at the first error of a function).
  var MAX_FLOAT_ROUNDS = 4;

  // {shader} or {log}: one compile of `source`.
  function compileOnce(gl, type, source) {
    var s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (gl.getShaderParameter(s, gl.COMPILE_STATUS)) return { shader: s };
    var log = gl.isContextLost() ? T('the GPU context was lost') : gl.getShaderInfoLog(s) || T('compile failed');
    gl.deleteShader(s);
    return { log: String(log) };
  }

  function outcome(r, floated) {
    return r.shader ? { shader: r.shader, floated: floated } : { error: cleanLog(r.log) + esHint(r.log) };
  }

  // ANGLE's words when an integer stands where a float is wanted (`pow(x, 32)`,
  // `float a = 1;`, `v * 2`: the tutorials' desktop GLSL converts it, GLSL ES never does):
  // "no matching overloaded function", "cannot convert from 'const int'", "... operand of
  // type 'const int'".
  var INT_FOR_FLOAT = /no matching overloaded function|'const (lowp |mediump |highp )?int'/;

  // The sentence that says why the driver refused an integer where a float is wanted, on its
  // own line, after such an error; else nothing.
  function esHint(log) {
    if (!INT_FOR_FLOAT.test(String(log))) return '';
    return '\n' + T('The page compiles your shader as GLSL ES, which never turns an integer into a float: write 32.0, not 32, where a float is expected (the command line, desktop GLSL, accepts both).');
  }

  // The note on the integers compile() read as floats (its `floated`), each written once.
  function floatedNote(floated) {
    var seen = floated.filter(function (d, k) { return floated.indexOf(d) === k; });
    return TF('GLSL ES never turns an integer into a float, so the page read {} as {}, as desktop GLSL (the command line) does.',
      [seen.join(', '), seen.map(function (d) { return d + '.0'; }).join(', ')]);
  }

  // The 1-based line numbers of a driver log's errors of the integer-for-float kind
  // (ANGLE writes "ERROR: 0:23: 'pow' : no matching overloaded function found").
  function errorLines(log) {
    var lines = [];
    String(log).split('\n').forEach(function (l) {
      var m = /^ERROR: \d+:(\d+): (.*)$/.exec(l.trim());
      if (m && INT_FOR_FLOAT.test(m[2]) && lines.indexOf(Number(m[1])) < 0) lines.push(Number(m[1]));
    });
    return lines;
  }

  // An integer literal with what surrounds it: a decimal integer not part of a name or of
  // another number (`vec3`, `1.5`, `2e3`, `0x1F`, `3u` keep theirs).
  var INT_LITERAL = /(^|[^\w.])(\d+)(?![\w.])/g;

  // What before (after) an integer literal keeps it an integer: `[` (`]`), `/`, `%`, `^`, a
  // shift, a single `&` or `|` (`&&` and `||` take booleans, so they do not count).
  var INTEGER_LEFT = /(\[|\/|%|\^|<<|>>|(^|[^&])&|(^|[^|])\|)$/;
  var INTEGER_RIGHT = /^(\]|\/|%|\^|<<|>>|&($|[^&])|\|($|[^|]))/;

  // `source` with each integer literal of the lines `lines` written as a float (`32` as
  // `32.0`), where desktop GLSL would convert it and the value cannot change: not in a
  // statement that names an integer or boolean type, nor on a line with a `for` (its
  // counters stay integers),
  // not an array's index or size (after `[`), not an operand of `/`, `%`, a shift or a
  // bitwise operator (where an integer's result differs). {text, changed: ['32', ...]}. A
  // rewrite the shader does not accept fails to compile, and compile() keeps the first error.
  function floatLiterals(source, lines) {
    var all = source.split('\n'), changed = [];
    lines.forEach(function (n) {
      if (n < 1 || n > all.length || /\bfor\b/.test(all[n - 1])) return;
      all[n - 1] = all[n - 1].split(';').map(function (statement) {
        if (/\b(u?int|[iub]vec[234]|bool)\b/.test(statement)) return statement;
        return statement.replace(INT_LITERAL, function (match, before, digits, at) {
          var start = at + before.length, end = start + digits.length;
          var left = statement.slice(0, start).replace(/\s+$/, ''), right = statement.slice(end).replace(/^\s+/, '');
          if (INTEGER_LEFT.test(left) || INTEGER_RIGHT.test(right)) return match;
          changed.push(digits);
          return before + digits + '.0';
        });
      }).join(';');
    });
    return { text: all.join('\n'), changed: changed };
  }

  // `source` with comments blanked to spaces (newlines kept), so that line numbers and
  // column positions stay those of the reader's text.
  function blankComments(source) {
    return source.replace(/\/\*[\s\S]*?\*\/|\/\/[^\n]*/g, function (c) { return c.replace(/[^\n]/g, ' '); });
  }

  // The index of the parenthesis closing the one at `open`, or -1.
  function closing(text, open) {
    var depth = 0;
    for (var i = open; i < text.length; i++) {
      if (text[i] === '(') depth++;
      else if (text[i] === ')' && --depth === 0) return i;
    }
    return -1;
  }

  // The top-level `;` positions inside text[from, to).
  function semicolons(text, from, to) {
    var out = [], depth = 0;
    for (var i = from; i < to; i++) {
      if (text[i] === '(') depth++;
      else if (text[i] === ')') depth--;
      else if (text[i] === ';' && depth === 0) out.push(i);
    }
    return out;
  }

  // The reader's text with every loop condition also counting iterations:
  // `while (c)` becomes `while ((c) && ll_loop())`, `for (a; c; b)` becomes
  // `for (a; (c) && ll_loop(); b)` (an empty c is `true`), on the same line. `ll_loop()`
  // is declared by loopHeader(). Returns {text, loops}: loops counts the rewritten loops.
  function guardLoops(source) {
    var text = blankComments(source);
    var out = '', last = 0, loops = 0;
    var re = /\b(for|while)\s*\(/g, m;
    while ((m = re.exec(text))) {
      var open = m.index + m[0].length - 1, close = closing(text, open);
      if (close < 0) break; // the driver names the unbalanced parenthesis
      var from = open + 1, to = close;
      if (m[1] === 'for') {
        var semi = semicolons(text, open + 1, close);
        if (semi.length !== 2) continue;
        from = semi[0] + 1;
        to = semi[1];
      }
      var cond = source.substring(from, to);
      out += source.substring(last, from) + '(' + (cond.trim() ? cond : 'true') + ') && ll_loop()';
      last = to;
      loops++;
    }
    return { text: out + source.substring(last), loops: loops };
  }

  // One header line (no newline inside, so a caller adds exactly one line): the iteration
  // counter and ll_loop(), which stops every loop once the fragment ran `cap` iterations.
  function loopHeader(guard) {
    return 'int ll_loops = 0; bool ll_loop() { ll_loops++; return ll_loops <= ' + guard.loop_cap + '; }\n';
  }

  // The end of a fragment shader whose `main` was renamed by `#define main ll_main` (see
  // loopMainRename): the reader's main runs, then output `out` ({name, type} of outputName)
  // carries the crate's mark when the cap stopped a loop: in its alpha (vec4) or in all
  // three channels (vec3, whose target's alpha the shader cannot set).
  function loopFooter(guard, out) {
    var mark = guard.loop_mark.toFixed(1);
    var set = out.type === 'vec4' ? out.name + '.a = ' + mark : out.name + ' = vec3(' + mark + ')';
    return '\n#undef main\nvoid main() { ll_main(); if (ll_loops > ' + guard.loop_cap + ') ' + set + '; }\n';
  }
  var loopMainRename = '#define main ll_main\n';

  // Whether a fragment read back as [r, g, b, a] carries the loop guard's mark (loopFooter).
  function loopMarked(px, mark) {
    return px[3] === mark || (px[0] === mark && px[1] === mark && px[2] === mark);
  }

  // The first `out vec4` or `out vec3` of a fragment shader as {name, type}, or null.
  function outputName(source) {
    var m = /^[ \t]*(?:layout\s*\([^)]*\)\s*)?out\s+(?:(?:highp|mediump|lowp)\s+)?(vec[34])\s+(\w+)\s*;/m.exec(blankComments(source));
    return m ? { name: m[2], type: m[1] } : null;
  }

  // The tokens of a `#define` body: identifiers and numbers as one token, any other
  // character as one.
  function tokens(body) { return body.match(/[A-Za-z_]\w*|\d[\w.]*|\S/g) || []; }

  // Refuses a source whose macros expand past the crate's budget, before any compile:
  // returns {key, args} naming the rule broken ('defines': too many `#define`s;
  // 'expansion': macro args[0] expands past args[1] tokens), or null. A bound of each
  // macro's expansion: its body's tokens, every macro named counted at that macro's bound,
  // times, for each function-like macro named, the most times that macro repeats one of
  // its parameters (its argument may be copied that many times, at every nesting). Nested
  // object-like macros (`#define B A A A`) and nested repeating calls (`A(A(A(x)))`) both
  // grow this bound as fast as the expansion.
  function macroRefusal(source, guard) {
    var text = blankComments(source);
    var re = /^[ \t]*#[ \t]*define[ \t]+([A-Za-z_]\w*)(\([^)]*\))?([^\n]*)$/gm, m;
    var size = Object.create(null), repeat = Object.create(null), count = 0;
    while ((m = re.exec(text))) {
      count++;
      if (count > guard.max_defines) return { key: 'defines', args: [guard.max_defines] };
      var params = m[2] ? m[2].slice(1, -1).split(',').map(function (p) { return p.trim(); }) : [];
      var body = tokens(m[3]), sum = 0, factor = 1, own = 1;
      params.forEach(function (p) {
        var n = body.filter(function (t) { return t === p; }).length;
        if (n > own) own = n;
      });
      body.forEach(function (t) {
        if (size[t] === undefined) { sum += 1; return; }
        sum += size[t];
        factor *= repeat[t];
      });
      size[m[1]] = sum * factor;
      repeat[m[1]] = own;
      if (!(size[m[1]] <= guard.max_expansion)) return { key: 'expansion', args: [m[1], guard.max_expansion] };
    }
    return null;
  }

  // The reader's message for a refusal of macroRefusal, in the reader's language.
  function macroMessage(refusal) {
    if (refusal.key === 'defines') return TF('your shader has more than {} #define lines; the page compiles none past that (a macro bomb takes the browser\'s memory)', refusal.args);
    return TF('the macro {} expands to more than {} tokens: the page does not compile it (a macro bomb takes the browser\'s memory)', refusal.args);
  }

  // Waits until the GPU finished every command issued so far on `gl`, by reading one pixel
  // of the bound framebuffer (`float`: a float target), and returns the milliseconds since
  // `t0`. The wait blocks the page, so callers draw in bounded chunks and yield between them
  // (a fence polled from timers would not block, but headless Chromium's virtual time, which
  // the tests use, advances the page's clock by its timers, not by the GPU's work).
  function waitForGpu(gl, float, t0) {
    if (float) gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, new Float32Array(4));
    else gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    return performance.now() - t0;
  }

  // One turn of the event loop (lets the page paint and other scripts run).
  function yieldTurn() { return new Promise(function (resolve) { setTimeout(resolve, 0); }); }

  window.LightlabGL = {
    el: el,
    cleanLog: cleanLog,
    compile: compile,
    floatedNote: floatedNote,
    guardLoops: guardLoops,
    loopHeader: loopHeader,
    loopFooter: loopFooter,
    loopMainRename: loopMainRename,
    outputName: outputName,
    loopMarked: loopMarked,
    macroRefusal: macroRefusal,
    macroMessage: macroMessage,
    waitForGpu: waitForGpu,
    yieldTurn: yieldTurn
  };
})();
