#!/usr/bin/env python3
"""No import cycle between the files of a crate, and each crate root lists its modules in
dependency order.

    python3 tests/module_graph.py            check every crate (exit 1 on a problem)
    python3 tests/module_graph.py --graph    also print each crate's file-level edges

For every crate of the workspace (and the Python package's crate in python/), the module
tree is read from the crate root (`src/lib.rs`, else `src/main.rs`) through its `mod NAME;`
declarations (`#[path]` is not used in this repository and not supported). Each file is a
node. An edge A -> B means that file A names an item of file B: a path `crate::…`,
`super::…`, `self::…` or one starting with a child module's name, in a `use` declaration
(brace trees expanded) or anywhere in the code. A path is resolved to the deepest module it
names; a name re-exported by a module (`pub use x::Y;`) is followed to the module that
defines it, so a crate root that re-exports its modules' items is not part of every cycle.
Comments, strings and `#[cfg(test)]` modules are left out: a test module may use anything.

A strongly connected component of more than one file is a cycle; it is reported with one
cycle through it. The crate roots (and every `mod.rs`) must declare their modules in
dependency order: a module only uses modules declared before it. And the modules declared side
by side are layers: two of them (a folder counts as one, all its files) must not use each
other, even where no single file does, so that data flows down from folder to folder (e.g. the
library's `contact/` may use `params`, never `params` a file of `contact/`).

ALLOWED lists the cycles, the roots' order problems and the modules side by side that use each
other, of crates that other work fixes or that are known; the check fails on anything else.
Empty it (ALLOWED = {}) to make the check strict.
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

# Known problems: crate folder -> the cycles (each the sorted files of one strongly connected
# component, relative to the crate's src/), "order:<file>" for a root or mod.rs whose `mod`
# list is not yet in dependency order, and "layers:<file>:<a>,<b>,..." for modules declared
# side by side in <file> that use each other. An entry that no longer matches is reported as
# fixed; remove it then. When this is empty ({}) the check is strict.
ALLOWED = {
    # The parameter set checks and defaults itself with the rheology's plain-number formulas
    # (rheology/grease.rs: the grease's defaults and Arrhenius law; rheology/roelands_temperature.rs),
    # and rheology/viscosity.rs takes the parameter set's Lubricant: no file cycle, the two
    # modules are not layers.
    ".": ["layers:lib.rs:params,rheology"],
    # core/ and error.rs use each other (core/bytes.rs uses error.rs, error.rs uses
    # core/interface.rs): left after issue 40 item 1's version-neutral core.
    "crates/fmi-layer": ["layers:lib.rs:core,error"],
}


def crate_roots():
    out = []
    for toml in [ROOT / "Cargo.toml", *sorted(ROOT.glob("crates/*/Cargo.toml")), ROOT / "fmu_build/Cargo.toml",
                 ROOT / "python/Cargo.toml"]:
        src = toml.parent / "src"
        for name in ("lib.rs", "main.rs"):
            if (src / name).exists():
                out.append(src / name)
                break
    return out


def strip(text):
    """The code without comments, string and char literals (replaced by spaces)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            depth, i = 1, i + 2
            while i < n and depth:
                if text.startswith("/*", i):
                    depth, i = depth + 1, i + 2
                elif text.startswith("*/", i):
                    depth, i = depth - 1, i + 2
                else:
                    out.append("\n" if text[i] == "\n" else "")
                    i += 1
        elif c == "r" and re.match(r'r#*"', text[i:i + 40]) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            hashes = re.match(r'r(#*)"', text[i:]).group(1)
            end = text.find('"' + hashes, i + 2 + len(hashes))
            end = n if end < 0 else end + 1 + len(hashes)
            out.append(" " + "\n" * text.count("\n", i, end))
            i = end
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append(" " + "\n" * text.count("\n", i, j))
            i = j + 1
        elif c == "'":
            m = re.match(r"'(\\.|\\u\{[0-9a-fA-F]+\}|\\x..|[^\\'])'", text[i:i + 12])
            if m:
                out.append(" ")
                i += len(m.group(0))
            else:  # a lifetime
                out.append(c)
                i += 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def drop_cfg_test_modules(code):
    """Remove `#[cfg(test)] mod x { … }` and `#[cfg(test)] mod x;` (test code may use anything)."""
    while True:
        m = re.search(r"#\[cfg\(test\)\]\s*(?:#\[[^\]]*\]\s*)*(?:pub(?:\([^)]*\))?\s+)?mod\s+\w+\s*([;{])", code)
        if not m:
            return code
        if m.group(1) == ";":
            code = code[:m.start()] + code[m.end():]
            continue
        depth, j = 1, m.end()
        while j < len(code) and depth:
            depth += {"{": 1, "}": -1}.get(code[j], 0)
            j += 1
        code = code[:m.start()] + code[j:]


