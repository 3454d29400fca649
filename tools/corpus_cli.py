#!/usr/bin/env python3
"""The learner corpus (tests/data/learner_shaders/) through `lightlab check-shader` at the
command line's default case count, not the 2000 cases of tests/learner_corpus.rs: the first
finding of each diagnosis (id@site, `A + B` for a pair, `isolated …`) against the file's
`// expect:` line, with the time each check took.

    cargo build --release
    python3 tools/corpus_cli.py [tests/data/learner_shaders] [target/release/lightlab]

A pair counts in either order. `reflect-sign` and `view-dir-reversed` give identical outputs
(src/checker/mistakes.rs, EQUIVALENT), so a file expecting one may print the other: such lines
show DIFF here and count as exact in the corpus test.
"""
import json, os, re, subprocess, sys, time
d = sys.argv[1] if len(sys.argv) > 1 else "tests/data/learner_shaders"
exe = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "target/release/lightlab")
rows = []
for f in sorted(os.listdir(d)):
    if not f.endswith('.frag'): continue
    head = {}
    for line in open(os.path.join(d, f)):
        m = re.match(r'// (model|uniforms|vertex|expect): (.*)', line.strip())
        if m: head[m.group(1)] = m.group(2).strip()
    args = [exe, 'check-shader', '--model', head['model'], f, '--format', 'json']
    if 'uniforms' in head: args += ['--uniforms', head['uniforms']]
    if 'vertex' in head: args += ['--vertex', head['vertex']]
    t = time.time()
    out = subprocess.run(args, cwd=d, capture_output=True, text=True, env=dict(os.environ, LC_ALL='C'))
    dt = time.time() - t
    try: v = json.loads(out.stdout)
    except Exception: rows.append((f, head['expect'], 'ERROR ' + out.stderr[:100], dt)); continue
    diag = v.get('diagnosis') or []
    def name(x):
        s = x.get('id', '') + ('@' + x['site'] if x.get('site') else '')
        return s
    if not diag: got = 'agrees' if v.get('verdict') == 'agrees' else v.get('verdict', '?')
    else:
        first = diag[0]
        got = name(first)
        if first.get('second'): got += ' + ' + name(first['second'])
        if first.get('id') == 'isolated': got = 'isolated ' + first.get('title', '')
    rows.append((f, head['expect'], got, dt))
exact = 0
for f, want, got, dt in rows:
    ok = want == got or (want.startswith('isolated') and got.startswith('isolated') and want.split(' ',1)[1] in got) \
        or (' + ' in want and set(want.split(' + ')) == set(got.split(' + ')))
    exact += ok
    print('%-5s %5.1fs %-48s want %-40s got %s' % ('ok' if ok else 'DIFF', dt, f, want, got[:90]))
print('exact %d of %d' % (exact, len(rows)))
