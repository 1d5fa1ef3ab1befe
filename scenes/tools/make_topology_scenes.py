#!/usr/bin/env python3
"""Writes the topology and primitive-state scenes (issue 13): the negative-height viewport, primitive
restart, provoking vertex last, stippled lines (and stippled polygon-mode lines) and the adjacency topologies. Geometry is laid out in
pixels and unprojected through the pinhole camera (origin, looking along +z, y down, focal length
F), with the helpers it shares with make_feature_scenes.py (scene_layout.py). Run from scenes/:  python3 tools/make_topology_scenes.py"""
import math

from scene_layout import H, W, at, ccw, cw, draw, fan, rainbow, scene, strip

RESTART = "restart"
FLIPPED = {"x": 0, "y": H, "width": W, "height": -H}


def zigzag(x0, y0, dx, dy, n, z0, z1):
    return [at(x0 + dx * k, y0 + (dy if k % 2 else 0) + 0.37 * k, z0 + (z1 - z0) * k / max(1, n - 1)) for k in range(n)]


# ---- 1. the negative-height viewport (GL-style y flip) ----
draws = []
for col, (cull, front) in enumerate([("back", "counter_clockwise"), ("front", "counter_clockwise"),
                                     ("back", "clockwise"), ("none", "counter_clockwise")]):
    x = col * 64 + 4
    draws.append(draw(f"flipped, cull {cull}, front {front}", ccw(x, 8, 26, 70) + cw(x + 30, 8, 26, 70),
                      [[0.9, 0.2, 0.2]] * 3 + [[0.2, 0.8, 0.2]] * 3, cull=cull, front_face=front, viewport=FLIPPED))
draws.append(draw("flipped strip", strip(8, 100, 24, 30, 10, 1.5, 3.0), rainbow(10, 2), topology="triangle_strip",
                  viewport=FLIPPED))
draws.append(draw("flipped sub-viewport, fractional, clipped, reversed depth", strip(110, 80, 40, 120, 8, 1.0, 4.0),
                  rainbow(8, 5), topology="triangle_strip", cull="none",
                  viewport={"x": 140.25, "y": 186.5, "width": 100, "height": -80.75, "min_depth": 0.9,
                            "max_depth": 0.1}))
draws.append(draw("flipped lines", zigzag(10, 150, 22, 20, 11, 2.0, 3.0), rainbow(11, 1), topology="line_strip",
                  line_width=2.0, viewport=FLIPPED))
draws.append(draw("flipped points", [at(20 + 9 * k, 30 + 4 * k, 2.0) for k in range(12)], rainbow(12, 3),
                  topology="point_list", point_size=3.0, viewport=FLIPPED))
scene("viewport_flip.json", "Negative viewport height (Vulkan 1.1's GL-style y flip): y = 192, height = -192 mirrors "
      "the image, so triangles counter-clockwise in the ordinary image are clockwise here; each cull mode and front "
      "face with one triangle of each winding shows which survives (red: counter-clockwise before the flip, green: "
      "clockwise); a culled strip; a flipped sub-viewport with a fractional offset and reversed depth range, which "
      "clips a strip; lines and points flipped.", draws)

# ---- 2. primitive restart ----
pts = strip(6, 10, 20, 40, 12, 1.5, 3.0) + strip(6, 70, 20, 40, 9, 2.0, 2.5) + strip(130, 10, 22, 45, 14, 3.0, 1.5)
idx = list(range(0, 7)) + [RESTART] + list(range(7, 12)) + [RESTART, RESTART] + list(range(12, 21)) + \
    [RESTART, 21, 22, RESTART] + list(range(23, 35)) + [RESTART]
