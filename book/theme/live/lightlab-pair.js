// lightlab exercises: a vertex + fragment pair run in the page, as `lightlab check-shader
// --vertex` runs it (src/checker/check/pair). The data comes from the crate (src/live/pair.rs):
// the triangles in groups sharing a camera, the f64 reference's colour of each, the rule's
// bound, the reference pair and the vertex-stage mutant pairs.
//
// 1. vertex stage: the reader's vertex shader runs on the three vertices of each triangle
//    (its real vertex stage, its outputs captured by transform feedback);
// 2. interpolation: what the fragment shader reads is blended with the triangle's
//    barycentric weights, in f32 as the rasterizer does (the crate's `interpolate`);
// 3. fragment stage: the reader's fragment shader runs once per triangle, one point each,
//    on the blended values;
// 4. the verdict and the match of a mutant are the crate's rule (lightlab-decision.js).
//
// Both shaders run under the page's loop guard (lightlab-gl.js). This file computes no
// colour.
//
// Page parameter (tests/browser.rs):
//   ?pair-check   press Check in every pair box as it stands and write
//                 {id: {verdict, shown: [the data-mistake ids the box lists]}} into
//                 <pre id="lightlab-pair-state"> Classic script (no ES modules, no fetch): the book must work from disk.
(function () {
  'use strict';

  var words = window.lightlabText || { T: function (s) { return s; }, TF: function (s) { return s; } };
  var T = words.T, TF = words.TF;
  var G = window.LightlabGL;
  var D = window.LightlabDecision;
  var WIDTH = 64; // the fragment target's width in triangles (rows follow)
  var WIDTHS = { float: 1, vec2: 2, vec3: 3, vec4: 4 };
  var shared = null;

  function context() {
    if (shared && !shared.gl.isContextLost()) return shared;
    var canvas = document.createElement('canvas');
    canvas.width = 1;
    canvas.height = 1;
    var gl = canvas.getContext('webgl2', { antialias: false, depth: false, stencil: false });
    if (!gl || !gl.getExtension('EXT_color_buffer_float')) return null;
    shared = { gl: gl };
    return shared;
  }

  // A desktop shader as GLSL ES: its `#version` line replaced by the crate's header.
  function toEs(source, header) {
    var at = source.indexOf('#version');
    if (at >= 0 && source.substring(0, at).trim() === '') {
      var rest = source.substring(at);
      return header + rest.substring(rest.indexOf('\n') + 1);
    }
    return header + source;
  }

  // The plain `in` declarations of a fragment shader: [{qualifier, type, name}].
  function inputs(source) {
    var out = [], m;
    var re = /^[ \t]*((?:(?:flat|smooth|centroid)\s+)*)in\s+(\w+)\s+(\w+)\s*;/gm;
    var clean = source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/[^\n]*/g, '');
    while ((m = re.exec(clean))) out.push({ qualifier: m[1], type: m[2], name: m[3] });
    return out;
  }

  // `source` with its loops counted against the crate's cap (lightlab-gl.js); `main` is
  // renamed and `tail` (a new `main` calling ll_main) appended. {text} or {error}.
  function guardedText(source, header, guard, tail) {
    var refusal = G.macroRefusal(source, guard);
    if (refusal) return { error: G.macroMessage(refusal) };
    var es = toEs(G.guardLoops(source).text, header + G.loopHeader(guard) + G.loopMainRename);
    return { text: es + '\n#undef main\n' + tail };
  }

  function linked(gl, vs, fs, varyings) {
    var a = G.compile(gl, gl.VERTEX_SHADER, vs);
    if (a.error) return { error: G.cleanLog(a.error) };
    var b = G.compile(gl, gl.FRAGMENT_SHADER, fs);
    if (b.error) return { error: G.cleanLog(b.error) };
    var p = gl.createProgram();
    gl.attachShader(p, a.shader);
    gl.attachShader(p, b.shader);
    if (varyings) gl.transformFeedbackVaryings(p, varyings, gl.INTERLEAVED_ATTRIBS);
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) return { error: G.cleanLog(gl.getProgramInfoLog(p) || 'link') };
    var uniforms = {};
    var n = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
    for (var i = 0; i < n; i++) {
      var info = gl.getActiveUniform(p, i);
      uniforms[info.name] = { loc: gl.getUniformLocation(p, info.name), type: info.type };
    }
    return { program: p, uniforms: uniforms };
  }

  function setUniform(gl, u, v) {
    v = [].concat(v);
    if (u.type === gl.FLOAT) gl.uniform1f(u.loc, v[0]);
    else if (u.type === gl.FLOAT_VEC3) gl.uniform3fv(u.loc, v);
    else if (u.type === gl.FLOAT_MAT4) gl.uniformMatrix4fv(u.loc, false, v);
  }

  // Sets every uniform of program `p` that the triangle or its group gives a value.
  function setUniforms(gl, p, group, t) {
    var all = { view: group.view, projection: group.projection };
    Object.keys(t.uniforms).forEach(function (k) { all[k] = t.uniforms[k]; });
    Object.keys(all).forEach(function (k) { if (p.uniforms[k]) setUniform(gl, p.uniforms[k], all[k]); });
  }

  // Stage 1: the vertex shader on every vertex; per triangle, per vertex, the values of
  // `ins` then the loop count. {values: [triangle][vertex] -> Float32Array, capped} or {error}.
  function vertexStage(gl, data, vertex, ins, guard) {
    var g = guardedText(vertex, data.es_header, guard, 'out float ll_vloops;\nvoid main() { ll_main(); ll_vloops = float(ll_loops); }\n');
    if (g.error) return { error: g.error };
    var sink = data.es_header + 'out vec4 ll_colour;\nvoid main() { ll_colour = vec4(0.0); }\n';
    var names = ins.map(function (v) { return v.name; }).concat(['ll_vloops']);
    var p = linked(gl, g.text, sink, names);
    if (p.error) return { error: TF('your vertex shader cannot run with your fragment shader: {}', [p.error]) };
    var stride = ins.reduce(function (s, v) { return s + WIDTHS[v.type]; }, 1);
    var triangles = [];
    data.groups.forEach(function (grp) { grp.triangles.forEach(function (t) { triangles.push({ g: grp, t: t }); }); });
    var attribs = data.per_vertex.map(function (name) { return { name: name, loc: gl.getAttribLocation(p.program, name) }; });
    var vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    var buffers = attribs.filter(function (a) { return a.loc >= 0; }).map(function (a) {
      var flat = [];
      triangles.forEach(function (x) { x.t.vertices.forEach(function (v) { flat = flat.concat(v[a.name]); }); });
      var b = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, b);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(flat), gl.STATIC_DRAW);
      gl.enableVertexAttribArray(a.loc);
      gl.vertexAttribPointer(a.loc, 3, gl.FLOAT, false, 0, 0);
      return b;
    });
    var out = gl.createBuffer();
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, out);
    gl.bufferData(gl.TRANSFORM_FEEDBACK_BUFFER, triangles.length * 3 * stride * 4, gl.STREAM_READ);
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, null);
    var tf = gl.createTransformFeedback();
    gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, tf);
    gl.useProgram(p.program);
    gl.enable(gl.RASTERIZER_DISCARD);
    triangles.forEach(function (x, k) {
      setUniforms(gl, p, x.g, x.t);
      gl.bindBufferRange(gl.TRANSFORM_FEEDBACK_BUFFER, 0, out, k * 3 * stride * 4, 3 * stride * 4);
      gl.beginTransformFeedback(gl.POINTS);
      gl.drawArrays(gl.POINTS, 3 * k, 3);
      gl.endTransformFeedback();
    });
    gl.disable(gl.RASTERIZER_DISCARD);
    gl.bindBufferBase(gl.TRANSFORM_FEEDBACK_BUFFER, 0, null);
    gl.bindTransformFeedback(gl.TRANSFORM_FEEDBACK, null);
    var all = new Float32Array(triangles.length * 3 * stride);
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, out);
    gl.getBufferSubData(gl.TRANSFORM_FEEDBACK_BUFFER, 0, all);
    gl.bindBuffer(gl.TRANSFORM_FEEDBACK_BUFFER, null);
    gl.bindVertexArray(null);
    buffers.forEach(function (b) { gl.deleteBuffer(b); });
    gl.deleteBuffer(out);
    gl.deleteTransformFeedback(tf);
    gl.deleteVertexArray(vao);
    var capped = -1;
    var values = triangles.map(function (x, k) {
      return [0, 1, 2].map(function (v) {
        var s = all.subarray((3 * k + v) * stride, (3 * k + v + 1) * stride);
        if (capped < 0 && s[stride - 1] > guard.loop_cap) capped = k;
        return s;
      });
    });
    return { values: values, triangles: triangles, capped: capped };
  }

  // Stage 2 (src/checker/check/pair `interpolate`): input `k` of `ins` at the sample,
  // w0·a + w1·b + w2·c per component in f32; `flat`: the last vertex's value.
  function interpolated(ins, k, per, weights) {
    var at = ins.slice(0, k).reduce(function (s, v) { return s + WIDTHS[v.type]; }, 0);
    var f = Math.fround, out = [];
    for (var c = 0; c < WIDTHS[ins[k].type]; c++) {
      if (/flat/.test(ins[k].qualifier)) { out.push(per[2][at + c]); continue; }
      var s = f(f(per[0][at + c] * weights[0]) + f(per[1][at + c] * weights[1]));
      out.push(f(s + f(per[2][at + c] * weights[2])));
    }
    return out;
  }

  // Stage 3: the fragment shader once per triangle, its inputs fed as uniforms through a
  // point's vertex stage. {outputs: [group][triangle] -> [r, g, b, a], capped} or {error}.
  function fragmentStage(gl, data, fragment, ins, stage, guard) {
    var out = G.outputName(fragment);
    if (!out) return { error: T('your fragment shader has no `out vec4` colour') };
    var g = guardedText(fragment, data.es_header, guard, 'void main() { ll_main(); if (ll_loops > ' + guard.loop_cap + ') ' +
      (out.type === 'vec4' ? out.name + '.a = ' : out.name + ' = vec3(') + guard.loop_mark.toFixed(1) + (out.type === 'vec4' ? ';' : ');') + ' }\n');
    if (g.error) return { error: g.error };
    var vs = data.es_header + 'uniform vec2 ll_pixel;\nuniform vec2 ll_size;\n';
    ins.forEach(function (v) { vs += v.qualifier + 'out ' + v.type + ' ' + v.name + ';\nuniform ' + v.type + ' ll_in_' + v.name + ';\n'; });
    vs += 'void main() {\n';
    ins.forEach(function (v) { vs += '  ' + v.name + ' = ll_in_' + v.name + ';\n'; });
    vs += '  gl_Position = vec4((ll_pixel + 0.5) / ll_size * 2.0 - 1.0, 0.0, 1.0);\n  gl_PointSize = 1.0;\n}\n';
    var p = linked(gl, vs, g.text, null);
    if (p.error) return { error: p.error };
    var n = stage.triangles.length, height = Math.max(1, Math.ceil(n / WIDTH));
    var tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, WIDTH, height, 0, gl.RGBA, gl.FLOAT, null);
    var fbo = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
    gl.viewport(0, 0, WIDTH, height);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.useProgram(p.program);
    gl.uniform2f(p.uniforms.ll_size.loc, WIDTH, height);
    stage.triangles.forEach(function (x, k) {
      setUniforms(gl, p, x.g, x.t);
      ins.forEach(function (v, i) {
        var u = p.uniforms['ll_in_' + v.name];
        if (!u) return;
        var value = interpolated(ins, i, stage.values[k], x.t.weights);
        if (v.type === 'float') gl.uniform1f(u.loc, value[0]);
        else gl['uniform' + value.length + 'fv'](u.loc, value);
      });
      gl.uniform2f(p.uniforms.ll_pixel.loc, k % WIDTH, Math.floor(k / WIDTH));
      gl.drawArrays(gl.POINTS, 0, 1);
    });
    var px = new Float32Array(WIDTH * height * 4);
    gl.readPixels(0, 0, WIDTH, height, gl.RGBA, gl.FLOAT, px);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.deleteFramebuffer(fbo);
    gl.deleteTexture(tex);
    var outputs = [], k = 0, capped = -1;
    data.groups.forEach(function (grp) {
      outputs.push(grp.triangles.map(function () {
        var o = Array.prototype.slice.call(px, k * 4, k * 4 + 4);
        if (capped < 0 && G.loopMarked(o, guard.loop_mark)) capped = k;
        k++;
        return o;
      }));
    });
    return { outputs: outputs, capped: capped };
  }

  // A pair's colours on every triangle of `data`: {outputs, capped} or {error}.
  function run(data, vertex, fragment) {
    var ctx = context();
    if (!ctx) return { error: T('this browser gives no WebGL2 context, so the check cannot run here; `lightlab exercise check` runs it on the command line') };
    var ins = inputs(fragment);
    var stage = vertexStage(ctx.gl, data, vertex, ins, data.guard);
    if (stage.error) return stage;
    var frag = fragmentStage(ctx.gl, data, fragment, ins, stage, data.guard);
    if (frag.error) return frag;
    return { outputs: frag.outputs, capped: stage.capped >= 0 ? stage.capped : frag.capped };
  }

  // A mutant pair's colours: they depend on the mutant and the triangles, never on the
  // reader's pair, so each mutant runs once per page and later checks reuse its colours
  // (the Gouraud box has 18 mutants, each compiled and drawn in about a second on a
  // software GPU: every disagreeing check after the first is that much quicker).
  function mutantRun(data, m) {
    if (!m.ran) m.ran = run(data, m.vertex, m.fragment);
    return m.ran;
  }

  // The shape lightlab-decision.js compares: every triangle a defined case.
  function asCases(data) {
    return {
      mistake_share: data.mistake_share,
      verdict: data.verdict,
      cases: { groups: data.groups.map(function (g) { return { rows: g.triangles, defined: g.triangles.map(function () { return true; }) }; }) }
    };
  }

  // The verdict (src/checker/verdict.rs case_fails on every triangle) and, when the pair
  // disagrees, every mutant pair whose colours match the reader's (fewest mismatches first).
  function check(data, vertex, fragment) {
    var r = run(data, vertex, fragment);
    if (r.error) return { verdict: 'error', error: r.error, diagnosis: [] };
    if (r.capped >= 0) return { verdict: 'error', error: TF(data.loop_text, [data.guard.loop_cap, r.capped + 1]), diagnosis: [] };
    var view = asCases(data);
    var agreement = D.tally(D.againstExpected(view, r.outputs, data.expected));
    var failing = agreement.mismatches;
    var result = { verdict: failing === 0 ? 'agrees' : 'disagrees', failing: failing, agreement: agreement, outputs: r.outputs, diagnosis: [] };
    if (failing === 0) return result;
    var found = [];
    data.mutants.forEach(function (m) {
      var mr = mutantRun(data, m);
      if (mr.error) return; // a mutant the page cannot run (an interface block: GLSL ES 3.00 has none)
      var agreement = D.compare(view, r.outputs, mr.outputs, data.match_tolerance);
      if (D.matches(view, agreement)) found.push({ id: m.id, title: m.title, why: m.why, link: m.link, mismatches: agreement.mismatches });
    });
    found.sort(function (a, b) { return a.mismatches - b.mismatches; });
    result.diagnosis = found;
    return result;
  }

  // ------------------------------------------------------------------ the pair's editors
  // Saved work: the two texts in localStorage under `ID:vertex` and `ID` (the fragment
  // shader keeps the key a single-shader exercise uses), so an old single-shader save still
  // loads. Untrusted text only ever reaches textContent and textarea values.
  function load(key, fallback) {
    try { var v = window.localStorage.getItem(key); return v === null ? fallback : v; } catch (e) { return fallback; }
  }
  function save(key, text) {
    try { window.localStorage.setItem(key, text); } catch (e) { /* storage off: the work is not kept */ }
  }

  // One editor (a labelled textarea with its line numbers), saved under `key` on input.
  function editor(label, key, starter) {
    var area = G.el('div', { 'class': 'lightlab-editor-area' });
    var gutter = G.el('pre', { 'class': 'lightlab-gutter', 'aria-hidden': 'true' });
    var text = G.el('textarea', { spellcheck: 'false', rows: 18, 'aria-label': label });
    text.value = load(key, starter);
    var numbers = function () {
      var n = text.value.split('\n').length, s = '';
      for (var k = 1; k <= n; k++) s += k + '\n';
      gutter.textContent = s;
    };
    text.addEventListener('scroll', function () { gutter.scrollTop = text.scrollTop; });
    text.addEventListener('input', function () { numbers(); save(key, text.value); });
    area.appendChild(gutter);
    area.appendChild(text);
    numbers();
    return { area: area, text: text };
  }

  // The result of `check` in `out`, in the single-shader checker's words.
  function show(out, data, r) {
    out.textContent = '';
    out.className = 'lightlab-exercise-result lightlab-' + r.verdict;
    if (r.verdict === 'error') {
      out.appendChild(G.el('pre', { 'class': 'lightlab-editor-msg' }, r.error));
      return;
    }
    var a = r.agreement;
    out.appendChild(G.el('p', {}, r.verdict === 'agrees'
      ? TF('Agrees: your shader matches the reference on all {} defined cases (within {}).', [a.defined, D.exp1(data.verdict.bound)])
      : TF('Disagrees on {} of {} defined cases (largest difference {}).', [a.mismatches, a.defined, D.exp1(a.max_diff)])));
    if (!r.diagnosis.length) return;
    out.appendChild(G.el('p', {}, r.diagnosis.length === 1 ? T('The likely mistake:') : T('Mistakes that reproduce your output, best first:')));
    var ul = G.el('ul', { 'class': 'lightlab-diagnosis' });
    r.diagnosis.forEach(function (f) {
      var li = G.el('li', { 'data-mistake': f.id });
      li.appendChild(f.link ? G.el('a', { href: f.link }, T(f.title)) : G.el('strong', {}, T(f.title)));
      li.appendChild(document.createTextNode(' ' + TF('({}): {}', [f.id, T(f.why)])));
      ul.appendChild(li);
    });
    out.appendChild(ul);
  }

  // A pair exercise in `box`: the vertex editor beside the fragment editor (they stack on a
  // narrow screen: lightlab-live.css), Check, and the result. `id` keys the saved work;
  // `starter` is {vertex, fragment}; `onChecked(r)`, when given, hears every verdict.
  function PairBox(box, data, id, title, starter, onChecked) {
    var editors = G.el('div', { 'class': 'lightlab-pair-editors' });
    var vertex = editor(TF('your vertex shader for {}', [title]), id + ':vertex', starter.vertex);
    var fragment = editor(TF('your fragment shader for {}', [title]), id, starter.fragment);
    editors.appendChild(vertex.area);
    editors.appendChild(fragment.area);
    var buttons = G.el('div', { 'class': 'lightlab-exercise-buttons' });
    var button = G.el('button', { type: 'button', 'class': 'lightlab-check', 'aria-label': TF('Check your shader for {}', [title]) }, T('Check'));
    var out = G.el('div', { 'class': 'lightlab-exercise-result', role: 'status' });
    var self = this;
    button.addEventListener('click', function () { self.check(); });
    buttons.appendChild(button);
    box.appendChild(editors);
    box.appendChild(buttons);
    box.appendChild(out);
    this.check = function () {
      var r;
      try { r = check(data, vertex.text.value, fragment.text.value); } catch (e) { r = { verdict: 'error', error: String(e && e.message || e), diagnosis: [] }; }
      show(out, data, r);
      if (onChecked) onChecked(r);
      return r;
    };
    this.vertex = vertex.text;
    this.fragment = fragment.text;
  }

  // ------------------------------------------------------------------ the pair exercise
  // A pair exercise's box in a chapter (`data.kind === 'pair'`, built by the crate:
  // live::exercises), for lightlab-exercise.js: the PairBox on the exercise's own data, keyed
  // by its id; `onChecked` passes each verdict on (the progress list).
  function PairExercise(box, data, onChecked) {
    this.box = box;
    this.data = data;
    var status = box.querySelector('.lightlab-status');
    if (status) status.remove();
    var self = this;
    this.pair = new PairBox(box, data, data.id, T(data.title), data.starter, function (r) { if (onChecked) onChecked(self, r); });
  }

  // ?selftest: the reference pair must agree, the starting pair must disagree, and the first
  // and last mutant pairs the page can run must be named by their own id.
  PairExercise.prototype.selftest = function () {
    var data = this.data;
    var ref = check(data, data.reference.vertex, data.reference.fragment);
    var entry = { id: data.id, reference: ref.verdict, pass: ref.verdict === 'agrees', mutants: [] };
    if (ref.error) entry.error = ref.error;
    var start = check(data, data.starter.vertex, data.starter.fragment);
    entry.starter = { verdict: start.verdict, diagnosis: start.diagnosis.map(function (f) { return f.id; }) };
    entry.pass = entry.pass && start.verdict === 'disagrees';
    var runnable = data.mutants.filter(function (m) { return !mutantRun(data, m).error; });
    var picked = runnable.length > 1 ? [runnable[0], runnable[runnable.length - 1]] : runnable;
    picked.forEach(function (m) {
      var r = check(data, m.vertex, m.fragment);
      var ids = r.diagnosis.map(function (f) { return f.id; });
      var ok = r.verdict === 'disagrees' && ids[0] === m.id;
      entry.mutants.push({ id: m.id, verdict: r.verdict, diagnosis: ids, pass: ok, error: r.error });
      entry.pass = entry.pass && ok;
    });
    entry.pass = entry.pass && picked.length > 0;
    return Promise.resolve(entry);
  };

  // ?pair-check (see the top): once lightlab-exercise.js built the boxes.
  function pairCheck(all) {
    var state = {};
    all.filter(function (x) { return x.pair; }).forEach(function (x) {
      var r = x.pair.check();
      var shown = Array.prototype.map.call(x.box.querySelectorAll('[data-mistake]'), function (li) { return li.getAttribute('data-mistake'); });
      state[x.data.id] = { verdict: r.verdict, error: r.error || null, shown: shown };
    });
    var pre = G.el('pre', { id: 'lightlab-pair-state', hidden: 'hidden' }, JSON.stringify(state));
    document.body.appendChild(pre);
  }
  if (new URLSearchParams(window.location.search).has('pair-check')) {
    var built = window.LIGHTLAB_EXERCISES && window.LIGHTLAB_EXERCISES.started();
    if (built) pairCheck(built);
    else (window.LIGHTLAB_EXERCISE_HOOKS = window.LIGHTLAB_EXERCISE_HOOKS || []).push({ ready: pairCheck });
  }

  window.LightlabPair = { run: run, check: check, PairBox: PairBox, PairExercise: PairExercise };
})();
