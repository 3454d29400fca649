#!/usr/bin/env python3
"""Import cycles between the crate's modules (issue: "no circles").

Every `.rs` file under src/ is a module (`src/a/b.rs` and `src/a/b/mod.rs` are `a::b`).
A module depends on each module it names by path: `crate::x::y`, `super::x`, `self::x`
(in `use` lines and in code), resolved to the longest path that is a module. An edge to
one's own ancestor (a child using its parent's items) is not a dependency between
siblings and is left out; the parent declaring its children is left out too. The
output lists each cycle (a strongly connected component of more than one module) and
exits 1 when there is one. Tests (`#[cfg(test)] mod tests`, or `mod <name>_tests`, after which the file is not
read) are left out: a test may use anything.

Usage: python3 tools/module_cycles.py [SRC_DIR]
"""
import os, re, sys

src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..', 'src')
modules = {}
for root, _, files in os.walk(src):
    for f in files:
        if not f.endswith('.rs'):
            continue
        rel = os.path.relpath(os.path.join(root, f), src)[:-3].split(os.sep)
        if rel[0] == 'bin':
            continue
        if rel[-1] in ('mod', 'lib', 'main'):
            rel = rel[:-1]
        modules[tuple(rel)] = os.path.join(root, f)

def strip(text):
    text = re.sub(r'//[^\n]*', '', text)
    text = re.sub(r'/\*.*?\*/', '', text, flags=re.S)
    text = re.sub(r'"(?:\\.|[^"\\])*"', '""', text)
    cut = re.search(r"#\[cfg\(test\)\]\s*mod\s+\w*tests\b", text)
    return text[:cut.start()] if cut else text

def expand_use(text):
    """`use a::{b, c::{d, e}}` -> a::b, a::c::d, a::c::e (one level of braces at a time)."""
    out = []
    for m in re.finditer(r'\buse\s+([^;]+);', text):
        stack = [m.group(1).replace('\n', ' ')]
        while stack:
            s = stack.pop().strip()
            b = s.find('{')
            if b < 0:
                out.append(s.split(' as ')[0].strip())
                continue
            prefix, depth, items, cur = s[:b], 0, [], ''
            for ch in s[b + 1:s.rfind('}')]:
                if ch == '{': depth += 1
                if ch == '}': depth -= 1
                if ch == ',' and depth == 0:
                    items.append(cur); cur = ''
                else:
                    cur += ch
            items.append(cur)
            stack.extend(prefix + i.strip() for i in items if i.strip())
    return out

def resolve(me, path):
    parts = [p for p in path.split('::') if p]
    if not parts:
        return None
    if parts[0] == 'crate':
        base, parts = (), parts[1:]
    elif parts[0] in ('super', 'self'):
        base = me
        while parts and parts[0] in ('super', 'self'):
            if parts[0] == 'super':
                base = base[:-1]
            parts = parts[1:]
    else:
        return None
    full = base + tuple(parts)
    for n in range(len(full), 0, -1):
        if full[:n] in modules:
            return full[:n]
    return None

edges = {m: set() for m in modules}
for me, path in modules.items():
    text = strip(open(path, encoding='utf-8').read())
    paths = expand_use(text) + re.findall(r'\b((?:crate|super|self)(?:::\w+)+)', text)
    for p in paths:
        to = resolve(me, p)
        if to is None or to == me:
            continue
        if me[:len(to)] == to or to[:len(me)] == me:
            continue  # an ancestor or a descendant
        edges[me].add(to)

def cycles(graph):
    """Tarjan's strongly connected components of more than one node."""
    index, low, on, stack, sccs, counter = {}, {}, set(), [], [], [0]
    def visit(v):
        index[v] = low[v] = counter[0]; counter[0] += 1
        stack.append(v); on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w); low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop(); on.discard(w); comp.append(w)
                if w == v: break
            if len(comp) > 1:
                sccs.append(sorted(comp))
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sccs

sys.setrecursionlimit(10000)
# the top level: a file's dependency on another top-level module is its module's
top = {(m[0],): set() for m in modules if m}
for m, ws in edges.items():
    for w in ws:
        if m and w and m[0] != w[0]:
            top[(m[0],)].add((w[0],))
name = lambda m: '::'.join(m) or 'crate'
found = 0
for level, graph in (('top-level modules', top), ('files', edges)):
    for comp in cycles(graph):
        found += 1
        inside = set(comp)
        print(f'cycle between {level}:', ', '.join(name(m) for m in comp))
        for m in comp:
            for w in sorted(graph[m] & inside):
                why = sorted(name(a) + ' -> ' + name(b) for a, bs in edges.items() for b in bs
                             if a[:len(m)] == m and b[:len(w)] == w) if level != 'files' else []
                print(f'  {name(m)} -> {name(w)}' + (f'  ({"; ".join(why[:4])})' if why else ''))
print(f'{len(modules)} modules, {sum(map(len, edges.values()))} dependencies, {found} cycles')
sys.exit(1 if found else 0)
