// lightlab live figures: draws the figures that the book build describes in
// generated/live/<id>.js with WebGL2, running the GLSL the crate verifies.
//
// This file computes nothing about light. Every number (uniforms, matrices, meshes,
// textures, slider values, curves) comes from the crate: a control's option carries the
// patch of uniforms it sets, a toggle names the uniforms it zeroes. The script only
// compiles, uploads, sets uniforms and draws, and compares with the reference PNGs.
//
// Classic script (no ES modules, no fetch): the book must work when opened from disk.
//
// URL parameters:
//   ?selftest  render every figure at each of its reference points and write the result
//              as JSON into <pre id="lightlab-selftest">, with the exercises' self-check
//              (lightlab-exercise.js) under "exercises"
//   ?selftest=figures  (tests) the figures' part alone: "exercises" stays empty
//   ?fps[=N]   time each figure over N frames (default 30) and write {"fps":[{id, width, height, ms_per_frame, fps}]}
//              into <pre id="lightlab-fps">
//   ?set=ID.C=K[,ID.C=K]  start figure ID with control number C at option K (screenshots)
//   ?shot      write each figure's canvas as a PNG data URL into <pre id="lightlab-shots">
//   ?lose-context=ID  (tests) the browser's WEBGL_lose_context takes figure ID's context away
//              (1: the first figure's) before ?selftest runs; its result then carries
//              {lost: true, message}: the message the figure shows
//   ?restore-context  (tests) with ?lose-context: then gives the context back before ?selftest
//   ?figure-mutant=ID  (a test's) put the catalogue mutant ID, whose text the crate emitted in
//              the figure's data, into the editable program of every figure that has it;
//              the self-check must then fail. The URL names the id only, never shader text.
(function () {
  'use strict';

  var query = new URLSearchParams(window.location.search);
  var errors = [];
  window.addEventListener('error', function (e) {
    errors.push(String(e.message) + (e.filename ? ' at ' + e.filename + ':' + e.lineno : ''));
  });
  window.addEventListener('unhandledrejection', function (e) {
    errors.push('unhandled rejection: ' + String(e.reason));
  });

  // the page's words in the reader's language (lightlab-i18n.js); English when it is missing
  var words = window.lightlabText || { T: function (s) { return s; }, TF: function (s) { return s; } };
  var T = words.T, TF = words.TF;
  var numberList = words.numbers || function (v, digits) { return v.map(function (x) { return Number(x).toFixed(digits); }).join(', '); };
  var reducedMotion = window.matchMedia && window.matchMedia('(prefers-reduced-motion: reduce)').matches;

  function bytes(b64) {
    var s = atob(b64);
    var out = new Uint8Array(s.length);
    for (var i = 0; i < s.length; i++) out[i] = s.charCodeAt(i);
    return out;
  }
  function f32(b64) { return new Float32Array(bytes(b64).buffer); }
  function u32(b64) { return new Uint32Array(bytes(b64).buffer); }

  function clone(state) {
    var out = {};
    for (var k in state) out[k] = Array.isArray(state[k]) ? state[k].slice() : state[k];
    return out;
  }

  // the shared GL helpers and guards (lightlab-gl.js, loaded before this script)
  var G = window.LightlabGL;
  var el = G.el, compile = G.compile;

  var uid = 0;

  // ------------------------------------------------------------------ GL helpers

  function link(gl, vertex, fragment) {
    var vs = compile(gl, gl.VERTEX_SHADER, vertex);
    if (vs.error) return { error: vs.error, stage: 'vertex' };
    var fs = compile(gl, gl.FRAGMENT_SHADER, fragment);
    if (fs.error) return { error: fs.error, stage: 'fragment' };
    var p = gl.createProgram();
    gl.attachShader(p, vs.shader);
    gl.attachShader(p, fs.shader);
    gl.bindAttribLocation(p, 0, 'aPos');
    gl.bindAttribLocation(p, 1, 'aNormal');
    gl.bindAttribLocation(p, 2, 'aTexCoords');
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) return { error: gl.getProgramInfoLog(p) || T('link failed'), stage: 'link' };
    var uniforms = {};
    var n = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
    for (var i = 0; i < n; i++) {
      var info = gl.getActiveUniform(p, i);
      var name = info.name.replace(/\[0\]$/, '');
      uniforms[name] = { loc: gl.getUniformLocation(p, info.name), type: info.type };
    }
    return { program: p, uniforms: uniforms, floated: fs.floated };
  }

  function setUniform(gl, u, v) {
    switch (u.type) {
      case gl.FLOAT: gl.uniform1f(u.loc, v[0]); break;
      case gl.FLOAT_VEC2: gl.uniform2fv(u.loc, v); break;
      case gl.FLOAT_VEC3: gl.uniform3fv(u.loc, v); break;
      case gl.FLOAT_VEC4: gl.uniform4fv(u.loc, v); break;
      case gl.FLOAT_MAT3: gl.uniformMatrix3fv(u.loc, false, v); break;
      case gl.FLOAT_MAT4: gl.uniformMatrix4fv(u.loc, false, v); break;
      default: gl.uniform1i(u.loc, v[0]); break;
    }
  }

  function uploadMesh(gl, m) {
    var vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    [[m.positions, 3], [m.normals, 3], [m.uvs, 2]].forEach(function (a, i) {
      var b = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, b);
      gl.bufferData(gl.ARRAY_BUFFER, f32(a[0]), gl.STATIC_DRAW);
      gl.enableVertexAttribArray(i);
      gl.vertexAttribPointer(i, a[1], gl.FLOAT, false, 0, 0);
    });
    var ib = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ib);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, u32(m.triangles), gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    return { vao: vao, count: m.indices };
  }

  function uploadTexture(gl, t) {
    var tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGB32F, t.width, t.height, 0, gl.RGB, gl.FLOAT, f32(t.rgb));
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
    return tex;
  }

  // ------------------------------------------------------------------ a figure

  function Figure(root, spec) {
    this.root = root;
    this.spec = spec;
    this.canvas = root.querySelector('canvas.lightlab-live');
    this.status = root.querySelector('.lightlab-status');
    var gl = this.canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: true, alpha: false });
    if (!gl) throw new Error(spec.id + ': WebGL2 is not available');
    this.gl = gl;
    if (!gl.getExtension('OES_texture_float_linear')) errors.push(spec.id + ': OES_texture_float_linear missing');
    this.upload();
    this.watchContext();
    this.choice = spec.controls.map(function (c) { return c.default; });
    this.colors = {};
    this.visible = true;
    this.playing = null;
    this.applyControls();
    if (this.status) this.status.textContent = '';
  }

  // Meshes, textures and programs onto the GPU: at the start and again when the browser
  // gives a lost context back (everything of the old context is gone then).
  Figure.prototype.upload = function () {
    var gl = this.gl, spec = this.spec, self = this;
    var assets = window.LIGHTLAB_ASSETS || { meshes: {}, textures: {} };
    this.meshes = {};
    this.textures = {};
    this.programs = {};
    spec.panels.forEach(function (p) {
      p.draws.forEach(function (d) {
        self.meshNames(d).forEach(function (name) {
          if (!self.meshes[name]) {
            if (!assets.meshes[name]) throw new Error(spec.id + ': mesh ' + name + ' not loaded');
            self.meshes[name] = uploadMesh(gl, assets.meshes[name]);
          }
        });
        Object.keys(d.textures).forEach(function (s) {
          var name = d.textures[s];
          if (!self.textures[name]) {
            if (!assets.textures[name]) throw new Error(spec.id + ': texture ' + name + ' not loaded');
            self.textures[name] = uploadTexture(gl, assets.textures[name]);
          }
        });
      });
    });
    Object.keys(spec.programs).forEach(function (name) {
      var p = spec.programs[name];
      var r = link(gl, p.vertex, p.fragment);
      if (r.error) throw new Error(spec.id + ': program ' + name + ' (' + r.stage + '): ' + r.error);
      self.programs[name] = r;
    });
  };

  // A lost context (the browser's GPU watchdog stopped a draw, or the GPU process was
  // reset) leaves a message in the figure; a restored one gets everything back, the
  // reader's edited shader included, and draws again.
  Figure.prototype.watchContext = function () {
    var self = this;
    this.canvas.addEventListener('webglcontextlost', function (e) {
      e.preventDefault(); // without it the browser never gives the context back
      self.lost = true;
      self.say(T('The browser took this figure\'s GPU context away (a shader that ran too long, such as an endless loop, or a reset of the GPU); the figure comes back when the browser gives the context back, or when the page is reloaded.'));
    });
    this.canvas.addEventListener('webglcontextrestored', function () {
      self.lost = false;
      try {
        self.upload();
        if (self.edited) self.compileEdited(self.edited);
        self.say('');
        self.render();
      } catch (e) {
        self.say(TF('(not running here: {})', [String(e && e.message || e)]));
      }
    });
  };

  // A message under the figure (role status, so a screen reader says it); '' removes it.
  Figure.prototype.say = function (message) {
    if (!this.message) {
      this.message = el('p', { 'class': 'lightlab-figure-msg', role: 'status' });
      this.canvas.parentNode.insertBefore(this.message, this.canvas.nextSibling);
    }
    this.message.textContent = message;
    this.message.hidden = !message;
  };

  Figure.prototype.meshNames = function (d) {
    if (d.mesh.charAt(0) !== '@') return [d.mesh];
    var key = d.mesh, names = {};
    this.spec.points.forEach(function (p) { names[p.state[key]] = 1; });
    this.spec.controls.forEach(function (c) {
      c.options.forEach(function (o) { if (o.patch[key]) names[o.patch[key]] = 1; });
    });
    if (this.spec.state[key]) names[this.spec.state[key]] = 1;
    return Object.keys(names);
  };

  Figure.prototype.applyControls = function () {
    var s = clone(this.spec.state);
    var self = this;
    this.spec.controls.forEach(function (c, i) {
      if (c.kind === 'range' || c.kind === 'select' || c.kind === 'orbit' || c.kind === 'grid') {
        var patch = c.options[self.choice[i]].patch;
        for (var k in patch) s[k] = Array.isArray(patch[k]) ? patch[k].slice() : patch[k];
      } else if (c.kind === 'color' && self.colors[c.key]) {
        s[c.key] = self.colors[c.key].slice();
      }
    });
    this.spec.controls.forEach(function (c, i) {
      if (c.kind === 'toggle' && self.choice[i] === 1) {
        c.zero.forEach(function (k) { s[k] = s[k].map(function () { return 0; }); });
      }
    });
    this.state = s;
  };

  Figure.prototype.render = function (state) {
    var gl = this.gl, spec = this.spec, s = state || this.state, self = this;
    if (this.lost || gl.isContextLost()) return; // the message says so; a restore draws again
    var w = spec.width, h = spec.height;
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.enable(gl.SCISSOR_TEST);
    var filter = s['@filter'] === 'nearest' ? gl.NEAREST : gl.LINEAR;
    spec.panels.forEach(function (panel, pi) {
      gl.viewport(pi * w, 0, w, h);
      gl.scissor(pi * w, 0, w, h);
      var c = s.clearColor || [0, 0, 0, 1];
      gl.clearColor(c[0], c[1], c[2], c[3]);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      panel.draws.forEach(function (d) {
        if (d.when && !(s[d.when] && s[d.when][0])) return;
        var pname = d.program.charAt(0) === '@' ? s[d.program] : d.program;
        var prog = self.programs[pname];
        var mname = d.mesh.charAt(0) === '@' ? s[d.mesh] : d.mesh;
        var mesh = self.meshes[mname];
        if (!prog || !mesh) throw new Error(spec.id + ': no program ' + pname + ' or mesh ' + mname);
        gl.useProgram(prog.program);
        var unit = 0;
        for (var name in prog.uniforms) {
          var u = prog.uniforms[name];
          if (d.textures[name] !== undefined) {
            gl.activeTexture(gl.TEXTURE0 + unit);
            gl.bindTexture(gl.TEXTURE_2D, self.textures[d.textures[name]]);
            gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
            gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
            gl.uniform1i(u.loc, unit);
            unit++;
            continue;
          }
          var v = d.uniforms[name] !== undefined ? s[d.uniforms[name]] : (name === 'model' ? d.model : s[name]);
          if (v !== undefined && typeof v !== 'string') setUniform(gl, u, v);
        }
        if (d.cull) gl.enable(gl.CULL_FACE); else gl.disable(gl.CULL_FACE);
        gl.bindVertexArray(mesh.vao);
        gl.drawElements(gl.TRIANGLES, mesh.count, gl.UNSIGNED_INT, 0);
      });
    });
    gl.bindVertexArray(null);
    gl.disable(gl.SCISSOR_TEST);
  };

  Figure.prototype.pixels = function () {
    var gl = this.gl, w = this.canvas.width, h = this.canvas.height;
    var raw = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, raw);
    var out = new Uint8Array(w * h * 4); // top row first, as the PNG
    for (var y = 0; y < h; y++) out.set(raw.subarray((h - 1 - y) * w * 4, (h - y) * w * 4), y * w * 4);
    return out;
  };

  // ------------------------------------------------------------------ controls

  Figure.prototype.changed = function () {
    this.applyControls();
    this.render();
    if (this.curve) this.drawCurve();
  };

  // The panels' labels in a row under the canvas, one per panel and as wide as it (the
  // canvas scales to the column, the row with it); none when no panel has a label.
  Figure.prototype.labelPanels = function () {
    var panels = this.spec.panels;
    if (!panels.some(function (p) { return p.label; })) return;
    var row = el('div', { 'class': 'lightlab-panel-labels' });
    row.style.width = this.canvas.width + 'px';
    panels.forEach(function (p) { row.appendChild(el('span', {}, T(p.label))); });
    this.canvas.parentNode.insertBefore(row, this.canvas.nextSibling);
  };

  Figure.prototype.buildControls = function () {
    this.labelPanels();
    var box = this.root.querySelector('.lightlab-controls');
    if (!box) return;
    var self = this;
    this.spec.controls.forEach(function (c, i) {
      var id = 'lightlab-' + self.spec.id + '-' + i + '-' + (uid++);
      var row = el('div', { 'class': 'lightlab-control' });
      if (c.kind === 'range') {
        row.appendChild(el('label', { 'for': id }, T(c.label) + ' '));
        var input = el('input', { type: 'range', id: id, min: 0, max: c.options.length - 1, step: 1, value: self.choice[i] });
        var out = el('output', { 'for': id }, T(c.options[self.choice[i]].label));
        input.setAttribute('aria-valuetext', T(c.options[self.choice[i]].label));
        input.addEventListener('input', function () {
          self.choice[i] = Number(input.value);
          out.textContent = T(c.options[self.choice[i]].label);
          input.setAttribute('aria-valuetext', out.textContent);
          self.changed();
        });
        row.appendChild(input);
        row.appendChild(out);
        if (c.play) row.appendChild(self.playButton(i, input));
        self.sync = self.sync || [];
        self.sync[i] = function () { input.value = self.choice[i]; out.textContent = T(c.options[self.choice[i]].label); };
      } else if (c.kind === 'select') {
        var sel = el('select', { id: id });
        c.options.forEach(function (o, k) {
          var opt = el('option', { value: k }, T(o.label));
          if (k === self.choice[i]) opt.selected = true;
          sel.appendChild(opt);
        });
        sel.addEventListener('change', function () { self.choice[i] = Number(sel.value); self.changed(); });
        row.appendChild(el('label', { 'for': id }, T(c.label) + ' '));
        row.appendChild(sel);
      } else if (c.kind === 'toggle') {
        var box2 = el('input', { type: 'checkbox', id: id });
        box2.checked = self.choice[i] === 0;
        box2.addEventListener('change', function () { self.choice[i] = box2.checked ? 0 : 1; self.changed(); });
        row.appendChild(box2);
        row.appendChild(el('label', { 'for': id }, ' ' + T(c.label)));
      } else if (c.kind === 'color') {
        var v = self.state[c.key];
        var hex = '#' + v.map(function (x) {
          var b = Math.max(0, Math.min(255, Math.round(x * 255)));
          return (b < 16 ? '0' : '') + b.toString(16);
        }).join('');
        var picker = el('input', { type: 'color', id: id, value: hex });
        var shown = el('output', { 'for': id }, numberList(v, 2));
        picker.addEventListener('input', function () {
          var h = picker.value;
          var rgb = [1, 3, 5].map(function (k) { return parseInt(h.substr(k, 2), 16) / 255; });
          self.colors[c.key] = rgb;
          shown.textContent = numberList(rgb, 2);
          self.changed();
        });
        row.appendChild(el('label', { 'for': id }, T(c.label) + ' '));
        row.appendChild(picker);
        row.appendChild(shown);
      } else if (c.kind === 'orbit') {
        var label = el('output', {}, TF('{}: {}', [T(c.label), T(c.options[self.choice[i]].label)]));
        row.appendChild(label);
        self.orbit(i, c, label);
      } else if (c.kind === 'grid') {
        row.appendChild(self.grid(i, c, id));
      }
      box.appendChild(row);
      if (c.curves) {
        self.curve = { control: i, canvas: el('canvas', { width: 320, height: 120, 'class': 'lightlab-curve', role: 'img', 'aria-label': TF('{} curve', [T(c.label)]) }) };
        box.appendChild(self.curve.canvas);
        self.drawCurve();
      }
    });
    if (this.spec.editor) this.buildEditor(box);
  };

  Figure.prototype.playButton = function (i, input) {
    var self = this, c = this.spec.controls[i];
    var button = el('button', { type: 'button' }, reducedMotion ? T('step') : T('play'));
    button.addEventListener('click', function () {
      if (reducedMotion) { // one step per press: no motion the reader did not ask for
        self.choice[i] = (self.choice[i] + 1) % c.options.length;
        input.value = self.choice[i];
        input.dispatchEvent(new Event('input'));
        return;
      }
      if (self.playing !== null) { self.playing = null; button.textContent = T('play'); return; }
      self.playing = i;
      button.textContent = T('pause');
      var last = 0;
      var tick = function (t) {
        if (self.playing !== i) return;
        if (self.visible && t - last > 80) {
          last = t;
          self.choice[i] = (self.choice[i] + 1) % c.options.length;
          input.value = self.choice[i];
          input.dispatchEvent(new Event('input'));
        }
        window.requestAnimationFrame(tick);
      };
      window.requestAnimationFrame(tick);
    });
    return button;
  };

  Figure.prototype.orbit = function (i, c, label) {
    var self = this, canvas = this.canvas, start = null;
    var move = function (dc, dr) {
      var k = self.choice[i], col = k % c.cols, row = Math.floor(k / c.cols);
      col = (col + dc + c.cols) % c.cols;
      row = Math.max(0, Math.min(c.rows - 1, row + dr));
      self.choice[i] = row * c.cols + col;
      label.textContent = TF('{}: {}', [T(c.label), T(c.options[self.choice[i]].label)]);
      self.changed();
    };
    canvas.style.cursor = 'grab';
    canvas.addEventListener('pointerdown', function (e) { start = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
    canvas.addEventListener('pointerup', function () { start = null; });
    canvas.addEventListener('pointermove', function (e) {
      if (!start) return;
      var dx = Math.trunc((e.clientX - start[0]) / 12), dy = Math.trunc((e.clientY - start[1]) / 24);
      if (dx || dy) { move(-dx, dy); start = [e.clientX, e.clientY]; }
    });
    canvas.addEventListener('keydown', function (e) {
      var d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] }[e.key];
      if (d) { move(d[0], d[1]); e.preventDefault(); }
    });
  };

  // A grid of sliders (the crate's Kind::Grid): one slider per axis. The crate numbers the
  // options and gives each axis its stride: option = sum(position * stride), and
  // position = floor(option / stride) mod (the axis's ticks).
  function gridPositions(c, option) {
    return c.axes.map(function (a, k) { return Math.floor(option / c.strides[k]) % a.ticks.length; });
  }
  function gridOption(c, positions) {
    return positions.reduce(function (sum, p, k) { return sum + p * c.strides[k]; }, 0);
  }

  Figure.prototype.grid = function (i, c, id) {
    var self = this;
    var box = el('fieldset', { 'class': 'lightlab-grid' });
    box.appendChild(el('legend', {}, T(c.label)));
    c.axes.forEach(function (a, k) {
      var aid = id + '-' + k, at = gridPositions(c, self.choice[i])[k];
      var line = el('div', { 'class': 'lightlab-grid-axis' });
      var input = el('input', { type: 'range', id: aid, min: 0, max: a.ticks.length - 1, step: 1, value: at });
      var out = el('output', { 'for': aid }, T(a.ticks[at].label));
      input.setAttribute('aria-valuetext', out.textContent);
      input.addEventListener('input', function () {
        var positions = gridPositions(c, self.choice[i]);
        positions[k] = Number(input.value);
        self.choice[i] = gridOption(c, positions);
        out.textContent = T(a.ticks[positions[k]].label);
        input.setAttribute('aria-valuetext', out.textContent);
        self.changed();
      });
      line.appendChild(el('label', { 'for': aid }, T(a.label) + ' '));
      line.appendChild(input);
      line.appendChild(out);
      box.appendChild(line);
    });
    return box;
  };

  // The curve of the chosen option, in a plot box below a strip that holds the y axis's
  // name: the curve starts at the box's top (attenuation 1 at distance 0), so no text may
  // sit inside the box. The axis names are the crate's (curve_axes), in the page language.
  Figure.prototype.drawCurve = function () {
    var cv = this.curve.canvas, ctx = cv.getContext('2d'), c = this.spec.controls[this.curve.control];
    var axes = this.spec.curve_axes || { x: 'x', y: 'y', max: 1 };
    var pts = c.curves[this.choice[this.curve.control]];
    var number = words.number || String;
    var W = cv.width, H = cv.height;
    var left = 24, top = 18, right = W - 6, bottom = H - 22;
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, W, H);
    ctx.strokeStyle = '#888';
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(left, top); ctx.lineTo(left, bottom); ctx.lineTo(right, bottom);
    ctx.moveTo(left - 4, top); ctx.lineTo(left, top);
    ctx.stroke();
    ctx.fillStyle = '#333';
    ctx.font = '11px sans-serif';
    ctx.textBaseline = 'alphabetic';
    ctx.textAlign = 'left';
    ctx.fillText(T(axes.y), 2, 12);
    ctx.textAlign = 'right';
    ctx.fillText('1', left - 6, top + 4);
    ctx.fillText(T(axes.x) + ' ' + number(axes.max), right, H - 5);
    ctx.textAlign = 'left';
    ctx.fillText('0', left - 3, H - 5);
    ctx.strokeStyle = '#c33';
    ctx.lineWidth = 2;
    ctx.beginPath();
    pts.forEach(function (p, k) {
      var x = left + (right - left) * p[0] / axes.max, y = bottom - (bottom - top) * p[1];
      if (k === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
    });
    ctx.stroke();
  };

  Figure.prototype.buildEditor = function (box) {
    var self = this, name = this.spec.editor, p = this.spec.programs[name];
    var original = p.fragment.substring(p.header.length, p.fragment.length - p.main.length);
    var headerLines = p.header.split('\n').length - 1;
    var wrap = el('details', { 'class': 'lightlab-editor' });
    wrap.appendChild(el('summary', {}, TF('Edit the fragment shader ({}.glsl, the text lightlab oracle verifies)', [p.model])));
    var area = el('div', { 'class': 'lightlab-editor-area' });
    var gutter = el('pre', { 'class': 'lightlab-gutter', 'aria-hidden': 'true' });
    var text = el('textarea', { spellcheck: 'false', rows: 18, 'aria-label': T('fragment shader source') });
    text.value = original;
    var msg = el('pre', { 'class': 'lightlab-editor-msg', role: 'status' });
    var numbers = function () {
      var n = text.value.split('\n').length, s = '';
      for (var k = 1; k <= n; k++) s += k + '\n';
      gutter.textContent = s;
    };
    text.addEventListener('scroll', function () { gutter.scrollTop = text.scrollTop; });
    var apply = function () {
      numbers();
      var r = self.compileEdited(text.value);
      msg.textContent = r.text;
      msg.className = r.ok ? 'lightlab-editor-msg lightlab-editor-ok' : 'lightlab-editor-msg';
    };
    var timer = null;
    text.addEventListener('input', function () { clearTimeout(timer); timer = setTimeout(apply, 400); numbers(); });
    var reset = el('button', { type: 'button', 'aria-label': T('Reset the figure\'s shader to the verified one') }, T('Reset'));
    reset.addEventListener('click', function () { text.value = original; apply(); });
    area.appendChild(gutter);
    area.appendChild(text);
    wrap.appendChild(area);
    wrap.appendChild(reset);
    wrap.appendChild(msg);
    box.appendChild(wrap);
    numbers();
    this.headerLines = headerLines;
  };

  // Compile the reader's function text between the program's header and main, under the
  // page's guard (lightlab-gl.js: a macro bomb refused, every loop capped), and draw it
  // timed: a draw over the crate's limit (guard.live_draw_ms) puts the verified shader back.
  // Errors come at the reader's line numbers. Returns {ok, text}: the message under the editor.
  Figure.prototype.compileEdited = function (source) {
    var name = this.spec.editor, p = this.spec.programs[name], guard = this.spec.guard;
    if (this.lost || this.gl.isContextLost()) return { ok: false, text: T('the figure has no GPU context now; your shader compiles when the browser gives it back') };
    var refusal = G.macroRefusal(source, guard);
    if (refusal) return { ok: false, text: G.macroMessage(refusal) };
    var header = p.header + G.loopHeader(guard); // one more line: the reader's lines shift by one
    var r = link(this.gl, p.vertex, header + G.guardLoops(source).text + p.main);
    if (r.error) {
      var headerLines = header.split('\n').length - 1;
      var readerLines = source.split('\n').length;
      return { ok: false, text: String(r.error).replace(/\u0000/g, '').replace(/(ERROR|WARNING): (\d+):(\d+):/g, function (all, kind, file, line) {
        var n = Number(line) - headerLines;
        return n >= 1 && n <= readerLines ? TF('{}: line {}:', [kind, n]) : TF('{}: (in the figure\'s main, after your text):', [kind]);
      }).trim() };
    }
    var verified = this.programs[name];
    this.programs[name] = r;
    this.edited = source;
    var t0 = performance.now();
    this.changed();
    var ms = G.waitForGpu(this.gl, false, t0);
    if (this.gl.isContextLost()) return { ok: false, text: T('the browser took the GPU context away while your shader drew (an endless loop?)') };
    if (ms > guard.live_draw_ms) {
      this.programs[name] = verified;
      this.edited = null;
      this.changed();
      return { ok: false, text: TF('your shader took {} ms to draw the figure (the limit is {} ms): an endless or very long loop? The figure went back to the verified shader.', [ms.toFixed(0), guard.live_draw_ms]) };
    }
    var done = T('compiled: the figure now runs your shader');
    return { ok: true, text: r.floated.length ? done + '\n' + G.floatedNote(r.floated) : done };
  };

  // ?figure-mutant=ID: the figure's editable program becomes the crate's mutant ID (looked
  // up as an own property of the emitted map; a figure without it is left alone).
  Figure.prototype.useMutant = function (id) {
    var mutants = this.spec.mutants || {};
    if (!this.spec.editor || !Object.prototype.hasOwnProperty.call(mutants, id)) return;
    var r = this.compileEdited(mutants[id]);
    if (!r.ok) throw new Error(this.spec.id + ': mutant ' + id + ' does not compile: ' + r.text);
    this.mutant = id;
  };

  // ------------------------------------------------------------------ self-check

  function decodePng(b64) {
    return new Promise(function (resolve, reject) {
      var img = new Image();
      img.onload = function () {
        var c = document.createElement('canvas');
        c.width = img.width;
        c.height = img.height;
        var ctx = c.getContext('2d', { willReadFrequently: true });
        ctx.drawImage(img, 0, 0);
        resolve(ctx.getImageData(0, 0, img.width, img.height).data);
      };
      img.onerror = function () { reject(new Error('reference PNG does not decode')); };
      img.src = 'data:image/png;base64,' + b64;
    });
  }

  // The largest channel difference of pixel i (byte offset) between two RGBA arrays.
  function channelDiff(got, ref, i) {
    return Math.max(Math.abs(got[i] - ref[i]), Math.abs(got[i + 1] - ref[i + 1]), Math.abs(got[i + 2] - ref[i + 2]));
  }

  // Compare the page's pixels with point pt's reference (ref: its decoded RGBA) under the
  // point's tolerance {level, cap, share}, all emitted by the crate: no compared pixel more
  // than cap off, and at most share of the object's compared pixels (pt.covered, counted
  // by the crate) more than level off.
  function comparePoint(got, ref, pt, tol) {
    var max = 0, sum = 0, n = 0, over = 0, overCap = 0;
    for (var i = 0; i < got.length; i += 4) {
      if (ref[i + 3] !== 255) continue;
      var d = channelDiff(got, ref, i);
      if (d > max) max = d;
      if (d > tol.level) over++;
      if (d > tol.cap) overCap++;
      sum += d;
      n++;
    }
    var allowed = Math.floor(tol.share * pt.covered);
    var pass = n > 0 && overCap === 0 && over <= allowed;
    return { name: pt.name, tolerance: tol, pass: pass, max_diff_255: max, mean_diff_255: n ? sum / n : 0, pixels_over: over,
      pixels_over_cap: overCap, allowed_over: allowed, compared: n, covered: pt.covered };
  }

  Figure.prototype.selftest = function () {
    var self = this, spec = this.spec;
    if (this.lost || this.gl.isContextLost()) {
      return Promise.resolve({ id: spec.id, pass: false, lost: true, message: this.message ? this.message.textContent : null });
    }
    var result = { id: spec.id, pass: true, max_diff_255: 0, mean_diff_255: 0, pixels_over: 0, pixels_over_cap: 0,
      tolerance: spec.tolerance, mutant: this.mutant || null, points: [] };
    var total = 0, count = 0;
    var chain = Promise.resolve();
    spec.points.forEach(function (pt) {
      chain = chain.then(function () { return decodePng(pt.png); }).then(function (ref) {
        self.render(pt.state);
        var got = self.pixels();
        var r = comparePoint(got, ref, pt, pt.tolerance);
        if (query.has('dump')) {
          var worst = [];
          for (var j = 0; j < got.length && worst.length < 12; j += 4) {
            if (ref[j + 3] === 255 && channelDiff(got, ref, j) > pt.tolerance.level) worst.push([(j / 4) % self.canvas.width, Math.floor(j / 4 / self.canvas.width), Array.from(got.slice(j, j + 3)), Array.from(ref.slice(j, j + 3))]);
          }
          errors.push('dump ' + spec.id + ' ' + pt.name + ' ' + JSON.stringify(worst) + ' ' + self.canvas.toDataURL());
        }
        result.points.push(r);
        result.pass = result.pass && r.pass;
        result.max_diff_255 = Math.max(result.max_diff_255, r.max_diff_255);
        result.pixels_over += r.pixels_over;
        result.pixels_over_cap += r.pixels_over_cap;
        total += r.mean_diff_255 * r.compared;
        count += r.compared;
      });
    });
    return chain.then(function () {
      result.mean_diff_255 = count ? total / count : 0;
      self.render();
      return result;
    });
  };

  // ?fps=N: N whole frames, 1 to MAX_FPS_FRAMES (a huge or infinite N would freeze the tab);
  // anything else (missing, not a number, below 1) is the default 30.
  var MAX_FPS_FRAMES = 1000;
  function fpsFrames(param) {
    var n = Math.floor(Number(param));
    return isFinite(n) && n >= 1 ? Math.min(n, MAX_FPS_FRAMES) : 30;
  }

  Figure.prototype.fps = function () {
    var gl = this.gl, px = new Uint8Array(4), frames = fpsFrames(query.get('fps'));
    this.render();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    var t0 = performance.now();
    for (var k = 0; k < frames; k++) {
      this.render();
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px); // waits for the frame
    }
    var ms = (performance.now() - t0) / frames;
    return { id: this.spec.id, width: this.canvas.width, height: this.canvas.height, ms_per_frame: ms, fps: 1000 / ms };
  };

  // ------------------------------------------------------------------ start

  function output(id, value) {
    var pre = document.getElementById(id);
    if (!pre) {
      pre = el('pre', { id: id });
      (document.querySelector('main') || document.body).appendChild(pre);
    }
    pre.textContent = JSON.stringify(value);
  }

  function start() {
    var figures = [];
    var specs = window.LIGHTLAB_FIGURES || {};
    // no prototype: a parameter such as ?set=__proto__.0=1 or constructor.0=1 is one more
    // unknown figure id, never Object.prototype's own properties
    var sets = Object.create(null);
    (query.get('set') || '').split(',').forEach(function (s) {
      var m = /^([\w-]+)\.(\d+)=(\d+)$/.exec(s);
      if (m) (sets[m[1]] = sets[m[1]] || []).push([Number(m[2]), Number(m[3])]);
    });
    var seen = Object.create(null);
    document.querySelectorAll('figure.lightlab-figure').forEach(function (root) {
      var id = root.getAttribute('data-live');
      if (seen[id]) return; // the print page repeats chapters
      seen[id] = true;
      try {
        if (!Object.prototype.hasOwnProperty.call(specs, id)) throw new Error(id + ': figure data not loaded');
        var f = new Figure(root, specs[id]);
        (sets[id] || []).forEach(function (s) {
          if (f.spec.controls[s[0]] && (s[1] < f.spec.controls[s[0]].options.length || f.spec.controls[s[0]].kind === 'toggle')) f.choice[s[0]] = s[1];
        });
        f.applyControls();
        if (query.has('figure-mutant')) f.useMutant(query.get('figure-mutant'));
        f.buildControls();
        f.render();
        figures.push(f);
        if ('IntersectionObserver' in window) {
          new IntersectionObserver(function (entries) {
            entries.forEach(function (e) { f.visible = e.isIntersecting; });
          }).observe(root);
        }
      } catch (e) {
        errors.push(String(e && e.message || e));
        var status = root.querySelector('.lightlab-status');
        if (status) status.textContent = TF('(not running here: {})', [String(e && e.message || e)]);
      }
    });
    var lose = query.get('lose-context');
    var chosen = figures.filter(function (f, k) { return lose === f.spec.id || (lose === '1' && k === 0); })[0];
    var lost = Promise.resolve();
    if (chosen) {
      var ext = chosen.gl.getExtension('WEBGL_lose_context');
      if (ext) {
        lost = new Promise(function (resolve) { chosen.canvas.addEventListener('webglcontextlost', function () { setTimeout(resolve, 0); }); });
        ext.loseContext();
        if (query.has('restore-context')) {
          lost = lost.then(function () {
            return new Promise(function (resolve) {
              chosen.canvas.addEventListener('webglcontextrestored', function () { setTimeout(resolve, 0); });
              ext.restoreContext();
            });
          });
        }
      } else errors.push('?lose-context: no WEBGL_lose_context here');
    }
    if (query.has('shot')) {
      output('lightlab-shots', figures.map(function (f) { f.render(); return { id: f.spec.id, png: f.canvas.toDataURL('image/png') }; }));
    }
    if (query.has('fps')) {
      output('lightlab-fps', { fps: figures.map(function (f) { return f.fps(); }), errors: errors });
    }
    if (query.has('selftest')) {
      var results = [];
      var chain = lost;
      var figuresOnly = query.get('selftest') === 'figures';
      figures.forEach(function (f) {
        chain = chain.then(function () { return f.selftest(); }).then(function (r) { results.push(r); }, function (e) {
          errors.push(f.spec.id + ': ' + String(e && e.message || e));
          results.push({ id: f.spec.id, pass: false, max_diff_255: 255, mean_diff_255: 255, pixels_over: -1 });
        });
      });
      // The exercises' checker (lightlab-exercise.js) reports under "exercises".
      var exercises = [];
      chain.then(function () {
        var x = window.LIGHTLAB_EXERCISES;
        return x && !figuresOnly && x.selftest().then(function (r) {
          exercises = r.results;
          r.errors.forEach(function (e) { errors.push(e); });
        });
      }).then(function () { output('lightlab-selftest', { figures: results, exercises: exercises, errors: errors }); });
    }
  }

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})();