class Crate:
    def __init__(self, root_file):
        self.root_file = root_file
        self.src = root_file.parent
        self.files = {}      # module path (tuple) -> file
        self.inline = {}     # module path of an inline module -> its file
        self.code = {}       # file -> stripped code
        self.decl_order = {}  # file -> [child names in declaration order]
        self.load((), root_file)

    def load(self, path, file):
        self.files[path] = file
        code = drop_cfg_test_modules(strip(file.read_text(encoding="utf-8")))
        self.code[file] = code
        order = []
        # Inline modules: `mod x {` (their paths resolve into this file).
        stack = []
        for m in re.finditer(r"\bmod\s+(\w+)\s*([;{])|[{}]", code):
            tok = m.group(0)
            if tok == "{":
                stack.append(None)
            elif tok == "}":
                if stack:
                    stack.pop()
            elif m.group(2) == "{":
                inner = path + tuple(s for s in stack if s) + (m.group(1),)
                self.inline[inner] = file
                stack.append(m.group(1))
            elif not any(stack):  # `mod x;` at the file's top level
                name = m.group(1)
                order.append(name)
                base = file.parent if file.name in ("lib.rs", "main.rs", "mod.rs") else file.parent / file.stem
                child = base / f"{name}.rs"
                if not child.exists():
                    child = base / name / "mod.rs"
                if child.exists():
                    self.load(path + (name,), child)
        self.decl_order[file] = order

    def module_of(self, file):
        return next(p for p, f in self.files.items() if f == file)

    def is_module(self, path):
        return path in self.files or path in self.inline

    def file_of(self, path):
        return self.files.get(path) or self.inline.get(path)

    def reexports(self, module):
        """name -> absolute module path of its definition, for `pub use` items of a module file."""
        file = self.file_of(module)
        out = {}
        for m in re.finditer(r"\bpub(?:\([^)]*\))?\s+use\s+([^;]+);", self.code[file]):
            for full in expand_use(m.group(1)):
                segs = full.split("::")
                alias = segs[-1].split(" as ")[-1].strip()
                target = self.absolute(module, [s.split(" as ")[0].strip() for s in segs])
                if alias != "*":
                    out[alias] = target  # None: another crate's item (`pub use other as fmt;`)
        return out

    def absolute(self, module, segs):
        """The absolute path a path written in `module` starts from, or None for another crate."""
        if not segs:
            return None
        head = segs[0]
        if head == "crate":
            base, rest = (), segs[1:]
        elif head in ("super", "self"):
            base, rest = module, segs
            while rest and rest[0] in ("super", "self"):
                base = base[:-1] if rest[0] == "super" else base
                rest = rest[1:]
        elif self.is_module(module + (head,)):
            base, rest = module, segs
        else:
            return None
        return base + tuple(rest)

    def resolve(self, path, depth=0):
        """The module path (with a file) whose item `path` names."""
        best = ()
        for k in range(len(path), -1, -1):
            if self.is_module(path[:k]):
                best = path[:k]
                break
        rest = path[len(best):]
        if rest and depth < 8:
            exports = self.reexports(best)
            if rest[0] in exports:
                target = exports[rest[0]]
                if target is None:
                    return None
                if target != best + (rest[0],):
                    return self.resolve(target + rest[1:], depth + 1)
        return best

    def edges(self):
        out = {}
        for module, file in self.files.items():
            code = self.code[file]
            refs = set()
            for m in re.finditer(r"\buse\s+([^;]+);", code):
                for full in expand_use(m.group(1)):
                    refs.add(tuple(s.split(" as ")[0].strip() for s in full.split("::")))
            for m in re.finditer(r"(?<![\w:$])((?:crate|super|self|\w+)(?:::\w+)+)", code):
                refs.add(tuple(m.group(1).split("::")))
            for segs in refs:
                segs = tuple(s for s in segs if s not in ("*", ""))
                target = self.absolute(module, list(segs))
                if target is None:
                    continue
                resolved = self.resolve(target)
                dest = None if resolved is None else self.file_of(resolved)
                if dest is not None and dest != file:
                    out.setdefault(file, set()).add(dest)
        return out


