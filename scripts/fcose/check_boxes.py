"""Counts, for a fcose.js output with communities, the pairs of community boxes that
overlap by more than 1 unit on both axes, and the nodes whose centre lies inside
the box of a community they are not in (each node counted once).
usage: python3 check_boxes.py COMMUNITIES.json < fcose-output.json"""
import json, sys

community = json.load(open(sys.argv[1]))["community"]
out = json.load(sys.stdin)
pos, boxes = out["positions"], out["boxes"]
live = [(c, b) for c, b in enumerate(boxes) if b is not None]

overlaps = 0
for i in range(len(live)):
    for j in range(i + 1, len(live)):
        a, b = live[i][1], live[j][1]
        ox = min(a[2], b[2]) - max(a[0], b[0])
        oy = min(a[3], b[3]) - max(a[1], b[1])
        if ox > 1 and oy > 1:
            overlaps += 1

intruders = 0
for (x, y), own in zip(pos, community):
    if any(c != own and b[0] < x < b[2] and b[1] < y < b[3] for c, b in live):
        intruders += 1

print(json.dumps({"overlapping_box_pairs": overlaps, "intruders": intruders, "boxes": len(live)}))