scene("primitive_restart_strip.json", "Primitive restart on triangle strips (index 0xFFFFFFFF, written \"restart\"): "
      "runs of odd and even length with back-face culling on, so each run's winding parity must start afresh; two "
      "restarts in a row, a run too short for a triangle, a restart first and last; a strip with adjacency cut "
      "likewise.", [
          draw("strip with restarts", pts, rainbow(len(pts)), topology="triangle_strip", primitive_restart=True,
               indices=[RESTART] + idx),
          draw("strip with adjacency and restarts", strip(6, 130, 12, 40, 16, 2.0, 2.0) + strip(140, 130, 12, 40, 14, 2.0, 2.0),
               rainbow(30, 3), topology="triangle_strip_with_adjacency", primitive_restart=True, cull="none",
               indices=list(range(0, 16)) + [RESTART] + list(range(16, 30))),
      ])

pts = zigzag(8, 12, 20, 26, 12, 2.0, 3.0) + zigzag(8, 70, 16, 22, 15, 3.0, 1.5) + zigzag(8, 130, 24, 30, 10, 1.0, 2.0)
scene("primitive_restart_line_strip.json", "Primitive restart on line strips: three strips in one indexed draw, two "
      "restarts in a row, a one-index run (no line), wide and Bresenham lines; a line strip with adjacency cut by "
      "restarts (its first and last vertex of each run are adjacency only).", [
          draw("line strip with restarts", pts, rainbow(len(pts)), topology="line_strip", primitive_restart=True,
               line_width=2.0,
               indices=list(range(0, 12)) + [RESTART, RESTART] + list(range(12, 27)) + [RESTART, 27, RESTART] +
               list(range(28, 37))),
          draw("bresenham strip with restarts", zigzag(130, 150, 10, 16, 12, 2.0, 2.0), rainbow(12, 4),
               topology="line_strip", primitive_restart=True, line_rasterization="bresenham",
               indices=[0, 1, 2, 3, RESTART, 4, 5, 6, RESTART, 7, 8, 9, 10, 11]),
          draw("line strip with adjacency and restarts", zigzag(130, 100, 11, 18, 11, 2.5, 2.5), rainbow(11, 6),
               topology="line_strip_with_adjacency", primitive_restart=True, line_width=3.0,
               indices=[0, 1, 2, 3, 4, 5, RESTART, 6, 7, 8, 9, 10]),
      ])

pts = fan(45, 50, 38, 9, 2.0) + fan(130, 50, 35, 7, 2.5, 0.7) + fan(210, 50, 38, 10, 1.8) + fan(70, 140, 40, 8, 2.2)
scene("primitive_restart_fan.json", "Primitive restart on triangle fans: each run is a fan of its own around its first "
      "index (four fans in one draw, back-face culling on), a run of two indices draws nothing, restarts in a row.", [
          draw("fans with restarts", pts, rainbow(len(pts), 1), topology="triangle_fan", primitive_restart=True,
               indices=list(range(0, 10)) + [RESTART] + list(range(10, 18)) + [RESTART, RESTART] +
               list(range(18, 29)) + [RESTART, 29, 30, RESTART] + list(range(29, 38))),
      ])

