// lightlab exercises: the in-page checker. Each exercise box (generated/live/exercise-<id>.html)
// gets an editor with the starter shader and a "Check" button. The check draws the reader's
// fragment shader, the reference and every mutant of the mistake catalogue over the same
// cases on this browser's GPU, reads the float results back, and names the mistakes whose
// mutant reproduces the reader's output, as `lightlab exercise check` does on llvmpipe.
//
// This file computes nothing about light and retypes no number. The cases (packed rows,
// per-group uniforms, defined flags), the quantities' places in the rows, the tolerances,
// the mistake texts and every program come from the crate (generated/live/exercise-<id>.js,
// made by src/live/exercises.rs). The verdict is `lightlab exercise check`'s on the same cases,
// by the rule the crate emits (data.verdict, src/live/exercises.rs verdict_json); the
// diagnosis is src/gl/diagnose.rs's: a mutant the cases cannot tell from the reference is
// skipped; one within `match_tolerance` of the reader on all but `mistake_share` of the defined
// cases is reported, fewest mismatches first; else (shader exercises) the isolation step.
//
// The reader's shader is never rewritten: its `#version` line becomes the ES header the
// crate exports, and one point per case is drawn with every declared `in` fed from the
// case through the vertex stage and every declared uniform set from the case or its group.
//
// Classic script (no ES modules, no fetch): the book must work when opened from disk.
//
// URL parameters:
//   ?selftest           also check each exercise's reference (expects "agrees") and two of
//                       its mutants (expects their own id first); lightlab-live.js writes the
//                       result into <pre id="lightlab-selftest"> under "exercises"
//   ?exercise-all       with ?selftest: every mutant the cases tell from the reference, not two
//   (number and choice exercises: lightlab-answer.js; ?exercise-try and the learner's saved work, progress and links: lightlab-learner.js,
//   which follows each exercise through window.LIGHTLAB_EXERCISE_HOOKS)
(function () {
  'use strict';

  var query = new URLSearchParams(window.location.search);
  // the page's words in the reader's language (lightlab-i18n.js); English when it is missing
  var text = window.lightlabText || { T: function (s) { return s; }, TF: function (s) { return s; } };
  var T = text.T, TF = text.TF;
  var WIDTH = 64; // the float target's width in cases (any width works; rows follow)
  // Other scripts follow the exercises: each hook's attach(x) once a box is built, checked(x, r)
  // after a check the reader asked for, reset(x) after Reset, ready(all) once every box is built.
  var hooks = window.LIGHTLAB_EXERCISE_HOOKS = window.LIGHTLAB_EXERCISE_HOOKS || [];
  function notify(name, x, r) {
    hooks.forEach(function (h) {
      try { if (h[name]) h[name](x, r); } catch (e) { /* a helper's failure never stops the checker */ }
    });
  }
  // A driver's info log without the C string's terminating NULs (shown as a box glyph).
  function cleanLog(log) { return String(log).replace(/\u0000/g, '').trim(); }

  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    for (var k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  // ------------------------------------------------------------------ GL

  var shared = null;
  var lostBefore = false; // the browser took the context away (a shader ran too long)
  var lastTiming = null;  // the time guard's last measurement, for ?selftest
  var slowProbedOn = null; // the exercise whose ?selftest ran the slow probe
  function context() {
    if (shared && shared.gl.isContextLost()) {
      shared = null;
      lostBefore = true;
    }
    if (shared) return shared;
    var canvas = document.createElement('canvas');
    canvas.addEventListener('webglcontextlost', function (e) { e.preventDefault(); lostBefore = true; });
    canvas.width = 1;
    canvas.height = 1;
    var gl = canvas.getContext('webgl2', { antialias: false, depth: false, stencil: false });
    if (!gl) throw new Error(T('this browser gives no WebGL2 context, so the check cannot run here; `lightlab exercise check` runs it on the command line'));
    if (!gl.getExtension('EXT_color_buffer_float')) {
      throw new Error(T('this GPU cannot render to float targets (no EXT_color_buffer_float), so the check cannot read exact results here; `lightlab exercise check` runs it on the command line'));
    }
    shared = { gl: gl, programs: {}, textures: [] };
    return shared;
  }

  function compile(gl, type, source) {
    var s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
      var log = gl.getShaderInfoLog(s) || T('compile failed');
      gl.deleteShader(s);
      return { error: log };
    }
    return { shader: s };
  }

  // The reader's desktop shader as GLSL ES: the `#version` line (if any) replaced by the
  // crate's ES header. `offset` is what to subtract from a driver's line number to get
  // the reader's.
  function toEs(source, header) {
    var headerLines = header.split('\n').length - 1;
    var m = /^[ \t]*#version[^\n]*\n?/.exec(source);
    var lead = source.match(/^(\s*)/)[1];
    if (m && source.trim().indexOf('#version') === 0) {
      var before = lead.split('\n').length - 1; // blank lines before the #version line
      var rest = source.substring(source.indexOf('#version'));
      rest = rest.substring(rest.indexOf('\n') + 1);
      return { text: header + rest, offset: headerLines - 1 - before };
    }
    return { text: header + source, offset: headerLines };
  }

  // The `in` declarations of a fragment shader: [{qualifier, type, name}].
  function inputs(source) {
    var out = [];
    var re = /^[ \t]*((?:(?:flat|smooth|centroid)\s+)*)in\s+(\w+)\s+(\w+)\s*;/gm;
    var m;
    var clean = source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/[^\n]*/g, '');
    while ((m = re.exec(clean))) out.push({ qualifier: m[1], type: m[2], name: m[3] });
    return out;
  }

  // The vertex stage: one point per draw at pixel `ll_pixel`, each declared `in` of the
  // fragment stage passed through from a uniform of the same type.
  function vertexFor(ins, header) {
    var s = header;
    s += 'uniform vec2 ll_pixel;\nuniform vec2 ll_size;\n';
    ins.forEach(function (v) {
      s += v.qualifier + 'out ' + v.type + ' ' + v.name + ';\nuniform ' + v.type + ' ll_in_' + v.name + ';\n';
    });
    s += 'void main() {\n';
    ins.forEach(function (v) { s += '  ' + v.name + ' = ll_in_' + v.name + ';\n'; });
    s += '  gl_Position = vec4((ll_pixel + 0.5) / ll_size * 2.0 - 1.0, 0.0, 1.0);\n  gl_PointSize = 1.0;\n}\n';
    return s;
  }

  // A complete desktop fragment shader as a program; {error, line-mapped} when it fails.
  function program(source, header) {
    var ctx = context(), gl = ctx.gl;
    if (ctx.programs[source]) return ctx.programs[source];
    var es = toEs(source, header);
    var ins = inputs(source);
    var readerLines = source.split('\n').length;
    var fs = compile(gl, gl.FRAGMENT_SHADER, es.text);
    if (fs.error) {
      return {
        error: cleanLog(fs.error.replace(/(ERROR|WARNING): (\d+):(\d+):/g, function (all, kind, file, line) {
          var n = Number(line) - es.offset;
          return n >= 1 && n <= readerLines ? kind + ': line ' + n + ':' : kind + ':';
        }))
      };
    }
    var vs = compile(gl, gl.VERTEX_SHADER, vertexFor(ins, header));
    if (vs.error) return { error: TF('the inputs of your shader cannot be fed: {}', [cleanLog(vs.error)]) };
    var p = gl.createProgram();
    gl.attachShader(p, vs.shader);
    gl.attachShader(p, fs.shader);
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) return { error: cleanLog(gl.getProgramInfoLog(p) || T('link failed')) };
    var uniforms = {};
    var n = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
    for (var i = 0; i < n; i++) {
      var info = gl.getActiveUniform(p, i);
      uniforms[info.name.replace(/\[0\]$/, '')] = { loc: gl.getUniformLocation(p, info.name), type: info.type };
    }
    var r = { program: p, uniforms: uniforms, ins: ins.map(function (v) { return v.name; }) };
    ctx.programs[source] = r;
    return r;
  }

  function setUniform(gl, u, v, unit) {
    switch (u.type) {
      case gl.FLOAT: gl.uniform1f(u.loc, v[0]); break;
      case gl.FLOAT_VEC2: gl.uniform2fv(u.loc, v.slice(0, 2)); break;
      case gl.FLOAT_VEC3: gl.uniform3fv(u.loc, v.slice(0, 3)); break;
      case gl.FLOAT_VEC4: gl.uniform4fv(u.loc, v.length >= 4 ? v.slice(0, 4) : v.concat([1]).slice(0, 4)); break;
      case gl.FLOAT_MAT3: gl.uniformMatrix3fv(u.loc, false, v); break;
      case gl.FLOAT_MAT4: gl.uniformMatrix4fv(u.loc, false, v); break;
      case gl.SAMPLER_2D: texel(gl, unit, v); gl.uniform1i(u.loc, unit); break;
      case gl.BOOL: case gl.INT: gl.uniform1i(u.loc, v[0]); break;
      default: gl.uniform1f(u.loc, v[0]); break;
    }
  }

  // A texel quantity: a 1×1 float texture on `unit` holding the case's value, so that any
  // texture coordinate reads it exactly (nearest filtering).
  function texel(gl, unit, v) {
    var ctx = context();
    if (!ctx.textures[unit]) {
      var t = gl.createTexture();
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, 1, 1, 0, gl.RGBA, gl.FLOAT, null);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      ctx.textures[unit] = t;
    }
    gl.activeTexture(gl.TEXTURE0 + unit);
    gl.bindTexture(gl.TEXTURE_2D, ctx.textures[unit]);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, 1, 1, gl.RGBA, gl.FLOAT, new Float32Array([v[0], v[1], v[2], v.length > 3 ? v[3] : 1]));
  }

  var WIDTHS = { float: 1, vec2: 2, vec3: 3, texel: 3, mat4: 16 };

  // The value of quantity q in case `row` of `group` (a flat array), from the place the
  // crate's layout gives it; `null` when the case does not carry it.
  function value(q, group, row) {
    if (q.slot && typeof q.slot === 'object') {
      var flat = [];
      row.forEach(function (v) { flat = flat.concat(v); });
      var start = q.slot.input * 4 + q.slot.offset;
      return flat.slice(start, start + WIDTHS[q.type]);
    }
    if (q.slot === 'group' && group.uniforms[q.name] !== undefined) return [].concat(group.uniforms[q.name]);
    return q['default'] ? q['default'].slice() : null;
  }

  // Runs the complete shader `source` on every case of `data`; `fixed` maps quantity
  // names to the values every run uses (the quantities the reader's shader does not
  // declare, or those a switch zeroes); `zeroed` lists group uniforms set to zero.
  // Returns {outputs: [group][case] -> [r, g, b, a]} or {error}.
  // The reader's name for model quantity `name` under the exercise's mapping (`names`:
  // model name or struct/array prefix -> the reader's; empty for the crate's programs).
  function userName(names, name) {
    if (!names) return name;
    if (names[name]) return names[name];
    for (var m in names) {
      if (name.indexOf(m + '.') === 0 || name.indexOf(m + '[') === 0) return names[m] + name.slice(m.length);
    }
    return name;
  }

  function run(data, source, fixed, zeroed, names) {
    var p = program(source, data.es_header);
    if (p.error) return { error: p.error };
    var gl = context().gl;
    var groups = data.cases.groups;
    var total = 0;
    groups.forEach(function (g) { total += g.rows.length; });
    var height = Math.max(1, Math.ceil(total / WIDTH));
    var tex = gl.createTexture();
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, WIDTH, height, 0, gl.RGBA, gl.FLOAT, null);
    var fbo = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
    if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) {
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      return { error: 'this GPU cannot render to a float target here' };
    }
    gl.viewport(0, 0, WIDTH, height);
    gl.disable(gl.BLEND);
    gl.disable(gl.DEPTH_TEST);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.useProgram(p.program);
    var units = {}, nextUnit = 1;
    Object.keys(p.uniforms).forEach(function (name) {
      if (p.uniforms[name].type === gl.SAMPLER_2D) units[name] = nextUnit++;
    });
    var unset = {};
    Object.keys(p.uniforms).forEach(function (name) { if (name !== 'll_pixel' && name !== 'll_size') unset[name] = 1; });
    var set = function (model, v) {
      var name = userName(names, model);
      var key = p.ins.indexOf(name) >= 0 ? 'll_in_' + name : name;
      var u = p.uniforms[key];
      if (u && v) {
        setUniform(gl, u, v, units[name]);
        delete unset[key];
      }
    };
    gl.uniform2f(p.uniforms.ll_size.loc, WIDTH, height);
    var index = 0;
    groups.forEach(function (g) {
      Object.keys(g.uniforms).forEach(function (name) {
        var v = [].concat(g.uniforms[name]);
        set(name, zeroed && zeroed.indexOf(name) >= 0 ? v.map(function () { return 0; }) : v);
      });
      g.rows.forEach(function (row) {
        data.quantities.forEach(function (q) {
          var v = fixed[q.name] || value(q, g, row);
          if (v) set(q.name, v);
          else { // the model does not read it
            var user = userName(names, q.name);
            delete unset[p.ins.indexOf(user) >= 0 ? 'll_in_' + user : user];
          }
        });
        gl.uniform2f(p.uniforms.ll_pixel.loc, index % WIDTH, Math.floor(index / WIDTH));
        gl.drawArrays(gl.POINTS, 0, 1);
        index++;
      });
    });
    var px = new Float32Array(WIDTH * height * 4);
    gl.readPixels(0, 0, WIDTH, height, gl.RGBA, gl.FLOAT, px);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(fbo);
    gl.deleteTexture(tex);
    var outputs = [];
    index = 0;
    groups.forEach(function (g) {
      var o = [];
      g.rows.forEach(function () { o.push(Array.prototype.slice.call(px, index * 4, index * 4 + 4)); index++; });
      outputs.push(o);
    });
    return { outputs: outputs, unset: Object.keys(unset) };
  }

  // ------------------------------------------------------------------ the decision rule

  // src/gl/diagnose.rs compare_outputs: rgb per defined case within `tolerance`; two
  // non-finite values agree, a finite against a non-finite one does not.
  function compare(data, a, b, tolerance) {
    var r = { defined: 0, mismatches: 0, max_diff: 0 };
    data.cases.groups.forEach(function (g, gi) {
      g.rows.forEach(function (row, i) {
        if (!g.defined[i]) return;
        r.defined++;
        var bad = false;
        for (var c = 0; c < 3; c++) {
          var x = a[gi][i][c], y = b[gi][i][c];
          var fx = isFinite(x), fy = isFinite(y);
          if (fx && fy) {
            var d = Math.abs(x - y);
            if (d > r.max_diff) r.max_diff = d;
            if (d > tolerance) bad = true;
          } else if (fx !== fy) {
            bad = true;
          }
        }
        if (bad) r.mismatches++;
      });
    });
    return r;
  }
  // The verdict's rule on one case (src/gl/diagnose.rs case_fails): a channel more than
  // `bound` from the crate's f64 value `want`, or not a number, fails the case.
  function caseFails(got, want, bound) {
    for (var c = 0; c < 3; c++) if (!(Math.abs(got[c] - want[c]) <= bound)) return true;
    return false;
  }
  // Defined cases (those the crate gave a value) as {g, i, bad, diff} against `expected`.
  function againstExpected(data, out, expected) {
    var cases = [];
    expected.forEach(function (rows, gi) {
      rows.forEach(function (want, i) {
        var o = out[gi][i], diff = 0;
        for (var c = 0; want !== null && c < 3; c++) { var d = Math.abs(o[c] - want[c]); if (d > diff) diff = d; }
        if (want !== null) cases.push({ g: gi, i: i, bad: caseFails(o, want, data.verdict.bound), diff: diff });
      });
    });
    return cases;
  }
  function tally(cases) { // the agreement {defined, mismatches, max_diff} of againstExpected's cases
    var r = { defined: cases.length, mismatches: 0, max_diff: 0 };
    cases.forEach(function (c) { if (c.bad) r.mismatches++; if (isFinite(c.diff) && c.diff > r.max_diff) r.max_diff = c.diff; });
    return r;
  }
  // Which rule decides for a program run with `fixed`: "f64" when the crate emitted the f64
  // values for exactly these fixed quantities (the mapping's; a shader that hard-codes another
  // quantity gets "gpu": within match_tolerance of the reference drawn here), "reference" for
  // a variant.
  function ruleFor(data, fixed) {
    if (data.verdict.rule !== 'f64') return data.verdict.rule;
    return Object.keys(fixed).sort().join(',') === data.verdict.fixed.slice().sort().join(',') ? 'f64' : 'gpu';
  }
  function matches(data, agreement) {
    return agreement.defined > 0 && agreement.mismatches <= data.mistake_share * agreement.defined;
  }
  function exp1(x) { return x.toExponential(1).replace('e+', 'e'); }

  // The quantities the reader's program does not declare, fixed to their defaults (one
  // policy with the command line: undeclared quantities take the chapter's values).
  function fixedFor(data, p) {
    var fixed = {};
    data.quantities.forEach(function (q) {
      var user = userName(data.names, q.name);
      var declared = p.ins.indexOf(user) >= 0 || p.uniforms[user] !== undefined;
      if (!declared && q['default']) fixed[q.name] = q['default'].slice();
    });
    // the exercise's mapping fixes quantities too, declared or not (as [values] on the command line)
    Object.keys(data.values || {}).forEach(function (name) { fixed[name] = data.values[name].slice(); });
    return fixed;
  }

  // ------------------------------------------------------------------ isolation
  // src/gl/diagnose.rs isolate: when no mistake of the catalogue matches, switch terms and
  // lights off one at a time (the crate's data.switches), then look for a case predicate
  // (the crate's per-case data.cases.groups[g].flags) that every disagreeing case has.
  // The sentences are the command line's (data.isolation), filled the same way.

  function fill(data, key, args) {
    var parts = data.isolation[key].split('{}');
    var s = parts[0];
    for (var k = 1; k < parts.length; k++) s += (args[k - 1] === undefined ? '' : String(args[k - 1])) + parts[k];
    return s;
  }
  // The same sentence in the reader's language: the template and the words filled in
  // (term and condition names) translated; numbers pass through.
  function shown(data, key, args) {
    return TF(data.isolation[key], args.map(function (a) { return typeof a === 'string' ? T(a) : a; }));
  }
  function joinShown(names, sep) { return names.map(function (n) { return T(n); }).join(sep); }

  // Defined cases as {g, i, bad}: bad when a and b differ by more than the tolerance.
  function verdicts(data, a, b) {
    var out = [];
    data.cases.groups.forEach(function (g, gi) {
      g.rows.forEach(function (row, i) {
        if (!g.defined[i]) return;
        var bad = false;
        for (var c = 0; c < 3; c++) {
          var x = a[gi][i][c], y = b[gi][i][c];
          if (isFinite(x) && isFinite(y)) { if (Math.abs(x - y) > data.match_tolerance) bad = true; }
          else if (isFinite(x) !== isFinite(y)) bad = true;
        }
        out.push({ g: gi, i: i, bad: bad });
      });
    });
    return out;
  }

  function isolate(data, p, source, fixed, learner, reference, rule) {
    var cases = rule === 'f64' ? againstExpected(data, learner.outputs, data.verdict.expected)
      : verdicts(data, learner.outputs, reference.outputs);
    var failing = cases.filter(function (c) { return c.bad; });
    var evidence = shown(data, 'evidence', [failing.length, cases.length]);
    var located = [], switchable = [];
    data.switches.forEach(function (sw) {
      var declared = sw.quantities.every(function (q) {
        var user = userName(data.names, q);
        return p.ins.indexOf(user) >= 0 || p.uniforms[user] !== undefined;
      });
      if (!declared) return;
      var off = {};
      Object.keys(fixed).forEach(function (k) { off[k] = fixed[k]; });
      sw.quantities.forEach(function (q) { off[q] = [0, 0, 0, 0]; });
      var a = run(data, source, off, sw.uniforms, data.names);
      var b = rule === 'f64' ? null : run(data, data.reference, off, sw.uniforms);
      if (a.error || (b && b.error)) return;
      var still = (b ? verdicts(data, a.outputs, b.outputs) : againstExpected(data, a.outputs, data.verdict.switches[sw.name]))
        .filter(function (c) { return c.bad; }).length;
      evidence += shown(data, 'evidence_off', [sw.name, still]);
      if (still === 0) located.push(sw.name);
      switchable.push(sw.name);
    });
    var none = switchable.length ? 'several_terms' : 'none';
    var sentence = located.length === 0 ? fill(data, none, [])
      : located.length === 1 ? fill(data, 'one', [located[0]]) : fill(data, 'several', [located.join(', ')]);
    var sentenceShown = located.length === 0 ? shown(data, none, [])
      : located.length === 1 ? shown(data, 'one', [located[0]]) : shown(data, 'several', [joinShown(located, T(', '))]);
    var flagsOf = function (c) { return data.cases.groups[c.g].flags[c.i]; };
    var conditions = data.flag_labels.filter(function (label, k) {
      return failing.length > 0 && failing.every(function (c) { return flagsOf(c)[k]; }) &&
        cases.some(function (c) { return !flagsOf(c)[k]; });
    });
    if (conditions.length) {
      sentence += fill(data, 'only_when', [conditions.join(' and ')]);
      sentenceShown += shown(data, 'only_when', [joinShown(conditions, T(' and '))]);
      evidence += shown(data, 'evidence_always', [joinShown(conditions, T(' and '))]);
    }
    // title: the command line's English (the self-test compares it); shown: the reader's
    return { id: 'isolated', title: sentence, shown: sentenceShown, evidence: evidence, link: '', why: '' };
  }

  // ------------------------------------------------------------------ the time guard
  // A shader cannot be stopped once drawn, so before the whole check the reader's shader
  // and the reference draw one case each, timed; a reader's case slower than both the
  // crate's ratio to the reference and its absolute floor (data.time_limits) stops the
  // check with a message instead of freezing the page for every case and mutant. A first
  // draw includes the program's compile (SwiftShader and ANGLE build a program at its first
  // draw), so a first draw over the limit is drawn again and only the warm time counts. An
  // endless loop never returns: the browser's GPU watchdog then takes the context away, and
  // the next check says so and starts a new one.

  function oneCase(data) {
    var g = data.cases.groups[0];
    var one = Object.create(data);
    one.cases = { groups: [{ uniforms: g.uniforms, rows: [g.rows[0]], defined: [g.defined[0]], flags: g.flags ? [g.flags[0]] : [] }] };
    return one;
  }

  function timed(data, source, fixed, names) {
    var t0 = performance.now();
    var r = run(data, source, fixed, null, names);
    return { ms: performance.now() - t0, error: r.error, lost: context().gl.isContextLost() };
  }

  // The slowest a reader's warm case may be: the crate's ratio times the reference's, but
  // never less than the absolute floor.
  function timeLimit(data, referenceMs) {
    var t = data.time_limits;
    return Math.max(t.floor_ms, t.ratio * referenceMs);
  }

  function tooSlow(data, source, fixed) {
    if (lostBefore) {
      lostBefore = false;
      return data.time_limits.lost_text;
    }
    var one = oneCase(data);
    timed(one, data.reference, fixed); // compiles and warms the reference
    var reference = { ms: Infinity };
    for (var k = 0; k < 3; k++) { // the fastest of three: one draw can wait on a pause of the browser's
      var sample = timed(one, data.reference, fixed);
      if (sample.ms < reference.ms) reference = sample;
    }
    var limit = timeLimit(data, reference.ms);
    var first = timed(one, source, fixed, data.names); // includes the reader's compile
    var reader = first.ms > limit && !first.lost ? timed(one, source, fixed, data.names) : first;
    lastTiming = { first_ms: first.ms, reader_ms: reader.ms, reference_ms: reference.ms, limit_ms: limit };
    if (reader.lost) return T(data.time_limits.lost_text);
    if (reader.ms > limit) return TF(data.time_limits.slow_text, [reader.ms.toFixed(0), reference.ms.toFixed(1)]);
    return null;
  }

  // The whole check of `source` against exercise `data`:
  // {verdict: "agrees"|"disagrees"|"error", error?, agreement, diagnosis: [{id, title, evidence, link, why}]}
  function check(data, source) {
    if (!source.trim()) return { verdict: 'error', error: T('the shader is empty'), diagnosis: [] };
    var p = program(source, data.es_header);
    if (p.error) return { verdict: 'error', error: p.error, diagnosis: [] };
    var known = { ll_pixel: 1, ll_size: 1 };
    p.ins.forEach(function (n) { known['ll_in_' + n] = 1; });
    data.quantities.forEach(function (q) { known[userName(data.names, q.name)] = 1; });
    data.cases.groups.forEach(function (g) { Object.keys(g.uniforms).forEach(function (n) { known[userName(data.names, n)] = 1; }); });
    var unknown = Object.keys(p.uniforms).filter(function (n) { return !known[n]; });
    var unknownIns = p.ins.filter(function (n) { return !data.quantities.some(function (q) { return userName(data.names, q.name) === n; }); });
    if (unknown.length || unknownIns.length) {
      return { verdict: 'error', diagnosis: [], error: TF('the check sets no value for {}: use the names of the chapter\'s shader (the starter\'s declarations)', [unknown.concat(unknownIns).join(', ')]) };
    }
    var fixed = fixedFor(data, p);
    var slow = tooSlow(data, source, fixed);
    if (slow) return { verdict: 'error', error: slow, diagnosis: [] };
    var learner = run(data, source, fixed, null, data.names);
    if (learner.error) return { verdict: 'error', error: learner.error, diagnosis: [] };
    var reference = run(data, data.reference, fixed);
    if (reference.error) return { verdict: 'error', error: TF('the reference does not run here: {}', [reference.error]), diagnosis: [] };
    var tolerance = data.match_tolerance;
    var rule = ruleFor(data, fixed);
    var agreement = rule === 'f64' ? tally(againstExpected(data, learner.outputs, data.verdict.expected))
      : compare(data, learner.outputs, reference.outputs, rule === 'reference' ? data.verdict.bound : tolerance);
    var result = { verdict: agreement.defined > 0 && agreement.mismatches === 0 ? 'agrees' : 'disagrees', agreement: agreement, diagnosis: [], fixed: Object.keys(fixed), unset: reference.unset, rule: rule };
    if (result.verdict === 'agrees') return result;
    var found = [];
    data.mutants.forEach(function (m) {
      var out = run(data, m.shader, fixed);
      if (out.error) throw new Error('mutant ' + m.id + ' does not run: ' + out.error);
      var vsReference = compare(data, out.outputs, reference.outputs, tolerance);
      if (matches(data, vsReference)) return;
      var vsLearner = compare(data, out.outputs, learner.outputs, tolerance);
      if (!matches(data, vsLearner)) return;
      var same = m.equivalent.length ? TF('; gives the same output as {} ({})', [m.equivalent.join(', '), T(m.equivalence_reason)]) : '';
      var evidence = TF('this mistake reproduces your output on {} of {} defined cases (largest difference {}); cases where the correct shader differs from it: {}',
        [vsLearner.defined - vsLearner.mismatches, vsLearner.defined, exp1(vsLearner.max_diff), vsReference.mismatches]) + same;
      found.push({ agreement: vsLearner, finding: { id: m.id, title: m.title, evidence: evidence, link: m.link, why: m.why, hints: m.hints || [] } });
    });
    found.sort(function (a, b) {
      return (a.agreement.mismatches - b.agreement.mismatches) || (a.agreement.max_diff - b.agreement.max_diff);
    });
    result.diagnosis = found.map(function (f) { return f.finding; });
    if (!found.length && data.verdict.isolate) result.diagnosis = [isolate(data, p, source, fixed, learner, reference, rule)];
    return result;
  }

  // ------------------------------------------------------------------ the page

  function show(box, data, r) {
    var out = box.querySelector('.lightlab-exercise-result');
    out.textContent = '';
    out.className = 'lightlab-exercise-result lightlab-' + r.verdict;
    if (r.verdict === 'error') {
      out.appendChild(el('pre', { 'class': 'lightlab-editor-msg' }, r.error));
      return;
    }
    var a = r.agreement;
    var head = r.verdict === 'agrees'
      ? TF('Agrees: your shader matches the reference on all {} defined cases (within {}).', [a.defined, exp1(r.rule === 'gpu' ? data.match_tolerance : data.verdict.bound)])
      : TF('Disagrees on {} of {} defined cases (largest difference {}).', [a.mismatches, a.defined, exp1(a.max_diff)]);
    out.appendChild(el('p', {}, head));
    if (r.fixed && r.fixed.length) out.appendChild(el('p', {}, TF('Your shader does not declare {}: fixed to the chapter\'s values.', [r.fixed.join(', ')])));
    var isolated = r.diagnosis.length === 1 && r.diagnosis[0].id === 'isolated';
    if (isolated) {
      // as the command line: "Your shader disagrees with the model M: <sentence>." then the evidence
      var f0 = r.diagnosis[0];
      out.appendChild(el('p', { 'data-mistake': 'isolated' }, TF('No mistake of the catalogue reproduces your output: {}.', [f0.shown || T(f0.title)])));
      var small = el('p', {});
      small.appendChild(el('small', {}, f0.evidence));
      out.appendChild(small);
    }
    if (r.diagnosis.length && !isolated) {
      out.appendChild(el('p', {}, r.diagnosis.length === 1 ? T('The likely mistake:') : T('Mistakes that reproduce your output, best first:')));
      var ul = el('ul', { 'class': 'lightlab-diagnosis' });
      r.diagnosis.forEach(function (f) {
        var li = el('li', { 'data-mistake': f.id });
        var title = f.link ? el('a', { href: f.link }, T(f.title)) : el('strong', {}, T(f.title));
        li.appendChild(title);
        li.appendChild(document.createTextNode(' (' + f.id + '): ' + T(f.why) + ' '));
        li.appendChild(el('small', {}, f.evidence));
        ul.appendChild(li);
      });
      out.appendChild(ul);
      showHints(out, r.diagnosis[0].hints || []);
    }
  }

  // The likeliest mistake's hints (the catalogue's three: where to look, the idea, the fix),
  // one more at each press of the button, which counts them: "Show a hint (1/3)".
  function showHints(out, hints) {
    if (!hints.length) return;
    var list = el('ol', { 'class': 'lightlab-hints' });
    var button = el('button', { type: 'button', 'class': 'lightlab-hint-button' });
    var label = function () { button.textContent = TF('Show a hint ({}/{})', [list.children.length + 1, hints.length]); };
    button.addEventListener('click', function () {
      list.appendChild(el('li', {}, T(hints[list.children.length])));
      if (list.children.length < hints.length) label(); else button.remove();
    });
    label();
    out.appendChild(list);
    out.appendChild(button);
  }

  function Exercise(box, data) {
    this.box = box;
    this.data = data;
    var self = this;
    var status = box.querySelector('.lightlab-status');
    if (status) status.remove();
    var area = el('div', { 'class': 'lightlab-editor-area' });
    var gutter = el('pre', { 'class': 'lightlab-gutter', 'aria-hidden': 'true' });
    var text = el('textarea', { spellcheck: 'false', rows: 18, 'aria-label': TF('your fragment shader for {}', [T(data.title)]) });
    text.value = data.starter;
    var numbers = function () {
      var n = text.value.split('\n').length, s = '';
      for (var k = 1; k <= n; k++) s += k + '\n';
      gutter.textContent = s;
    };
    text.addEventListener('scroll', function () { gutter.scrollTop = text.scrollTop; });
    text.addEventListener('input', numbers);
    var buttons = el('div', { 'class': 'lightlab-exercise-buttons' });
    var title = T(data.title);
    var checkButton = el('button', { type: 'button', 'class': 'lightlab-check', 'aria-label': TF('Check your shader for {}', [title]) }, T('Check'));
    var reset = el('button', { type: 'button', 'class': 'lightlab-reset', 'aria-label': TF('Reset the editor of {} to the starter', [title]) }, T('Reset'));
    checkButton.addEventListener('click', function () { notify('checked', self, self.check()); });
    reset.addEventListener('click', function () { self.reset(); });
    area.appendChild(gutter);
    area.appendChild(text);
    buttons.appendChild(checkButton);
    buttons.appendChild(reset);
    box.appendChild(area);
    box.appendChild(buttons);
    box.appendChild(el('div', { 'class': 'lightlab-exercise-result', role: 'status' }));
    numbers();
    this.text = text;
    this.numbers = numbers;
  }

  Exercise.prototype.check = function () {
    var r;
    try {
      r = check(this.data, this.text.value);
    } catch (e) {
      r = { verdict: 'error', error: String(e && e.message || e), diagnosis: [] };
    }
    show(this.box, this.data, r);
    return r;
  };

  Exercise.prototype.type = function (source) {
    this.text.value = source;
    this.numbers();
  };

  // Back to the starter, after asking when there is work to lose.
  Exercise.prototype.reset = function () {
    if (this.text.value === this.data.starter) return;
    if (!window.confirm(T('Discard your shader and go back to the starter? This cannot be undone.'))) return;
    this.type(this.data.starter);
    notify('reset', this);
  };

  // ?selftest: the reference must agree; two mutants that the cases tell from the reference
  // must be diagnosed with their own id (or one the catalogue lists as giving the same output).
  Exercise.prototype.selftest = function () {
    // the reference solution in the reader's names (the exercise's mapping applies to it);
    // the crate's programs below use the model's names, so they run without the mapping
    var ref = check(this.data, this.data.solution || this.data.reference);
    var data = Object.create(this.data);
    data.names = {};
    var entry = { id: data.id, reference: ref.verdict, pass: ref.verdict === 'agrees' && ref.diagnosis.length === 0, mutants: [] };
    if (ref.error) entry.error = ref.error;
    // every uniform and input of the reference must be fed from the crate's data, or
    // reference and reader could agree on a constant
    if (ref.unset && ref.unset.length) {
      entry.pass = false;
      entry.error = 'the reference reads ' + ref.unset.join(', ') + ', which the check never sets';
    }
    // the first and the last mutant the cases tell from the reference (catalogue order puts
    // the shared vector mistakes first and the model's own, attenuation or spot, last)
    var order = data.mutants.map(function (m, k) { return k; });
    var tried = {};
    var all = query.has('exercise-all'); // every mutant the cases tell from the reference
    var rounds = all ? order.length : 2;
    for (var pass = 0; pass < rounds; pass++) {
      var from = pass === 0 || all ? order : order.slice().reverse();
      var m = null, r = null;
      for (var k = 0; k < from.length; k++) {
        if (tried[from[k]]) continue;
        tried[from[k]] = true;
        r = check(data, data.mutants[from[k]].shader);
        if (r.verdict !== 'agrees') { m = data.mutants[from[k]]; break; } // else the cases cannot tell it from the reference
      }
      if (!m) break;
      var ids = r.diagnosis.map(function (f) { return f.id; });
      var accepted = [m.id].concat(m.equivalent);
      var ok = r.verdict === 'disagrees' && ids.indexOf(m.id) >= 0 && accepted.indexOf(ids[0]) >= 0;
      entry.mutants.push({ id: m.id, verdict: r.verdict, diagnosis: ids, pass: ok, error: r.error });
      entry.pass = entry.pass && ok;
    }
    // (a model with no catalogue mistake, opengl-tutorial 8's, has no mutant to try)
    var wanted = Math.min(2, data.mutants.length);
    entry.pass = entry.pass && (all ? entry.mutants.length >= wanted : entry.mutants.length === wanted);
    // a shader far slower than the reference (the crate's slow probe: a long loop) must be
    // stopped by the time guard with its message, before the whole check runs. The guard is
    // one function for the page and the probe takes seconds, so the first exercise with a
    // probe tries it and the others name that one.
    if (data.slow_probe && slowProbedOn) {
      entry.slow = { skipped: 'the page\'s time guard was probed on ' + slowProbedOn, pass: true };
    } else if (data.slow_probe) {
      slowProbedOn = data.id;
      var sr = check(data, data.slow_probe);
      var okSlow = sr.verdict === 'error' && String(sr.error).indexOf(T(data.time_limits.slow_text).split('{}')[0]) === 0;
      entry.slow = { verdict: sr.verdict, error: sr.error, timing: lastTiming, pass: okSlow };
      entry.pass = entry.pass && okSlow;
    }
    // a mistake outside the catalogue (the crate's probe: the specular term doubled) must
    // be isolated as the command line isolates it
    if (data.probe) {
      var pr = check(data, data.probe.shader);
      var title = pr.diagnosis.length === 1 && pr.diagnosis[0].id === 'isolated' ? pr.diagnosis[0].title : '';
      var okProbe = pr.verdict === 'disagrees' && title.indexOf(data.probe.expect) === 0;
      entry.isolation = { expect: data.probe.expect, title: title, verdict: pr.verdict, pass: okProbe, error: pr.error };
      entry.pass = entry.pass && okProbe;
    }
    return entry;
  };

  var exercises = [];
  var startError = null;

  var started = false;
  function start() {
    if (started) return;
    started = true;
    var all = window.LIGHTLAB_EXERCISE_DATA || {};
    var seen = {};
    document.querySelectorAll('div.lightlab-exercise').forEach(function (box) {
      var id = box.getAttribute('data-exercise');
      if (seen[id]) return; // the print page repeats chapters
      seen[id] = true;
      try {
        if (!all[id]) throw new Error(id + ': exercise data not loaded');
        if (all[id].kind === 'number' || all[id].kind === 'choice') {
          if (!window.LightlabAnswerExercise) throw new Error('lightlab-answer.js is not loaded');
          exercises.push(new window.LightlabAnswerExercise(box, all[id])); // no GPU needed
          return;
        }
        context();
        exercises.push(new Exercise(box, all[id]));
      } catch (e) {
        startError = startError || String(e && e.message || e);
        var status = box.querySelector('.lightlab-status');
        if (status) status.textContent = TF('(the in-page check cannot run here: {})', [String(e && e.message || e)]);
      }
    });
    exercises.forEach(function (x) { notify('attach', x); });
    notify('ready', exercises);
  }

  // lightlab-live.js calls this from its ?selftest run and writes the results under
  // "exercises"; errors go into its "errors".
  window.LIGHTLAB_EXERCISES = {
    // the boxes built so far, once start() ran (a hook registered late replays them)
    started: function () { return started ? exercises : null; },
    selftest: function () {
      start(); // lightlab-live.js may ask before this script's DOMContentLoaded listener ran
      return new Promise(function (resolve) {
        var results = [], errors = [];
        if (startError) errors.push(startError);
        exercises.forEach(function (x) {
          try {
            results.push(x.selftest());
          } catch (e) {
            errors.push(x.data.id + ': ' + String(e && e.message || e));
            results.push({ id: x.data.id, pass: false, reference: 'error', mutants: [] });
          }
        });
        resolve({ results: results, errors: errors });
      });
    }
  };

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})();
