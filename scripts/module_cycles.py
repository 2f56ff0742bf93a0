#!/usr/bin/env python3
"""Prints the crate's top-level modules, what each imports from the others (paths
`crate::x` in code, not in comments or doc links), and every cycle among them. Exits 1
when there is a cycle. Run from the repository root: `python3 scripts/module_cycles.py`."""
import os, re, sys

SRC = "src"
mods = {}
for entry in sorted(os.listdir(SRC)):
    name = entry[:-3] if entry.endswith(".rs") else entry
    if name in ("lib",):
        continue
    mods[name] = entry

def files(entry):
    path = os.path.join(SRC, entry)
    if os.path.isfile(path):
        yield path
    else:
        for root, _, names in os.walk(path):
            for n in names:
                if n.endswith(".rs"):
                    yield os.path.join(root, n)

def code_of(text):
    """The file's code: comments left out, and the `use` after a `#[cfg(doc)]` (it
    serves doc links only)."""
    out, skip_use = [], False
    for line in text.split("\n"):
        stripped = line.strip()
        if stripped.startswith("#[cfg(doc)]"):
            skip_use = True
            continue
        if skip_use and stripped.startswith("use "):
            # Through the end of the statement.
            skip_use = not stripped.endswith(";")
            skip_use = "statement" if skip_use else False
            continue
        if skip_use == "statement":
            skip_use = "statement" if not stripped.endswith(";") else False
            continue
        skip_use = False
        out.append(line.split("//")[0])
    return "\n".join(out)

def targets(code):
    """Every top-level module named after `crate::`, in plain paths and in groups
    (`crate::{a::X, b::{Y, Z}}`)."""
    found = set(re.findall(r"crate::(\w+)", code))
    for start in [m.end() for m in re.finditer(r"crate::\{", code)]:
        depth, item, i = 1, "", start
        while i < len(code) and depth:
            c = code[i]
            if c == "{":
                depth += 1
            elif c == "}":
                depth -= 1
            if depth == 1 and c == ",":
                found.add(item.strip().split("::")[0])
                item = ""
            elif depth >= 1 and not (depth == 1 and c in "{}"):
                item += c if depth == 1 else ""
            i += 1
        found.add(item.strip().split("::")[0])
    return found

deps = {m: set() for m in mods}
for m, entry in mods.items():
    for path in files(entry):
        for target in targets(code_of(open(path).read())):
            if target in mods and target != m:
                deps[m].add(target)

for m in sorted(deps):
    print(f"{m:12} -> {', '.join(sorted(deps[m])) or '-'}")

# cycles: strongly connected components with more than one module
index, low, stack, on, sccs, counter = {}, {}, [], set(), [], [0]
def visit(v):
    index[v] = low[v] = counter[0]; counter[0] += 1
    stack.append(v); on.add(v)
    for w in deps[v]:
        if w not in index:
            visit(w); low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        comp = []
        while True:
            w = stack.pop(); on.discard(w); comp.append(w)
            if w == v:
                break
        if len(comp) > 1:
            sccs.append(sorted(comp))
sys.setrecursionlimit(10000)
for v in sorted(deps):
    if v not in index:
        visit(v)
if sccs:
    for comp in sccs:
        edges = [f"{a}->{b}" for a in comp for b in sorted(deps[a]) if b in comp]
        print("cycle:", ", ".join(comp), "|", " ".join(edges))
    sys.exit(1)
print("no cycles")
