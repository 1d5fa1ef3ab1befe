#!/usr/bin/env python3
"""Writes top_left_rule.json: triangles whose vertices and edges pass exactly through pixel centres
(horizontal, vertical and diagonal edges of both slopes), each pair sharing an edge, with both
windings. Which triangle owns a pixel centre on a shared edge is the fill rule's decision alone.
Run from scenes/:  python3 tools/make_top_left_rule.py"""
import json

SIZE = 128

def clip(px, py):  # pixel centre (px, py) -> clip space with the clip_space camera (w = 1)
    return [(px + 0.5 - SIZE / 2) / (SIZE / 2), (py + 0.5 - SIZE / 2) / (SIZE / 2), 0.5]

draws = []
cells = [(4, 4), (36, 4), (68, 4), (100, 4), (4, 40), (36, 40), (68, 40), (100, 40)]
for i, (x, y) in enumerate(cells):
    s = 20
    a, b, c, d = (x, y), (x + s, y), (x + s, y + s), (x, y + s)
    if i % 2 == 0:   # split along the a-c diagonal
        t1, t2 = (a, d, c), (a, c, b)
    else:            # split along the b-d diagonal
        t1, t2 = (a, d, b), (b, d, c)
    if i >= 4:       # clockwise copies
        t1, t2 = t1[::-1], t2[::-1]
    for k, t in enumerate((t1, t2)):
        draws.append({"name": f"cell {i} half {k}", "positions": [clip(*p) for p in t],
                      "colour": [0.3 + 0.7 * k, 0.3 + 0.1 * i, 1.0 - 0.7 * k], "cull": "none"})
# A fan of thin triangles around a pixel centre: every edge passes through pixel centres.
centre = (64, 96)
rim = [(84, 96), (84, 106), (74, 116), (64, 116), (54, 116), (44, 106), (44, 96), (44, 86), (54, 76), (64, 76),
       (74, 76), (84, 86)]
for k in range(len(rim)):
    p, q = rim[k], rim[(k + 1) % len(rim)]
    draws.append({"name": f"fan {k}", "positions": [clip(*centre), clip(*p), clip(*q)],
                  "colour": [0.2 + 0.06 * k, 0.9 - 0.05 * k, 0.3], "cull": "none"})
scene = {
    "description": ("Fill rule on edges through pixel centres: split squares (both diagonals, both windings) and a "
                    "fan whose every edge passes through pixel centres. Depth test off, so the last triangle to "
                    "cover a pixel shows: a pixel owned by the wrong triangle changes colour."),
    "framebuffer": {"width": SIZE, "height": SIZE, "clear_colour": [0, 0, 0, 1]},
    "camera": {"type": "clip_space"},
    "draws": draws,
}
for d in draws:
    d["depth_test"] = False
with open("top_left_rule.json", "w") as f:
    json.dump(scene, f, indent=1)
    f.write("\n")
