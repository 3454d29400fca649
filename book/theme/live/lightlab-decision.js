// lightlab exercises: the decision rule of the in-page checker (lightlab-exercise.js), the
// one of src/checker/diagnose.rs: two runs compared case by case, a mutant matching the reader,
// and, when no mistake of the catalogue matches, the isolation of the difference. The
// sentences and the switches come from the crate's exercise data.
//
// Classic script (no ES modules, no fetch): the book must work when opened from disk.
(function () {
  'use strict';

  var words = window.lightlabText || { T: function (s) { return s; }, TF: function (s) { return s; } };
  var T = words.T, TF = words.TF;
  var G = window.LightlabGL;

  // src/checker/outputs.rs differ: |x - y| > tolerance * max(1, |x|, |y|), the tolerance taken
  // at the values' magnitude (rounding is relative).
  function differ(x, y, tolerance) {
    return Math.abs(x - y) > tolerance * Math.max(1, Math.abs(x), Math.abs(y));
  }

  // src/checker/outputs.rs compare_outputs: rgb per defined case within `tolerance` (differ); two
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
            if (differ(x, y, tolerance)) bad = true;
          } else if (fx !== fy) {
            bad = true;
          }
        }
        if (bad) r.mismatches++;
      });
    });
    return r;
  }
  function matches(data, agreement) {
    return agreement.defined > 0 && agreement.mismatches <= data.mistake_share * agreement.defined;
  }
  function exp1(x) { return (words.number || String)(x.toExponential(1).replace('e+', 'e')); }

  // The verdict's rule on one case (src/checker/diagnose.rs case_fails): a channel more than
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


  // isolation
  // src/checker/diagnose.rs isolate: when no mistake of the catalogue matches, switch terms and
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

  // Defined cases as {g, i, bad}: bad when a and b differ by more than the tolerance (differ).
  function verdicts(data, a, b) {
    var out = [];
    data.cases.groups.forEach(function (g, gi) {
      g.rows.forEach(function (row, i) {
        if (!g.defined[i]) return;
        var bad = false;
        for (var c = 0; c < 3; c++) {
          var x = a[gi][i][c], y = b[gi][i][c];
          if (isFinite(x) && isFinite(y)) { if (differ(x, y, data.match_tolerance)) bad = true; }
          else if (isFinite(x) !== isFinite(y)) bad = true;
        }
        out.push({ g: gi, i: i, bad: bad });
      });
    });
    return out;
  }

  // A promise of the isolation finding (one turn of the event loop per switch).
  function isolate(data, p, source, fixed, learner, reference, runner) {
    var run = runner.run, userName = runner.userName, f64 = runner.rule === 'f64';
    // under the f64 rule, each run against the crate's values (for a switch: the switched cases')
    var cases = f64 ? againstExpected(data, learner.outputs, data.verdict.expected)
      : verdicts(data, learner.outputs, reference.outputs);
    var failing = cases.filter(function (c) { return c.bad; });
    var evidence = shown(data, 'evidence', [failing.length, cases.length]);
    var located = [], switchable = [], locatedSwitches = [], unswitched = [];
    var chain = Promise.resolve();
    data.switches.forEach(function (sw) {
      var declared = sw.quantities.every(function (q) {
        var user = userName(data.names, q);
        return p.ins.indexOf(user) >= 0 || p.uniforms[user] !== undefined;
      });
      if (!declared) { unswitched.push(sw.name); return; } // its strength is a number in the shader
      chain = chain.then(G.yieldTurn).then(function () {
        var off = {};
        Object.keys(fixed).forEach(function (k) { off[k] = fixed[k]; });
        sw.quantities.forEach(function (q) { off[q] = [0, 0, 0, 0]; });
        var a = run(data, source, off, sw.uniforms, data.names, true);
        var b = f64 ? null : run(data, data.reference, off, sw.uniforms);
        if (a.error || (b && b.error)) return;
        var still = (b ? verdicts(data, a.outputs, b.outputs) : againstExpected(data, a.outputs, data.verdict.switches[sw.name]))
          .filter(function (c) { return c.bad; }).length;
        evidence += shown(data, 'evidence_off', [sw.name, still]);
        if (still === 0) { located.push(sw.name); locatedSwitches.push(sw); }
        switchable.push(sw.name);
      });
    });
    return chain.then(function () { return isolated(data, cases, failing, locatedSwitches, switchable, evidence, unswitched); });
  }

  // The isolation finding from the switches' results.
  function isolated(data, cases, failing, locatedSwitches, switchable, evidence, unswitched) {
    var located = locatedSwitches.map(function (sw) { return sw.name; });
    var none = switchable.length ? 'several_terms' : 'none';
    var sentence = located.length === 0 ? fill(data, none, [switchable.join(', ')])
      : located.length === 1 ? fill(data, 'one', [located[0]]) : fill(data, 'several', [located.join(', ')]);
    var sentenceShown = located.length === 0 ? shown(data, none, [joinShown(switchable, T(', '))])
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
    // src/checker/isolation.rs isolate: the hints of the first located switch (its name in the
    // blank), else those of the conditions, else those for terms the shader cannot switch
    // off (their names), else those for a difference found nowhere
    var first = locatedSwitches[0];
    var cannot = !first && !conditions.length && unswitched.length > 0;
    var templates = first ? first.hints : conditions.length ? data.isolation.hints_when
      : cannot ? data.isolation.hints_unswitched : data.isolation.hints_nowhere;
    var what = first ? T(first.name) : cannot ? joinShown(unswitched, T(" and ")) : joinShown(conditions, T(' and '));
    var hints = (templates || []).map(function (h) { return TF(h, [what]); });
    // title: the command line's English (the self-test compares it); shown: the reader's
    return { id: 'isolated', title: sentence, shown: sentenceShown, evidence: evidence, link: '', why: '', hints: hints };
  }

  // A catalogue mistake m that reproduces the reader's output, as the page shows it: the
  // agreement with the reader (vsLearner) and how far m is from the reference (vsReference).
  // A mutant in one site (src/checker/sites.rs) carries the site, its phrase and the command
  // line's English title (title_en); the reader sees both parts translated.
  // A candidate outside the catalogue (a variant's change left out, src/exercises/change.rs)
  // carries its title's and hints' arguments: the title and hints are filled here, in the
  // reader's language; the third hint lists the edits.
  function finding(m, vsLearner, vsReference) {
    var same = m.equivalent.length ? TF('; gives the same output as {} ({})', [m.equivalent.join(', '), T(m.equivalence_reason)]) : '';
    var evidence = TF('this mistake reproduces your output on {} of {} defined cases (largest difference {}); cases where the correct shader differs from it: {}',
      [vsLearner.defined - vsLearner.mismatches, vsLearner.defined, exp1(vsLearner.max_diff), vsReference.mismatches]) + same;
    var shownTitle = m.title_args ? TF(m.title, m.title_args.map(function (a) { return T(a); }))
      : m.site ? T(m.title) + T(', ') + T(m.site_phrase) : T(m.title);
    var hints = m.hints || [];
    if (m.hint_args) {
      var edits = (m.edits || []).map(function (e) { return TF(m.text, e); }).join('; ');
      hints = hints.map(function (h, k) { return TF(h, k < m.hint_args.length ? m.hint_args[k].map(function (a) { return T(a); }) : [edits]); });
    }
    return { id: m.id, site: m.site || null, title: m.title_en || m.title, shown: shownTitle, evidence: evidence,
      link: m.link, why: m.why, hints: hints };
  }

  // src/checker/diagnose.rs squashed: the text without comments and white space.
  function squashed(source) {
    return String(source).replace(/\/\*[\s\S]*?(\*\/|$)/g, ' ').replace(/\/\/[^\n]*/g, ' ').replace(/\s+/g, '');
  }
  // src/checker/diagnose.rs score_of: +1 for each step whose edit the text shows, -1 for each
  // whose base line it keeps instead (signs exported by the crate, already squashed).
  function textScore(signs, text) {
    var occurs = function (texts) { return texts.some(function (t) { return text.indexOf(t) >= 0; }); };
    return signs.reduce(function (sum, s) { return sum + (occurs(s.edit) ? 1 : occurs(s.base) ? -1 : 0); }, 0);
  }

  // The uniform names `source` declares at the top level (`uniform vec3 viewPos;`,
  // `uniform Light light;`), in use or not, as the command line's scanner reads them.
  function declaredUniforms(source) {
    var clean = source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/[^\n]*/g, '');
    var re = /^[ \t]*(?:layout\s*\([^)]*\)\s*)?uniform\s+(?:(?:highp|mediump|lowp)\s+)?\w+\s+(\w+)/gm, m, out = [];
    while ((m = re.exec(clean))) out.push(m[1]);
    return out;
  }

  // The first of the exercise's own rules (data.rules, the crate's `[rules]`, src/checker/check/
  // mapping.rs broken_rule) that the reader's program p breaks: a quantity it forbids
  // declared, or one it requires missing, as the command line's sentence; null when none.
  function brokenRule(data, p, source, userName) {
    var rules = data.rules;
    if (!rules) return null;
    var names = data.quantities.map(function (q) { return q.name; });
    data.cases.groups.forEach(function (g) { names = names.concat(Object.keys(g.uniforms)); });
    var uniforms = declaredUniforms(source);
    var declaredName = function (user) {
      return p.ins.indexOf(user) >= 0 || p.uniforms[user] !== undefined || uniforms.some(function (u) {
        return user === u || user.indexOf(u + '.') === 0 || user.indexOf(u + '[') === 0;
      });
    };
    var declares = function (rule) {
      return names.some(function (n) {
        var covered = n === rule || n.indexOf(rule + '.') === 0 || n.indexOf(rule + '[') === 0;
        return covered && declaredName(userName(data.names, n));
      });
    };
    var forbidden = rules.forbid.filter(declares)[0];
    if (forbidden !== undefined) return TF(rules.forbidden_text, [forbidden]);
    var missing = rules.require.filter(function (r) { return !declares(r); })[0];
    return missing === undefined ? null : TF(rules.required_text, [missing]);
  }

  window.LightlabDecision = {
    compare: compare, matches: matches, exp1: exp1, isolate: isolate, finding: finding, squashed: squashed, textScore: textScore,
    againstExpected: againstExpected, tally: tally, ruleFor: ruleFor, brokenRule: brokenRule
  };
})();
