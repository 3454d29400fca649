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
// diagnosis is src/checker/diagnose.rs's: a mutant within `match_tolerance` of the reader on all but
// `mistake_share` of the defined cases, and closer to the reader than the reference is, is
// reported, fewest mismatches first; else (shader exercises) the isolation step.
//
// The reader's shader is never rewritten but for the page's guard (lightlab-gl.js): its
// `#version` line becomes the ES header the crate exports, every loop condition also counts
// iterations against the crate's cap, and one point per case is drawn with every declared
// `in` fed from the case through the vertex stage and every declared uniform set from the
// case or its group. The reader's cases are drawn in chunks under a time budget (see "the
// time guard" below), so no shader holds the page; the verdict is a promise.
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
  // the shared GL helpers and guards (lightlab-gl.js, loaded before this script)
  var G = window.LightlabGL;
  var el = G.el, cleanLog = G.cleanLog, compile = G.compile;

  // ------------------------------------------------------------------ GL

  var shared = null;
  var lostBefore = false; // the browser took the context away (a shader ran too long)
  var lastTiming = null;  // the time guard's last measurement, for ?selftest
  var slowProbedOn = null; // the exercise whose ?selftest ran the slow probe
  var checking = null;     // the exercise whose check is drawing, for a lost context's message
  function context() {
    if (shared && shared.gl.isContextLost()) {
      shared = null;
      lostBefore = true;
    }
    if (shared) return shared;
    var canvas = document.createElement('canvas');
    // the browser takes the context away when its GPU watchdog stops a draw (a hardware GPU;
    // SwiftShader has no watchdog, the loop guard ends its draws): the check under way says so
    canvas.addEventListener('webglcontextlost', function (e) {
      e.preventDefault();
      lostBefore = true;
      if (checking) show(checking.box, checking.data, { verdict: 'error', error: T(checking.data.time_limits.lost_text), diagnosis: [] });
    });
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

  // The reader's shader under the page's guard (lightlab-gl.js): a macro bomb refused, every
  // loop counted against the crate's cap and a capped case marked in its alpha. The added
  // lines go into the header, so the driver's line numbers still map to the reader's.
  // {source, header} or {error}.
  function guarded(source, header, guard) {
    var refusal = G.macroRefusal(source, guard);
    if (refusal) return { error: G.macroMessage(refusal) };
    var out = G.outputName(source);
    var loops = G.guardLoops(source);
    if (!out) return { source: loops.text, header: header + G.loopHeader(guard) };
    return { source: loops.text + G.loopFooter(guard, out), header: header + G.loopHeader(guard) + G.loopMainRename };
  }

  // A complete desktop fragment shader as a program; {error, line-mapped} when it fails.
  // `guard`: the page's limits when the shader is the reader's (see guarded), else null.
  function program(source, header, guard) {
    var ctx = context(), gl = ctx.gl;
    var key = (guard ? 'guarded\n' : '') + source;
    if (ctx.programs[key]) return ctx.programs[key];
    var shown = source, vertexHeader = header;
    if (guard) {
      var g = guarded(source, header, guard);
      if (g.error) return { error: g.error };
      source = g.source;
      header = g.header;
    }
    var es = toEs(source, header);
    var ins = inputs(source);
    var readerLines = shown.split('\n').length;
    var fs = compile(gl, gl.FRAGMENT_SHADER, es.text);
    if (fs.error) {
      return {
        error: cleanLog(fs.error.replace(/(ERROR|WARNING): (\d+):(\d+):/g, function (all, kind, file, line) {
          var n = Number(line) - es.offset;
          return n >= 1 && n <= readerLines ? kind + ': line ' + n + ':' : kind + ':';
        }))
      };
    }
    var vs = compile(gl, gl.VERTEX_SHADER, vertexFor(ins, vertexHeader));
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
    var r = { program: p, uniforms: uniforms, ins: ins.map(function (v) { return v.name; }), floated: fs.floated };
    ctx.programs[key] = r;
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

  // Sets up a run of the complete shader `source` on every case of `data`: `fixed` maps
  // quantity names to the values every run uses (the quantities the reader's shader does not
  // declare, or those a switch zeroes); `zeroed` lists group uniforms set to zero; `names`
  // is the exercise's mapping (the reader's shader) or empty (the crate's programs); the
  // reader's shader runs under the loop guard. Returns a run for draw() and finish(), or {error}.
  function prepare(data, source, fixed, zeroed, names, reader) {
    var p = program(source, data.es_header, reader ? data.guard : null);
    if (p.error) return { error: p.error };
    var gl = context().gl;
    var rows = []; // [{g, row}] in case order
    data.cases.groups.forEach(function (g) { g.rows.forEach(function (row) { rows.push({ g: g, row: row }); }); });
    var height = Math.max(1, Math.ceil(rows.length / WIDTH));
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
    var units = {}, nextUnit = 1;
    Object.keys(p.uniforms).forEach(function (name) {
      if (p.uniforms[name].type === gl.SAMPLER_2D) units[name] = nextUnit++;
    });
    var unset = {};
    Object.keys(p.uniforms).forEach(function (name) { if (name !== 'll_pixel' && name !== 'll_size') unset[name] = 1; });
    gl.viewport(0, 0, WIDTH, height);
    gl.disable(gl.BLEND);
    gl.disable(gl.DEPTH_TEST);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT);
    return { data: data, p: p, gl: gl, rows: rows, height: height, tex: tex, fbo: fbo, units: units, unset: unset,
      fixed: fixed, zeroed: zeroed, names: names, group: null };
  }

  // Draws cases [from, to) of run `r` (one point each); the GPU may still be busy after.
  function draw(r, from, to) {
    var gl = r.gl, p = r.p;
    gl.bindFramebuffer(gl.FRAMEBUFFER, r.fbo);
    gl.viewport(0, 0, WIDTH, r.height);
    gl.useProgram(p.program);
    var set = function (model, v) {
      var name = userName(r.names, model);
      var key = p.ins.indexOf(name) >= 0 ? 'll_in_' + name : name;
      var u = p.uniforms[key];
      if (u && v) {
        setUniform(gl, u, v, r.units[name]);
        delete r.unset[key];
      }
    };
    gl.uniform2f(p.uniforms.ll_size.loc, WIDTH, r.height);
    r.group = null; // uniforms are set again at each call: another run may have drawn between
    for (var index = from; index < to; index++) {
      var g = r.rows[index].g, row = r.rows[index].row;
      if (g !== r.group) {
        r.group = g;
        Object.keys(g.uniforms).forEach(function (name) {
          var v = [].concat(g.uniforms[name]);
          set(name, r.zeroed && r.zeroed.indexOf(name) >= 0 ? v.map(function () { return 0; }) : v);
        });
      }
      r.data.quantities.forEach(function (q) {
        var v = r.fixed[q.name] || value(q, g, row);
        if (v) set(q.name, v);
        else { // the model does not read it
          var user = userName(r.names, q.name);
          delete r.unset[p.ins.indexOf(user) >= 0 ? 'll_in_' + user : user];
        }
      });
      gl.uniform2f(p.uniforms.ll_pixel.loc, index % WIDTH, Math.floor(index / WIDTH));
      gl.drawArrays(gl.POINTS, 0, 1);
    }
  }

  // Reads run `r`'s results back and frees its target: {outputs: [group][case] -> [r, g, b, a],
  // unset, capped: the first case whose loops hit the guard's cap, or -1}.
  function finish(r) {
    var gl = r.gl;
    var px = new Float32Array(WIDTH * r.height * 4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, r.fbo);
    gl.readPixels(0, 0, WIDTH, r.height, gl.RGBA, gl.FLOAT, px);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(r.fbo);
    gl.deleteTexture(r.tex);
    var outputs = [], index = 0, capped = -1, mark = r.data.guard.loop_mark;
    r.data.cases.groups.forEach(function (g) {
      var o = [];
      g.rows.forEach(function () {
        if (capped < 0 && G.loopMarked(px.subarray(index * 4, index * 4 + 4), mark)) capped = index;
        o.push(Array.prototype.slice.call(px, index * 4, index * 4 + 4));
        index++;
      });
      outputs.push(o);
    });
    return { outputs: outputs, unset: Object.keys(r.unset), capped: capped };
  }

  // A whole run at once, for the crate's programs (reference, mutants) and for the reader's
  // shader once the time guard let it through every case: {outputs, unset, capped} or {error}.
  function run(data, source, fixed, zeroed, names, reader) {
    var r = prepare(data, source, fixed, zeroed, names, reader);
    if (r.error) return { error: r.error };
    draw(r, 0, r.rows.length);
    return finish(r);
  }
  // ------------------------------------------------------------------ the decision rule (lightlab-decision.js)
  var D = window.LightlabDecision;
  var compare = D.compare, matches = D.matches, exp1 = D.exp1;
  var againstExpected = D.againstExpected, tally = D.tally, ruleFor = D.ruleFor;
  function isolate(data, p, source, fixed, learner, reference, rule) {
    return D.isolate(data, p, source, fixed, learner, reference, { run: run, userName: userName, rule: rule });
  }

  // The quantities the reader's program does not declare, fixed to their defaults (one
  // policy with the command line: undeclared quantities take the chapter's values).
  // `unread`: the model names of those it declares and never reads (neverRead), which the
  // cases vary as the command line does (the reference reads them; the reader's shader not).
  function fixedFor(data, p, unread) {
    var fixed = {};
    data.quantities.forEach(function (q) {
      var user = userName(data.names, q.name);
      var declared = p.ins.indexOf(user) >= 0 || p.uniforms[user] !== undefined || unread.indexOf(q.name) >= 0;
      if (!declared && q['default']) fixed[q.name] = q['default'].slice();
    });
    // the exercise's mapping fixes quantities too, declared or not (as [values] on the command line)
    Object.keys(data.values || {}).forEach(function (name) { fixed[name] = data.values[name].slice(); });
    return fixed;
  }

  // The quantities the cases vary that the reader's shader declares as uniforms but never
  // reads, as the command line's notes (src/checker/check/mapping.rs, never_read_notes):
  // `data.never_read_text` filled with the reader's name and the model's, array indices
  // written [i], each note once. The driver says which uniforms a program reads (its active
  // ones); whether the shader declares one it does not read, the driver says too: the
  // shader compiles again with one more function whose body names it only if it is
  // declared. A name whose outermost variable is not declared skips its members. The
  // quantities the exercise's mapping fixes (`data.values`) are not varied, so not noted;
  // nor are `in` variables (the driver reports no inactive fragment input). The command line
  // counts the name's occurrences instead, so a function parameter of the same name (the
  // crate's references pass `lightPos` so) counts there as a read: the page's note is the
  // more exact where the two differ.
  function neverRead(data, p, source) {
    var gl = context().gl;
    var known = {};
    var declares = function (name) {
      if (known[name] === undefined) {
        var es = toEs(source + '\nvoid ll_names_it() { ' + name + '; }\n', data.es_header);
        var fs = compile(gl, gl.FRAGMENT_SHADER, es.text);
        if (fs.shader) gl.deleteShader(fs.shader);
        known[name] = !fs.error;
      }
      return known[name];
    };
    var anyIndex = function (name) { return name.replace(/\[\d+\]/g, '[i]'); };
    // the leaves: each case quantity the model reads, then each scene uniform of the groups
    var leaves = data.quantities.filter(function (q) { return q.slot && typeof q.slot === 'object'; })
      .map(function (q) { return q.name; });
    data.cases.groups.forEach(function (g) {
      Object.keys(g.uniforms).forEach(function (name) { if (leaves.indexOf(name) < 0) leaves.push(name); });
    });
    var notes = [], names = [];
    leaves.forEach(function (model) {
      var user = userName(data.names, model);
      if (p.uniforms[user] !== undefined || p.ins.indexOf(user) >= 0) return;
      if (data.values && data.values[model]) return;
      if (!/^[A-Za-z_]\w*(\[\d+\])?(\.\w+(\[\d+\])?)*$/.test(user)) return;
      if (!declares(user.split(/[.[]/)[0]) || !declares(user)) return;
      names.push(model);
      var note = TF(data.never_read_text, [anyIndex(user), anyIndex(model)]);
      if (notes.indexOf(note) < 0) notes.push(note);
    });
    return { names: names, notes: notes };
  }

  // ------------------------------------------------------------------ the time guard
  // A draw cannot be stopped once issued, so the reader's shader is drawn in chunks of
  // growing size (1, 2, 4, … cases), after the reference drew the same chunks, timed. After
  // each chunk the page waits for the GPU (lightlab-gl.js `waitForGpu`) and yields to the
  // event loop (the tab stays responsive), and stops the check as soon as the reader's cases
  // so far took longer than their budget: the crate's floor plus its ratio times the
  // reference's time on the same cases (data.guard, src/live/guard.rs). The reader's first
  // draw includes the program's compile (SwiftShader and ANGLE build a program at its first
  // draw), so case 1 is drawn once untimed first: a correct shader is never judged by its
  // compile. The loop guard bounds every single draw (SwiftShader has no GPU watchdog); on
  // a GPU with one, an endless loop loses the context, and the check says so.

  // The chunks [from, to) over `n` cases: sizes 1, 2, 4, …
  function chunks(n) {
    var out = [], from = 0, size = 1;
    while (from < n) {
      out.push([from, Math.min(n, from + size)]);
      from += size;
      size *= 2;
    }
    return out;
  }

  // Draws run `r` chunk by chunk, waiting for the GPU after each and yielding to the page
  // between chunks: {ms: [per chunk]}, or {stopped: {chunk, ms, lost}} as soon as the total
  // time of chunks 0..k passes budget(k) ms.
  function drawChunks(r, parts, budget) {
    var times = [], total = 0, k = 0;
    var next = function () {
      if (k >= parts.length) return { ms: times };
      var t0 = performance.now();
      draw(r, parts[k][0], parts[k][1]);
      var ms = G.waitForGpu(r.gl, true, t0);
      total += ms;
      var lost = r.gl.isContextLost();
      if (lost || total > budget(k)) return { stopped: { chunk: k, ms: total, lost: lost } };
      times.push(ms);
      k++;
      return G.yieldTurn().then(next);
    };
    return Promise.resolve().then(next);
  }

  function sum(list, upTo) {
    var s = 0;
    for (var k = 0; k <= upTo && k < list.length; k++) s += list[k];
    return s;
  }

  // The reference's and the reader's runs of the check, the reader's under the time guard:
  // {reference, learner} (whole runs, as run() returns them) or {error}.
  function guardedRuns(data, source, fixed) {
    var limits = data.guard;
    var ref = prepare(data, data.reference, fixed);
    if (ref.error) return Promise.resolve({ error: TF('the reference does not run here: {}', [ref.error]) });
    var parts = chunks(ref.rows.length);
    draw(ref, 0, 1); // compiles and warms the reference
    G.waitForGpu(ref.gl, true, 0);
    var endless = function () { return Infinity; }; // the crate's reference always ends
    return drawChunks(ref, parts, endless).then(function (refTimes) {
      var reference = finish(ref);
      var r = prepare(data, source, fixed, null, data.names, true);
      if (r.error) return { error: r.error };
      // the most the reader's chunks 0..k may take in total
      var allowed = function (k) { return limits.chunk_floor_ms + limits.chunk_ratio * sum(refTimes.ms, k); };
      var stopped = function (ms, last, c) {
        if (r.gl.isContextLost()) return { error: T(data.time_limits.lost_text) };
        return { error: TF(data.time_limits.slow_text, [ms.toFixed(0), 1, last, (text.number || String)(sum(refTimes.ms, c).toFixed(1))]) };
      };
      var t0 = performance.now();
      draw(r, 0, 1); // compiles the reader's program (the loop guard bounds the draw)
      var warm = G.waitForGpu(r.gl, true, t0);
      if (r.gl.isContextLost()) return stopped(warm, 1, 0);
      return G.yieldTurn().then(function () {
        return drawChunks(r, parts, allowed);
      }).then(function (got) {
        if (got.stopped) {
          var c = got.stopped.chunk;
          lastTiming = { cases: parts[c], reader_ms: got.stopped.ms, reference_ms: sum(refTimes.ms, c), limit_ms: allowed(c) };
          return stopped(got.stopped.ms, parts[c][1], c);
        }
        lastTiming = { warm_ms: warm, reader_ms: sum(got.ms, parts.length), reference_ms: sum(refTimes.ms, parts.length), limit_ms: allowed(parts.length - 1) };
        var learner = finish(r);
        if (learner.capped >= 0) {
          lastTiming.capped = learner.capped;
          return { error: TF(data.time_limits.loop_text, [limits.loop_cap, learner.capped + 1]) };
        }
        return { reference: reference, learner: learner };
      });
    });
  }

  // The whole check of `source` against exercise `data`, as a promise of
  // {verdict: "agrees"|"disagrees"|"error", error?, agreement, diagnosis: [{id, title, evidence, link, why}]}
  function check(data, source) {
    var fail = function (error) { return { verdict: 'error', error: error, diagnosis: [] }; };
    if (lostBefore) { // the context was lost since the last check: a new one, and say why
      lostBefore = false;
      shared = null;
      return Promise.resolve(fail(T(data.time_limits.lost_text)));
    }
    if (!source.trim()) return Promise.resolve(fail(T('the shader is empty')));
    var p = program(source, data.es_header, data.guard);
    if (p.error) return Promise.resolve(fail(p.error));
    var known = { ll_pixel: 1, ll_size: 1 };
    p.ins.forEach(function (n) { known['ll_in_' + n] = 1; });
    data.quantities.forEach(function (q) { known[userName(data.names, q.name)] = 1; });
    data.cases.groups.forEach(function (g) { Object.keys(g.uniforms).forEach(function (n) { known[userName(data.names, n)] = 1; }); });
    var unknown = Object.keys(p.uniforms).filter(function (n) { return !known[n]; });
    var unknownIns = p.ins.filter(function (n) { return !data.quantities.some(function (q) { return userName(data.names, q.name) === n; }); });
    if (unknown.length || unknownIns.length) {
      return Promise.resolve(fail(TF('the check sets no value for {}: use the names of the chapter\'s shader (the starter\'s declarations)', [unknown.concat(unknownIns).join(', ')])));
    }
    var broken = D.brokenRule(data, p, source, userName); if (broken) return Promise.resolve(fail(broken));
    var unread = neverRead(data, p, source);
    var fixed = fixedFor(data, p, unread.names);
    return guardedRuns(data, source, fixed).then(function (runs) {
      if (runs.error) return fail(runs.error);
      return decide(data, p, source, fixed, runs.learner, runs.reference);
    }).then(function (r) {
      r.never_read = unread.notes;
      r.floated = p.floated;
      return r;
    });
  }

  // The catalogue's runs, kept per exercise and fixed values: a mutant's outputs depend on
  // nothing of the reader's shader but the values its check fixes (fixedFor), so a later
  // check's diagnosis draws none of them again (the multiple lights' 61 mutants took about
  // 1.6 s of every wrong answer's check in SwiftShader). keptRuns(data, fixed)[k] is mutant
  // k's run (data.mutants, then data.candidates).
  var catalogueRuns = Object.create(null);
  function keptRuns(data, fixed) {
    var values = Object.keys(fixed).sort().map(function (n) { return [n, fixed[n]]; });
    var key = JSON.stringify([data.id, values]);
    return catalogueRuns[key] || (catalogueRuns[key] = []);
  }

  // Mutant k's run from `kept`, or drawn and kept there. A mutant that does not compile (a
  // part left out that another part needs) is kept as such; a run during which the context
  // was lost is not kept. `counts` tallies the runs drawn and kept (?exercise-verdicts).
  function catalogueRun(kept, k, m, data, fixed, counts) {
    if (kept[k]) {
      counts.kept++;
      return kept[k];
    }
    counts.drawn++;
    var out = run(data, m.shader, fixed);
    if (shared && !shared.gl.isContextLost()) kept[k] = out;
    return out;
  }

  // The verdict once both runs are in: agreement, then the catalogue's mistakes (the crate's
  // programs, one turn of the event loop each; each drawn once per page, catalogueRun), then
  // isolation.
  function decide(data, p, source, fixed, learner, reference) {
    var tolerance = data.match_tolerance;
    var rule = ruleFor(data, fixed);
    var agreement = rule === 'f64' ? tally(againstExpected(data, learner.outputs, data.verdict.expected))
      : compare(data, learner.outputs, reference.outputs, rule === 'reference' ? data.verdict.bound : tolerance);
    var result = { verdict: agreement.defined > 0 && agreement.mismatches === 0 ? 'agrees' : 'disagrees', agreement: agreement, diagnosis: [], fixed: Object.keys(fixed), unset: reference.unset, rule: rule, catalogue: { drawn: 0, kept: 0 } };
    if (result.verdict === 'agrees') return result;
    var found = [];
    // how far the reader is from the reference: a mutant must come closer (src/checker/diagnose.rs)
    var baseline = compare(data, reference.outputs, learner.outputs, tolerance);
    var chain = Promise.resolve();
    // the reader's text, for the tie-break between mistakes with the same output (src/checker/diagnose.rs text_score)
    var squashed = D.squashed(source);
    // the catalogue's mutants, then (a variant's) the exercise's change left out: src/exercises/change.rs
    var kept = keptRuns(data, fixed);
    data.mutants.concat(data.candidates || []).forEach(function (m, k) {
      chain = chain.then(G.yieldTurn).then(function () {
        var out = catalogueRun(kept, k, m, data, fixed, result.catalogue);
        if (out.error && m.optional) return; // a part left out that another part needs: no candidate
        if (out.error) throw new Error('mutant ' + m.id + ' does not run: ' + out.error);
        var vsReference = compare(data, out.outputs, reference.outputs, tolerance);
        var vsLearner = compare(data, out.outputs, learner.outputs, tolerance);
        if (!matches(data, vsLearner) || vsLearner.mismatches >= baseline.mismatches) return;
        found.push({ agreement: vsLearner, score: D.textScore(m.signs || [], squashed), finding: D.finding(m, vsLearner, vsReference) });
      });
    });
    return chain.then(function () {
      found.sort(function (a, b) {
        return (a.agreement.mismatches - b.agreement.mismatches) || (b.score - a.score) ||
          (a.agreement.max_diff - b.agreement.max_diff);
      });
      result.diagnosis = found.map(function (f) { return f.finding; });
      if (found.length || !data.verdict.isolate) return result;
      return isolate(data, p, source, fixed, learner, reference, rule).then(function (f) {
        result.diagnosis = [f];
        return result;
      });
    });
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
    (r.never_read || []).forEach(function (text) { out.appendChild(el('p', { 'class': 'lightlab-never-read' }, text)); });
    if (r.floated && r.floated.length) out.appendChild(el('p', { 'class': 'lightlab-floated' }, G.floatedNote(r.floated)));
    var isolated = r.diagnosis.length === 1 && r.diagnosis[0].id === 'isolated';
    if (isolated) {
      // as the command line: "Your shader disagrees with the model M: <sentence>." then the evidence
      var f0 = r.diagnosis[0];
      out.appendChild(el('p', { 'data-mistake': 'isolated' }, TF('No mistake of the catalogue reproduces your output: {}.', [f0.shown || T(f0.title)])));
      var small = el('p', {});
      small.appendChild(el('small', {}, f0.evidence));
      out.appendChild(small);
      // the isolation's hints, already in the reader's language (where, the idea, the fix)
      showHints(out, f0.hints || []);
    }
    if (r.diagnosis.length && !isolated) {
      out.appendChild(el('p', {}, r.diagnosis.length === 1 ? T('The likely mistake:') : T('Mistakes that reproduce your output, best first:')));
      var ul = el('ul', { 'class': 'lightlab-diagnosis' });
      r.diagnosis.forEach(function (f) {
        var li = el('li', { 'data-mistake': f.id });
        var name = f.shown || T(f.title);
        var title = f.link ? el('a', { href: f.link }, name) : el('strong', {}, name);
        li.appendChild(title);
        li.appendChild(document.createTextNode(' ' + TF('({}): {}', [f.id, T(f.why)]) + ' '));
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
    checkButton.addEventListener('click', function () {
      self.check().then(function (r) { notify('checked', self, r); });
    });
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
    this.checkButton = checkButton;
  }

  // A check of `source` shown in `x`'s box while it runs: a promise of its result, never
  // rejected (an exception is an error verdict). One check at a time on the page.
  function checkIn(x, data, source) {
    var failed = function (e) { return { verdict: 'error', error: String(e && e.message || e), diagnosis: [] }; };
    var previous = running;
    running = previous.then(function () {
      checking = { box: x.box, data: x.data };
      var r;
      try { r = check(data, source); } catch (e) { r = Promise.resolve(failed(e)); }
      return r.then(null, failed).then(function (result) { checking = null; return result; });
    });
    return running;
  }
  var running = Promise.resolve();

  // The reader's shader checked: "checking…" and the button off while it runs, then the result.
  Exercise.prototype.check = function () {
    var self = this;
    var out = this.box.querySelector('.lightlab-exercise-result');
    out.textContent = T('Checking…');
    out.className = 'lightlab-exercise-result';
    this.checkButton.disabled = true;
    return checkIn(this, this.data, this.text.value).then(function (r) {
      self.checkButton.disabled = false;
      self.timing = lastTiming; // the time guard's measurement, for ?exercise-state
      show(self.box, self.data, r);
      return r;
    });
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
  Exercise.prototype.selftest = async function () {
    // the reference solution in the reader's names (the exercise's mapping applies to it);
    // the crate's programs below use the model's names, so they run without the mapping
    var ref = await checkIn(this, this.data, this.data.solution || this.data.reference);
    var data = Object.create(this.data);
    data.names = {}; data.rules = null; // the exercise's rules bind the reader, not the crate's programs
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
        r = await checkIn(this, data, data.mutants[from[k]].shader);
        if (r.verdict !== 'agrees') { m = data.mutants[from[k]]; break; } // else the cases cannot tell it from the reference
      }
      if (!m) break;
      var ids = r.diagnosis.map(function (f) { return f.id; });
      var accepted = [m.id].concat(m.equivalent);
      // a mutant in one site (src/checker/sites.rs) must be named with its site
      var sameSite = !m.site || (r.diagnosis[0] && r.diagnosis[0].site === m.site);
      var ok = r.verdict === 'disagrees' && ids.indexOf(m.id) >= 0 && accepted.indexOf(ids[0]) >= 0 && sameSite;
      entry.mutants.push({ id: m.site ? m.id + '@' + m.site : m.id, verdict: r.verdict, diagnosis: ids, pass: ok, error: r.error });
      entry.pass = entry.pass && ok;
    }
    // (a model with no catalogue mistake, opengl-tutorial 8's, has no mutant to try)
    var wanted = Math.min(2, data.mutants.length);
    entry.pass = entry.pass && (all ? entry.mutants.length >= wanted : entry.mutants.length === wanted);
    // a loop far past the loop guard's cap (the crate's slow probe, which would hold the page
    // for minutes in SwiftShader) must be stopped and named by the guard. The guard is one
    // function for the page, so the first exercise with a probe tries it and the others name
    // that one.
    if (data.slow_probe && slowProbedOn) {
      entry.slow = { skipped: 'the page\'s time guard was probed on ' + slowProbedOn, pass: true };
    } else if (data.slow_probe) {
      slowProbedOn = data.id;
      var sr = await checkIn(this, data, data.slow_probe);
      var okSlow = sr.verdict === 'error' && String(sr.error).indexOf(T(data.time_limits.loop_text).split('{}')[0]) === 0;
      entry.slow = { verdict: sr.verdict, error: sr.error, timing: lastTiming, pass: okSlow };
      entry.pass = entry.pass && okSlow;
    }
    // a mistake outside the catalogue (the crate's probe: the specular term doubled) must
    // be isolated as the command line isolates it
    if (data.probe) {
      var pr = await checkIn(this, data, data.probe.shader);
      var title = pr.diagnosis.length === 1 && pr.diagnosis[0].id === 'isolated' ? pr.diagnosis[0].title : '';
      var okProbe = pr.verdict === 'disagrees' && title.indexOf(data.probe.expect) === 0;
      var hints = title ? pr.diagnosis[0].hints : [];
      entry.isolation = { expect: data.probe.expect, title: title, hints: hints, verdict: pr.verdict, pass: okProbe, error: pr.error };
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
        // number and choice boxes (lightlab-answer.js, no GPU needed), pair boxes (lightlab-pair.js)
        var kind = all[id].kind, Other = kind === 'pair' ? window.LightlabPair && window.LightlabPair.PairExercise
          : (kind === 'number' || kind === 'choice') && window.LightlabAnswerExercise;
        if (kind && !Other) throw new Error('the script for ' + kind + ' exercises is not loaded');
        if (Other) { exercises.push(new Other(box, all[id], function (x, r) { notify('checked', x, r); })); return; }
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
      var results = [], errors = [];
      if (startError) errors.push(startError);
      var chain = Promise.resolve();
      exercises.forEach(function (x) {
        chain = chain.then(function () { return x.selftest(); }).then(function (r) { results.push(r); }, function (e) {
          errors.push(x.data.id + ': ' + String(e && e.message || e));
          results.push({ id: x.data.id, pass: false, reference: 'error', mutants: [] });
        });
      });
      return chain.then(function () { return { results: results, errors: errors }; });
    }
  };

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})();