# ---- 3. provoking vertex last ----
LAST = {"shading": "vertex_color_flat", "provoking_vertex": "last"}
draws = [
    draw("list, both windings", ccw(6, 6, 36, 36, 2.5) + cw(46, 6, 36, 36, 2.0), rainbow(6), cull="none", **LAST),
    draw("strip", strip(90, 6, 20, 40, 10, 1.5, 3.0), rainbow(10, 2), topology="triangle_strip", cull="none", **LAST),
    draw("fan", fan(215, 40, 34, 8, 2.2), rainbow(9, 4), topology="triangle_fan", cull="none", **LAST),
    draw("lines", [at(10, 60 + 3 * k, 2.0) if k % 2 == 0 else at(80, 70 + 3 * k, 2.5) for k in range(8)],
         rainbow(8, 1), topology="line_list", line_width=2.0, **LAST),
    draw("line strip", zigzag(90, 60, 14, 16, 9, 2.0, 3.0), rainbow(9, 3), topology="line_strip", line_width=3.0,
         **LAST),
    draw("clipped by the near plane", [[-1.2, 0.2, -0.5], [-0.2, 0.9, 3.0], [-1.4, 0.9, 2.0],
                                       [-0.3, 0.25, 1.0], [-0.6, 0.3, -1.0], [0.1, 0.8, 2.5]], rainbow(6, 5),
         cull="none", **LAST),
    draw("clipped by the sides, strip", [[1.0, -0.2, 2.0], [1.6, 0.4, 2.0], [0.7, 0.1, 2.0], [1.9, 0.8, 2.0],
                                         [0.8, 0.6, 2.0], [2.2, 0.95, 2.0]], rainbow(6, 2), topology="triangle_strip",
         cull="none", **LAST),
    draw("clipped lines", [[0.0, 0.6, -1.0], [0.5, 0.7, 3.0], [-3.0, 0.75, 2.0], [3.0, 0.85, 2.0]], rainbow(4, 6),
         topology="line_list", line_width=1.5, **LAST),
    draw("polygon mode line, clipped", [[-0.9, 0.3, 2.0], [-0.2, 0.95, 2.0], [-1.5, 1.2, 2.0], [-0.1, 0.4, 0.3]],
         rainbow(4, 3), topology="triangle_strip", polygon_mode="line", cull="none", line_width=2.0, **LAST),
]
scene("provoking_vertex_last.json", "Provoking vertex last (VK_EXT_provoking_vertex) with a flat varying: a triangle "
      "list of both windings (a clockwise one is reordered by setup), a strip (odd triangles keep the last vertex "
      "last), a fan (0, i+1, i+2), lines and a line strip (the second end), triangles clipped by the near plane and "
      "the sides (the clipped fan is emitted from the provoking vertex), clipped lines and polygon mode line.", draws)

# ---- 4. stippled lines ----
def stipple_scene(filename, mode, label):
    def st(factor, pattern, **more):
        return dict(topology=more.pop("topology", "line_list"), line_rasterization=mode,
                    line_stipple={"factor": factor, "pattern": pattern}, **more)
    star = []
    for k in range(16):
        a = 2 * math.pi * (k + 0.21) / 16
        star += [at(60 + 6 * math.cos(a), 52 + 6 * math.sin(a), 2.0), at(60 + 48 * math.cos(a), 52 + 48 * math.sin(a), 3.0)]
    draws = [
        draw("star, factor 1, 0x0f0f", star, rainbow(32), **st(1, 0x0F0F)),
        draw("list, factor 3, 0x00ff, width 3", [at(130, 10 + 12 * k, 2.0) if k % 2 == 0 else at(250, 14 + 12 * k, 2.5)
                                                  for k in range(8)], rainbow(8, 2), **st(3, 0x00FF, line_width=3.0)),
        draw("strip: the counter runs on, factor 2, 0x3c5a", zigzag(8, 112, 21, 14, 12, 2.0, 3.0), rainbow(12, 4),
             **st(2, 0x3C5A, topology="line_strip", line_width=2.0)),
        draw("strip restarted: the counter restarts, factor 1, 0x1fe3", zigzag(8, 150, 13, 10, 12, 2.0, 2.0),
             rainbow(12, 1), **st(1, 0x1FE3, topology="line_strip", primitive_restart=True,
                                  indices=[0, 1, 2, 3, 4, "restart", 5, 6, 7, 8, "restart", 9, 10, 11])),
        draw("clipped by the near plane and the sides, flat, factor 4, 0xa5f1",
             [[0.0, 0.5, -1.0], [0.6, 0.55, 3.0], [-3.0, 0.62, 2.0], [3.0, 0.72, 2.0]], rainbow(4, 6),
             shading="vertex_color_flat", **st(4, 0xA5F1, line_width=1.5)),
        draw("factor 256, 0x0001", [at(140, 185, 1.0), at(250, 170, 1.0)], [[1, 1, 1], [0.3, 0.3, 1]],
             **st(256, 0x0001)),
        draw("pattern 0xffff", [at(135, 120, 2.0), at(250, 150, 3.0)], [[1, 0.5, 0.2], [0.2, 0.5, 1]],
             **st(5, 0xFFFF, line_width=2.0)),
        draw("strip leaving the view: the line wholly outside does not advance the counter, factor 2, 0x0f3f",
             [at(150, 92, 2.0), at(230, 100, 2.0), at(400, 60, 2.0), at(420, 130, 2.0), at(240, 108, 2.0),
              at(160, 112, 2.0)], rainbow(6, 2), **st(2, 0x0F3F, topology="line_strip")),
    ]
    scene(filename, f"Stippled {label} lines (VK_EXT_line_rasterization stippledLineEnable): Mesa's stipple stage "
          "cuts each line, after clipping, into segments of ceil(length) steps, each step on when bit "
          "(counter / factor) mod 16 of the pattern is set; the counter restarts at every line of a list and at the "
          "first line of each strip (and after a primitive restart) and runs on along a strip; varyings of a "
          "segment's new ends are linear in window space; factors 1 to 256, wide and clipped lines, a flat varying; "
          "a strip leaving the view, whose line wholly outside does not advance the counter.",
          draws)

