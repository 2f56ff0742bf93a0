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

deps = {m: set() for m in mods}
for m, entry in mods.items():
    for path in files(entry):
        text = open(path).read()
        in_test = False
        for line in text.split("\n"):
            code = line.split("//")[0]
            if line.strip().startswith("#[cfg(doc)]"):
                in_test = True  # the next `use` serves doc links only
                continue
            if in_test and code.strip().startswith("use "):
                in_test = False
                continue
            in_test = False
            for target in re.findall(r"crate::(\w+)", code):
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
