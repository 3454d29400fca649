// lightlab exercises answered with a number or a choice: the box, the check against the
// crate's answer and the ?selftest of the right and wrong answers. lightlab-exercise.js builds
// one LightlabAnswerExercise per such box (its data has `kind` "number" or "choice"); a check
// the reader asks for is reported to the hooks of window.LIGHTLAB_EXERCISE_HOOKS, as the
// shader exercises' checks are. No GPU is needed.
(function () {
  'use strict';

  var text = window.lightlabText || { T: function (s) { return s; }, TF: function (s) { return s; } };
  var T = text.T, TF = text.TF;
  var hooks = window.LIGHTLAB_EXERCISE_HOOKS = window.LIGHTLAB_EXERCISE_HOOKS || [];
  function notify(name, x, r) {
    hooks.forEach(function (h) {
      try { if (h[name]) h[name](x, r); } catch (e) { /* a helper's failure never stops the checker */ }
    });
  }

  function el(tag, attrs, content) {
    var e = document.createElement(tag);
    for (var k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (content !== undefined) e.textContent = content;
    return e;
  }

  // The crate's texts mark code as Markdown does, `theta = dot(...)`: each span becomes a
  // <code> element and the rest text nodes, built node by node (never innerHTML), so the
  // reader sees code, not backticks. An unpaired backtick stays as it is.
  function withCode(parent, text) {
    var parts = String(text).split('`');
    if (parts.length % 2 === 0) { parent.appendChild(document.createTextNode(String(text))); return parent; }
    parts.forEach(function (part, k) {
      if (k % 2) parent.appendChild(el('code', {}, part));
      else if (part) parent.appendChild(document.createTextNode(part));
    });
    return parent;
  }

  // A number or a choice (data.kind), checked against the crate's answer. Every text is
  // the command line's, exported by src/live/exercises.rs: this file only compares the
  // reader's number with the answer and its tolerance, and puts the number where the
  // texts hold `data.given`.
  function answerVerdict(data, value) {
    if (data.kind === 'choice') {
      var c = data.choices[value];
      if (!c) return { verdict: 'error', error: T('choose one of the answers first'), diagnosis: [] };
      return { verdict: c.agrees ? 'agrees' : 'disagrees', text: T(c.text), diagnosis: c.diagnosis };
    }
    var token = String(value === undefined || value === null ? '' : value).trim().split(/\s+/)[0];
    // a decimal comma (45,28) reads as the command line reads it (exercises::parse_answer_number)
    var given = Number(/^[+-]?\d*,\d+([eE][+-]?\d+)?$/.test(token) ? token.replace(',', '.') : token);
    if (token === '' || !isFinite(given)) {
      return { verdict: 'error', error: TF('`{}` is not a number: write one number', [token]), diagnosis: [] };
    }
    var shown = String(given);
    var fill = function (t) { return T(t).split(data.given).join(shown); };
    if (Math.abs(given - data.answer) <= data.tolerance) return { verdict: 'agrees', text: fill(data.right), diagnosis: [] };
    var f = given > data.answer ? data.too_high : data.too_low;
    return { verdict: 'disagrees', text: T(f.text), diagnosis: [{ id: f.id, title: f.title, evidence: fill(f.evidence) }] };
  }

  function showAnswer(box, r) {
    var out = box.querySelector('.lightlab-exercise-result');
    out.textContent = '';
    out.className = 'lightlab-exercise-result lightlab-' + r.verdict;
    if (r.verdict === 'error') {
      out.appendChild(el('p', {}, r.error));
      return;
    }
    out.appendChild(withCode(el('p', {}), r.text));
    r.diagnosis.forEach(function (f) {
      var p = el('p', { 'data-mistake': f.id });
      p.appendChild(withCode(el('small', {}), T(f.evidence)));
      out.appendChild(p);
    });
  }

  function AnswerExercise(box, data) {
    this.box = box;
    this.data = data;
    var self = this;
    var status = box.querySelector('.lightlab-status');
    if (status) status.remove();
    box.appendChild(withCode(el('p', { 'class': 'lightlab-exercise-statement' }), T(data.statement)));
    var form = el('div', { 'class': 'lightlab-exercise-answer' });
    this.inputs = [];
    if (data.kind === 'choice') {
      data.choices.forEach(function (c, k) {
        var label = el('label', {});
        var input = el('input', { type: 'radio', name: 'lightlab-answer-' + data.id, value: String(k) });
        label.appendChild(input);
        withCode(label, ' (' + c.letter + ') ' + T(c.choice));
        form.appendChild(label);
        form.appendChild(el('br', {}));
        self.inputs.push(input);
      });
    } else {
      var input = el('input', { type: 'text', inputmode: 'decimal', size: '12', 'aria-label': T('your answer') });
      form.appendChild(input);
      if (data.unit) form.appendChild(document.createTextNode(' ' + data.unit));
      self.inputs.push(input);
    }
    var buttons = el('div', { 'class': 'lightlab-exercise-buttons' });
    var checkButton = el('button', { type: 'button', 'aria-label': TF('Check your answer for {}', [T(data.title)]) }, T('Check'));
    checkButton.addEventListener('click', function () { notify('checked', self, self.check()); });
    buttons.appendChild(checkButton);
    box.appendChild(form);
    box.appendChild(buttons);
    box.appendChild(el('div', { 'class': 'lightlab-exercise-result', role: 'status' }));
  }

  AnswerExercise.prototype.value = function () {
    if (this.data.kind !== 'choice') return this.inputs[0].value;
    for (var k = 0; k < this.inputs.length; k++) if (this.inputs[k].checked) return k;
    return -1;
  };

  AnswerExercise.prototype.check = function (value) {
    var r = answerVerdict(this.data, value === undefined ? this.value() : value);
    showAnswer(this.box, r);
    return r;
  };

  // ?selftest: the crate's answer must agree, and wrong answers (every wrong choice; a
  // number beyond the tolerance on each side; a word) must be named as the command line
  // names them.
  AnswerExercise.prototype.selftest = function () {
    var data = this.data;
    var tries = [];
    if (data.kind === 'choice') {
      var right = data.choices.map(function (c) { return c.agrees; }).indexOf(true);
      tries.push({ value: right, expect: null });
      data.choices.forEach(function (c, k) { if (k !== right) tries.push({ value: k, expect: 'wrong-choice' }); });
    } else {
      var off = 2 * data.tolerance + 1;
      tries.push({ value: String(data.answer), expect: null });
      tries.push({ value: String(data.answer + off), expect: data.too_high.id });
      tries.push({ value: String(data.answer - off), expect: data.too_low.id });
      tries.push({ value: 'not-a-number', expect: 'error' });
    }
    var self = this;
    var first = self.check(tries[0].value);
    var entry = { id: data.id, reference: first.verdict, pass: first.verdict === 'agrees', mutants: [] };
    tries.slice(1).forEach(function (t) {
      var r = self.check(t.value);
      var ids = r.diagnosis.map(function (f) { return f.id; });
      var ok = t.expect === 'error' ? r.verdict === 'error' : r.verdict === 'disagrees' && ids[0] === t.expect;
      entry.mutants.push({ id: t.expect, verdict: r.verdict, diagnosis: ids, pass: ok });
      entry.pass = entry.pass && ok;
    });
    self.check(tries[0].value);
    return entry;
  };

  window.LightlabAnswerExercise = AnswerExercise;
})();