stipple_scene("line_stipple.json", "rectangular", "rectangular")
stipple_scene("line_stipple_bresenham.json", "bresenham", "Bresenham")


# ---- 5. stippled polygon-mode lines ----
def stipple_polygon_scene(filename, mode, label):
    def st(factor, pattern, **more):
        return dict(topology=more.pop("topology", "triangle_list"), polygon_mode=more.pop("polygon_mode", "line"),
                    line_rasterization=mode, line_stipple={"factor": factor, "pattern": pattern}, cull="none", **more)
    draws = [
        draw("list of both windings: the counter restarts at each triangle, factor 1, 0x0f0f",
             ccw(6, 6, 50, 40) + cw(62, 6, 50, 40, 2.5) + ccw(6, 52, 30, 50, 3.0), rainbow(9), **st(1, 0x0F0F)),
        draw("strip, width 2, factor 2, 0x3c5a", strip(120, 8, 26, 36, 8, 2.0, 3.5), rainbow(8, 2),
             **st(2, 0x3C5A, topology="triangle_strip", line_width=2.0)),
        draw("fan, factor 3, 0x00ff, provoking vertex last", fan(200, 110, 40, 7, 2.5), rainbow(8, 4),
             shading="vertex_color_flat", provoking_vertex="last", **st(3, 0x00FF, topology="triangle_fan")),
        # Clipping cuts these into fans: the counter restarts at a fan's first triangle only and runs on
        # through the rest of its edges.
        draw("clipped by the near plane and the sides, factor 1, 0x1fe3",
             [[-1.2, 0.2, -0.5], [-0.2, 0.9, 3.0], [-1.4, 0.9, 2.0], [-0.3, 0.25, 1.0], [-0.6, 0.3, -1.0],
              [0.1, 0.8, 2.5]], rainbow(6, 5), **st(1, 0x1FE3)),
        draw("clipped by the sides, flat, width 1.5, factor 2, 0xa5f1",
             [[1.0, -0.2, 2.0], [1.6, 0.4, 2.0], [0.7, 0.1, 2.0], [1.9, 0.8, 2.0], [0.8, 0.6, 2.0],
              [2.2, 0.95, 2.0]], rainbow(6, 2), shading="vertex_color_flat",
             **st(2, 0xA5F1, topology="triangle_strip", line_width=1.5)),
        draw("depth-biased, over the first triangle, factor 1, 0x3333",
             [at(10, 10, 2.6), at(14, 44, 2.6), at(54, 12, 2.6)], rainbow(3, 3),
             depth_bias={"constant": 2000, "slope": 1.5, "clamp": 0}, **st(1, 0x3333)),
        draw("point mode: the stipple leaves points alone", ccw(60, 120, 60, 60, 2.0), rainbow(3, 6),
             point_size=3.0, **st(1, 0x0001, polygon_mode="point")),
    ]
    scene(filename, f"Stippled {label} polygon-mode lines: Mesa's unfilled stage hands each triangle's edges "
          "(v2-v0, v0-v1, v1-v2, those its edge flags keep) to the stipple stage, resetting the counter at every "
          "triangle of the draw and, of a triangle clipping cut into a fan, at the fan's first triangle only, so the "
          "counter runs on through the fan's edges; a list of both windings, a wide strip, a flat fan with provoking "
          "vertex last, triangles clipped by the near plane and the sides, depth bias, and polygon mode point, "
          "which the stipple leaves alone.", draws)


