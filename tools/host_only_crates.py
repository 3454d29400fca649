#!/usr/bin/env python3
"""The dependencies that only run at build time, against Cargo.toml's opt-level 0 list.

`[profile.dev.package."*"] opt-level = 2` optimizes every dependency in `cargo test`, and
cargo gives `package."*"` precedence over `build-override`: proc macros, build scripts and
the crates only they use were compiled at opt-level 2 as well, at the start of every
clippy and test build (clippy --all-targets on an empty target: 5 to 6 minutes in CI
with them, 2 min 21 s without). Cargo.toml names them one by one at opt-level 0, as
cargo builds them by default.

A crate is host-only when every path to it from lightlab passes through a proc-macro crate
or a build-dependency edge (from `cargo metadata`, all features, this platform). The
script prints that set and the Cargo.toml list, and exits 1 if they differ: a new or
removed dependency changes the set, and the list follows.

Usage: python3 tools/host_only_crates.py [--print]
"""
import json, os, re, subprocess, sys

root_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..')
host = subprocess.run(['rustc', '-vV'], capture_output=True, text=True, check=True).stdout
triple = re.search(r'^host: (\S+)', host, re.M).group(1)
meta = json.loads(subprocess.run(
    ['cargo', 'metadata', '--format-version', '1', '--all-features', '--filter-platform', triple],
    cwd=root_dir, capture_output=True, text=True, check=True).stdout)
packages = {p['id']: p for p in meta['packages']}
nodes = {n['id']: n for n in meta['resolve']['nodes']}
root = meta['resolve']['root']

def proc_macro(pid):
    return any('proc-macro' in t['kind'] for t in packages[pid]['targets'])

def reach(follow):
    seen, stack = set(), [root]
    while stack:
        pid = stack.pop()
        if pid in seen:
            continue
        seen.add(pid)
        stack += [d['pkg'] for d in nodes[pid]['deps'] if follow(d)]
    return seen

# compiled for the target: normal and dev edges, not into a proc macro
target = reach(lambda d: not proc_macro(d['pkg'])
               and any(k['kind'] in (None, 'dev') for k in d['dep_kinds']))
everything = reach(lambda d: True)
names = lambda ids: {packages[i]['name'] for i in ids}
want = names(everything - target) - names(target)

toml = open(os.path.join(root_dir, 'Cargo.toml'), encoding='utf-8').read()
section = re.search(r'^\[profile\.dev\.package\]\n(.*?)(?=^\[|\Z)', toml, re.M | re.S)
have = set(re.findall(r'^"?([A-Za-z0-9_-]+)"? = \{ opt-level = 0 \}', section.group(1), re.M)) if section else set()

if '--print' in sys.argv:
    print('\n'.join(f'{n} = {{ opt-level = 0 }}' for n in sorted(want)))
missing, extra = sorted(want - have), sorted(have - want)
if missing or extra:
    print('Cargo.toml [profile.dev.package] opt-level 0 list differs from the host-only crates:')
    if missing:
        print('  build-time only, not listed:', ' '.join(missing))
    if extra:
        print('  listed, but not (or no longer) build-time only:', ' '.join(extra))
    sys.exit(1)
print(f'{len(want)} build-time crates, all at opt-level 0 in the dev profile')
