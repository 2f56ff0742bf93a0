"""A tree drawn as a fan: each subtree in a wedge of its parent's, as wide as its share
of the leaves, each node on the arc of its depth, the root at the fan's point and the
fan opening down (y grows down; up with --up, for a tree whose edges point to the
root). Prints {"positions": [[x, y], ...]} in the scene's node order, and on stderr how
many edges point down (target below source) and the least drop, in hops.

usage: python3 fan.py SCENE.json DEGREES [ROOT_ID] [--up] | python3 ../reference/stress.py SCENE.json
"""
import json
import math
import sys

args = [a for a in sys.argv[1:] if a != "--up"]
sign = -1.0 if "--up" in sys.argv else 1.0
scene = json.load(open(args[0]))
fan = float(args[1])
ids = [n["id"] for n in scene["nodes"]]
index = {v: i for i, v in enumerate(ids)}
root = index[int(args[2])] if len(args) > 2 else 0
n = len(ids)
around = [[] for _ in range(n)]
for a, b in scene["edges"]:
    around[index[a]].append(index[b])
    around[index[b]].append(index[a])
depth, parent, order = [-1] * n, [-1] * n, [root]
depth[root] = 0
for u in order:
    for v in around[u]:
        if depth[v] < 0:
            depth[v], parent[v] = depth[u] + 1, u
            order.append(v)
if len(order) != n or len(scene["edges"]) != n - 1:
    sys.exit("not a tree")
children = [[] for _ in range(n)]
for v in order[1:]:
    children[parent[v]].append(v)
leaves = [0] * n
for v in reversed(order):
    leaves[v] = sum(leaves[c] for c in children[v]) or 1
angle, wedge = [0.0] * n, {root: (-fan / 2, fan / 2)}
for u in order:
    lo, hi = wedge[u]
    angle[u] = (lo + hi) / 2
    at = lo
    for c in children[u]:
        width = (hi - lo) * leaves[c] / leaves[u]
        wedge[c] = (at, at + width)
        at += width
positions = [
    [depth[v] * math.sin(math.radians(angle[v])), sign * depth[v] * math.cos(math.radians(angle[v]))]
    for v in range(n)
]
drops = []
for a, b in scene["edges"]:
    a, b = index[a], index[b]
    drops.append(positions[b][1] - positions[a][1])
print(json.dumps({"edges_down": sum(d > 0 for d in drops), "edges": len(drops), "least_drop_hops": round(min(drops), 3)}), file=sys.stderr)
print(json.dumps({"positions": positions}))
