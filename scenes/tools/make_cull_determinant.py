#!/usr/bin/env python3
"""Writes cull_determinant.json: triangles whose window-space float determinant is exactly zero
while their snapped fixed-point area is not. Vertices lie on the line y = 2x - 0.5 (so the float
determinant cancels exactly) at x positions whose 1/8-pixel fractions round differently under
8-bit snapping in x and in y: the end vertices snap onto the line through the pixel centres
(k, 2k), the middle one 1/256 px to its right, so the long edge is a left edge and owns the
pixel centres on it.
lavapipe culls such a triangle twice over when its vertex batch clips: Mesa's draw-pipeline cull
stage counts a zero determinant as back-facing, then llvmpipe's setup uses the fixed-point area.
In a batch that does not clip only the fixed-point test runs. The scene has one draw of each kind.
Their plane equations divide by the zero determinant: depth and colour are NaN (a NaN depth
clamps to 1 in lavapipe, so the depth test is off here; a NaN colour stores as 0).
Run from scenes/:  python3 tools/make_cull_determinant.py"""
import json

SIZE = 256

def clip(xw, yw):
    # clip_space camera, w = 1: x_win = x * 128 + 128 exactly for these dyadic values.
    return [(xw - 128) / 128, (yw - 128) / 128, 0.5]

def sliver(m, fracs, flip):
    pts = []
    for k, f in zip((m - 30, m, m + 30), fracs):
        t = 256 * k + f          # snapped x before rounding: (x_win - 0.5) * 256
        xw = (t + 128) / 256
        pts.append(clip(xw, 2 * xw - 0.5))
    if flip:
        pts[1], pts[2] = pts[2], pts[1]
    return pts

def triangles():
    pts = []
    for m in range(35, 60, 4):
        for flip in (False, True):
            pts += sliver(m, (7 / 8, 5 / 8, 7 / 8), flip)
    return pts

colours = lambda n: [[1.0, 0.8, 0.2]] * n
plain = triangles()
# The same slivers plus one triangle that leaves the view: the whole batch goes through the draw pipeline.
clipped = triangles() + [clip(10, 250), clip(300, 240), clip(10, 200)]
for p in clipped[:-3]:
    p[0] += 0.75  # shift this copy right so the two draws do not overlap
scene = {
    "description": ("Triangles with a float determinant of exactly zero and a non-zero fixed-point area, with "
                    "back-face culling: in a vertex batch without clipping only llvmpipe's fixed-point test "
                    "decides; in a batch that clips, Mesa's draw-pipeline cull stage drops them first."),
    "framebuffer": {"width": SIZE, "height": SIZE, "clear_colour": [0.1, 0.1, 0.1, 1]},
    "camera": {"type": "clip_space"},
    "draws": [
        {"name": "batch without clipping", "positions": plain, "colours": colours(len(plain)), "cull": "back",
         "depth_test": False},
        {"name": "batch with clipping", "positions": clipped, "colours": colours(len(clipped)), "cull": "back",
         "depth_test": False},
    ],
}
with open("cull_determinant.json", "w") as f:
    json.dump(scene, f, indent=1)
    f.write("\n")