def expand_use(tree):
    """`a::{b, c::{d, e}}` -> ['a::b', 'a::c::d', 'a::c::e']."""
    tree = re.sub(r"\s+", " ", tree).strip()
    if tree.startswith("::"):
        tree = tree[2:]
    i = tree.find("{")
    if i < 0:
        return [tree]
    prefix = tree[:i]
    depth, parts, cur = 0, [], ""
    for ch in tree[i + 1:tree.rfind("}")]:
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
            continue
        depth += {"{": 1, "}": -1}.get(ch, 0)
        cur += ch
    parts.append(cur)
    out = []
    for p in parts:
        p = p.strip()
        if not p:
            continue
        if p == "self":
            out.append(prefix.rstrip(":"))
        else:
            out += [prefix + e for e in expand_use(p)]
    return out


def sccs(nodes, edges):
    """Tarjan's strongly connected components."""
    index, low, on, stack, out, counter = {}, {}, set(), [], [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            out.append(comp)

    sys.setrecursionlimit(10000)
    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return out


def a_cycle(comp, edges):
    """One cycle through the first file of a component (breadth-first back to it)."""
    comp = set(comp)
    start = min(comp)
    prev, frontier = {start: None}, [start]
    while frontier:
        nxt = []
        for v in frontier:
            for w in sorted(edges.get(v, ())):
                if w == start:
                    path = [v]
                    while prev[path[-1]] is not None:
                        path.append(prev[path[-1]])
                    return list(reversed(path)) + [start]
                if w in comp and w not in prev:
                    prev[w] = v
                    nxt.append(w)
        frontier = nxt
    return [start]


def check(show_graph=False):
    problems, allowed_seen = [], []
    for root_file in crate_roots():
        crate = Crate(root_file)
        folder = str(root_file.parent.parent.relative_to(ROOT)) if root_file.parent.parent != ROOT else "."
        allowed = ALLOWED.get(folder, [])
        rel = lambda f: str(f.relative_to(crate.src))  # noqa: E731
        edges = crate.edges()
        if show_graph:
            for a in sorted(edges):
                print(f"{folder}: {rel(a)} -> {', '.join(sorted(rel(b) for b in edges[a]))}")
        found = []
        for comp in sccs(set(crate.files.values()), edges):
            if len(comp) > 1:
                names = sorted(rel(f) for f in comp)
                cycle = " -> ".join(rel(f) for f in a_cycle(comp, edges))
                found.append((" ".join(names), f"{folder}: import cycle between {', '.join(names)} (e.g. {cycle})"))
        # Roots and mod.rs files: declared in dependency order.
        for file, order in crate.decl_order.items():
            if len(order) < 2:
                continue
            module = crate.module_of(file)
            graph = sibling_graph(crate, module, order, edges)
            closure = {c: reachable(c, graph) for c in order}
            bad = [(a, b) for i, a in enumerate(order) for b in order[i + 1:] if b in closure[a] and a not in closure[b]]
            if bad:
                found.append((f"order:{rel(file)}", f"{folder}: {rel(file)} declares "
                              + "; ".join(f"`{a}` before `{b}`, which it uses" for a, b in bad)
                              + f". A dependency order: {', '.join(topological(order, graph))}"))
            # Side by side: layers, none using another that uses it back.
            for comp in sccs(set(order), graph):
                if len(comp) > 1:
                    names = [c for c in order if c in comp]
                    loop = a_cycle(comp, graph)
                    steps = "; ".join(f"{a} -> {b} ({example_edge(crate, module, a, b, edges, rel)})" for a, b in zip(loop, loop[1:]))
                    found.append((f"layers:{rel(file)}:{','.join(sorted(names))}", f"{folder}: {rel(file)} declares "
                                  + f"{', '.join(f'`{c}`' for c in names)}, which use each other: {steps}"))
        for key in allowed:
            if key not in {k for k, _ in found}:
                allowed_seen.append(f"{folder}: '{key}' is fixed: remove it from ALLOWED")
        for key, message in found:
            if key in allowed:
                allowed_seen.append(message)
            else:
                problems.append(message)
    return problems, allowed_seen


def sibling_graph(crate, module, order, edges):
    """child -> children it uses: an edge from any file of one child's subtree to another's."""
    owner = {}
    for path, f in crate.files.items():
        if len(path) > len(module) and path[:len(module)] == module and path[len(module)] in order:
            owner[f] = path[len(module)]
    graph = {c: set() for c in order}
    for a, targets in edges.items():
        for b in targets:
            if a in owner and b in owner and owner[a] != owner[b]:
                graph[owner[a]].add(owner[b])
    return graph


def example_edge(crate, module, a, b, edges, rel):
    """One file of sibling `a` that uses one of sibling `b`, as `x.rs uses y.rs`."""
    def owns(name, f):
        path = crate.module_of(f)
        return len(path) > len(module) and path[:len(module)] == module and path[len(module)] == name
    for f in sorted(edges):
        if owns(a, f):
            for g in sorted(edges[f]):
                if owns(b, g):
                    return f"{rel(f)} uses {rel(g)}"
    return "?"


def topological(order, graph):
    """The declared order changed as little as possible: each module after those it uses."""
    out, placed = [], set()
    while len(out) < len(order):
        ready = [c for c in order if c not in placed and graph[c] - {c} <= placed | cycle_mates(c, graph)]
        pick = ready[0] if ready else next(c for c in order if c not in placed)
        out.append(pick)
        placed.add(pick)
    return out


def cycle_mates(c, graph):
    return {d for d in reachable(c, graph) if c in reachable(d, graph)}


def reachable(start, edges):
    """Everything reachable from start."""
    seen, todo = set(), [start]
    while todo:
        v = todo.pop()
        for w in edges.get(v, ()):
            if w not in seen:
                seen.add(w)
                todo.append(w)
    return seen


def self_test():
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "src"
        (src / "c").mkdir(parents=True)
        (src / "lib.rs").write_text("mod a;\nmod b;\nmod c;\npub use a::A;\n")
        (src / "a.rs").write_text("use crate::b::B; // crate::c::X in a comment\npub struct A;\n"
                                  "#[cfg(test)]\nmod tests { use crate::c::Z; }\n")
        (src / "b.rs").write_text("pub struct B;\nfn f() { let s = \"crate::c::Y\"; super::c::d::g(); }\n")
        (src / "c" / "mod.rs").write_text("pub mod d;\n")
        (src / "c" / "d.rs").write_text("use crate::{A, b::{self, B}};\npub fn g() {}\n")
        crate = Crate(src / "lib.rs")
        e = {str(k.relative_to(src)): sorted(str(v.relative_to(src)) for v in vs) for k, vs in crate.edges().items()}
        want = {"lib.rs": ["a.rs"], "a.rs": ["b.rs"], "b.rs": ["c/d.rs"], "c/d.rs": ["a.rs", "b.rs"]}
        assert e == want, f"self-test: edges {e}, expected {want}"
        comps = [sorted(str(f.relative_to(src)) for f in c) for c in sccs(set(crate.files.values()), crate.edges()) if len(c) > 1]
        assert comps == [["a.rs", "b.rs", "c/d.rs"]], comps
        (src / "lib.rs").write_text("mod p;\nmod r;\n")
        (src / "p.rs").write_text("use crate::r::g::G;\n")
        (src / "r").mkdir()
        (src / "r" / "mod.rs").write_text("pub mod g;\npub mod v;\n")
        (src / "r" / "g.rs").write_text("pub struct G;\n")
        (src / "r" / "v.rs").write_text("use crate::p::P;\n")
        for stale in ("a.rs", "b.rs"):
            (src / stale).unlink()
        import shutil
        shutil.rmtree(src / "c")
        crate = Crate(src / "lib.rs")
        edges = crate.edges()
        assert not [c for c in sccs(set(crate.files.values()), edges) if len(c) > 1], "self-test: no file cycle"
        graph = sibling_graph(crate, (), ["p", "r"], edges)
        assert [sorted(c) for c in sccs({"p", "r"}, graph) if len(c) > 1] == [["p", "r"]], graph
    assert expand_use("a::{b, c::{d, e as f}, self}") == ["a::b", "a::c::d", "a::c::e as f", "a"]


def main(argv):
    self_test()
    problems, allowed = check("--graph" in argv)
    for m in allowed:
        print(f"allowed for now (ALLOWED in tests/module_graph.py): {m}")
    for m in problems:
        print(m)
    print(f"module_graph: {len(problems)} problem(s), {len(allowed)} allowed until their crates are tidied")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