stipple_polygon_scene("line_stipple_polygon_modes.json", "rectangular", "rectangular")
stipple_polygon_scene("line_stipple_polygon_modes_bresenham.json", "bresenham", "Bresenham")

# ---- 5. adjacency topologies ----
def adjacent_list(x, y, n, z):
    """Triangles with adjacency: each triangle's vertices at even places, adjacency (far off) at odd places."""
    pts = []
    for k in range(n):
        tri = ccw(x + 30 * k, y, 26, 34, z) if k % 2 == 0 else cw(x + 30 * k, y, 26, 34, z)
        for v in tri:
            pts += [v, at(240, 150, 1.0)]  # an adjacency vertex: in view, far from the triangles
    return pts

draws = [
    draw("triangle list with adjacency", adjacent_list(6, 6, 4, 2.0), rainbow(24), topology="triangle_list_with_adjacency",
         cull="back"),
    draw("triangle strip with adjacency", [at(6 + 12 * (i // 2), 60 + (36 if (i // 2) % 2 else 0), 2.0) if i % 2 == 0
                                           else at(250, 10, 1.0) for i in range(18)], rainbow(18, 2),
         topology="triangle_strip_with_adjacency", cull="back"),
    draw("triangle strip with adjacency, flat, provoking last", [at(136 + 12 * (i // 2), 60 + (36 if (i // 2) % 2 else 0), 2.5)
                                                                 if i % 2 == 0 else at(20, 180, 1.0) for i in range(20)],
         rainbow(20, 5), topology="triangle_strip_with_adjacency", cull="none", shading="vertex_color_flat",
         provoking_vertex="last"),
    draw("line list with adjacency", [at(250, 100, 1.0) if k % 4 in (0, 3) else at(10 + 14 * k, 110 + (20 if k % 4 == 2 else 0), 2.0)
                                      for k in range(16)], rainbow(16, 1), topology="line_list_with_adjacency",
         line_width=2.0),
    draw("line strip with adjacency, flat", [at(10 + 20 * k, 150 + (18 if k % 2 else 0), 2.0) for k in range(12)],
         rainbow(12, 3), topology="line_strip_with_adjacency", shading="vertex_color_flat", line_width=2.0),
    draw("triangle list with adjacency, indexed", [at(150, 120, 2.0), at(200, 185, 2.0), at(240, 120, 2.0),
                                                   at(5, 5, 1.0)], rainbow(4, 6),
         topology="triangle_list_with_adjacency", cull="none", indices=[0, 3, 1, 3, 2, 3]),
]
scene("adjacency.json", "Adjacency topologies without a geometry shader: the adjacent vertices are ignored for "
      "rasterization (they lie in view, far from the primitives, and would cover much if drawn). Triangle list with adjacency (vertices 0, 2, "
      "4 of each six) with back-face culling; triangle strip with adjacency (vertices 2i, 2i+2, 2i+4, odd triangles "
      "reordered) culled, and with a flat varying and provoking vertex last; line list with adjacency (vertices 1, 2 "
      "of each four); line strip with adjacency (its first and last vertex adjacency only) with a flat varying; an "
      "indexed list with adjacency.", draws)
