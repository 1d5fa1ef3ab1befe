#!/usr/bin/env python3
"""Writes the feature and stability scenes of the conformance suite (one JSON file each).
Geometry is laid out in pixels and unprojected through the scenes' pinhole camera (at the origin,
looking along +z, y down, focal length F), so each scene's layout is easy to reason about.
Run from scenes/:  python3 tools/make_feature_scenes.py"""
import math
import random

from scene_layout import FRAMEBUFFER, F, PALETTE, at, ccw, cw, draw, fan, rainbow, scene, strip

draws = []
for row, front in enumerate(["counter_clockwise", "clockwise"]):
    for col, cull in enumerate(["none", "front", "back", "front_and_back"]):
        x, y = col * 64 + 4, row * 96 + 8
        draws.append(draw(f"{cull}/{front}", ccw(x, y, 26, 80) + cw(x + 30, y, 26, 80),
                          rainbow(6, col + 4 * row), cull=cull, front_face=front))
scene("culling.json", "Back-face culling: none, front, back and front_and_back, each with counter-clockwise and "
      "clockwise front faces; every cell holds one counter-clockwise (left) and one clockwise (right) triangle.",
      draws)

# ---- topologies: lists, strips and fans, indexed and not ----
list_pts = ccw(8, 8, 40, 40, 2.5) + ccw(56, 8, 40, 40, 1.5) + cw(104, 8, 40, 40, 2)
strip_pts = strip(8, 60, 30, 50, 10, 1.5, 3.0)
fan_pts = fan(200, 48, 40, 9, 2.2)
draws = [
    draw("list non-indexed", list_pts, rainbow(9), cull="none"),
    draw("strip non-indexed", strip_pts, rainbow(10, 2), topology="triangle_strip"),
    draw("strip indexed", strip(8, 125, 30, 50, 10, 3.0, 1.5), rainbow(10, 3), topology="triangle_strip",
         indices=list(range(10))),
    draw("fan non-indexed", fan_pts, rainbow(10, 1), topology="triangle_fan"),
    draw("fan indexed", fan(200, 140, 40, 9, 2.6), rainbow(10, 5), topology="triangle_fan",
         indices=[0] + list(range(1, 10))),
]
scene("topologies.json", "Primitive topologies: triangle list, strip and fan, indexed and non-indexed, with "
      "back-face culling on strips and fans (their alternate triangles keep a consistent winding) and per-vertex "
      "colours (the provoking vertex and vertex order of every assembled triangle).", draws)

# ---- viewport and scissor ----
big = [at(-100, -100, 2), at(-100, 400, 3), at(400, -100, 2.5)]
draws = [
    draw("viewport", big, rainbow(3), cull="none",
         viewport={"x": 20.25, "y": 30.5, "width": 120, "height": 90, "min_depth": 0.25, "max_depth": 0.75}),
    draw("scissor", [at(-50, -50, 4), at(-50, 300, 4), at(350, 100, 2)], rainbow(3, 3), cull="none",
         scissor={"x": 150, "y": 100, "width": 80, "height": 60}),
    draw("viewport flipped depth", [at(160, 10, 2), at(160, 90, 6), at(250, 10, 3)], rainbow(3, 5), cull="none",
         viewport={"x": 128, "y": 0, "width": 128, "height": 96, "min_depth": 0.9, "max_depth": 0.1}),
]
scene("viewport_scissor.json", "Viewport with a fractional offset, a size smaller than the framebuffer and a depth "
      "range [0.25, 0.75]; a reversed depth range [0.9, 0.1]; a scissor rectangle. Geometry reaches beyond the "
      "viewport, so clipping against x and y sets the visible edges.", draws)

# ---- depth formats: interpenetrating triangles, an intersection line, clear value tests ----
def depth_scene(filename, fmt, unit, label):
    draws = [
        draw("slanted A", [at(10, 20, 1.0), at(10, 180, 6.0), at(240, 100, 1.5)], rainbow(3, 0)),
        draw("slanted B", [at(240, 20, 6.0), at(30, 100, 1.2), at(240, 180, 1.0)], rainbow(3, 2)),
        draw("beyond the clear depth", [at(100, 5, 15), at(100, 60, 15), at(200, 5, 15)], rainbow(3, 4)),
    ]
    fb = dict(FRAMEBUFFER, depth_format=fmt, clear_depth=0.97)
    scene(filename, f"Depth format {label}: two interpenetrating slanted triangles (their intersection line is "
          f"decided by the format's precision) and a triangle behind the clear depth 0.97, which must not show.",
          draws, framebuffer=fb, tolerance={"depth": unit})

depth_scene("depth_d16.json", "d16_unorm", 1.5259022e-05, "D16_UNORM")
depth_scene("depth_x8_d24.json", "x8_d24_unorm", 5.9604649e-08, "X8_D24_UNORM_PACK32")
depth_scene("depth_d32.json", "d32_sfloat", 5.9604645e-08, "D32_SFLOAT")

# ---- depth compare ops and depth writes ----
background = [at(0, 0, 2), at(0, 192, 2), at(256, 0, 4), at(256, 192, 4)]
bg = draw("background", background, [[0.3, 0.3, 0.3]] * 4, topology="triangle_strip")
draws = [bg]
ops = ["never", "less", "equal", "less_or_equal", "greater", "not_equal", "greater_or_equal", "always"]
for i, op in enumerate(ops):
    y = 4 + i * 23
    band = [at(0, y, 4), at(0, y + 20, 4), at(256, y, 2), at(256, y + 20, 2)]
    draws.append(draw(f"compare {op}", band, [PALETTE[i]] * 4, topology="triangle_strip", depth_compare=op,
                      depth_write=(i % 2 == 0)))
draws.append(draw("equal on the same plane", background[:3], [[1, 1, 1]] * 3, depth_compare="equal",
                  depth_write=False))
draws.append(draw("no depth test", ccw(200, 150, 40, 30, 10), rainbow(3), depth_test=False))
scene("depth_compare.json", "Every depth compare op against a background whose depth runs across the image, with "
      "depth writes alternately on and off; a coplanar copy of the background drawn with EQUAL (passes only where "
      "both interpolate to the same bits); a triangle with the depth test off.", draws,
      framebuffer=dict(FRAMEBUFFER, clear_depth=0.995))

# ---- depth clamp versus depth clip ----
draws = [
    draw("crosses near, clamped", [at(20, 20, 0.2), at(20, 170, 3), at(120, 60, 0.3)], rainbow(3), cull="none",
         depth_clamp=True, viewport={"x": 0, "y": 0, "width": 256, "height": 192, "min_depth": 0.1,
                                     "max_depth": 0.9}),
    draw("crosses far, clamped", [at(130, 20, 40), at(130, 170, 5), at(250, 90, 60)], rainbow(3, 3), cull="none",
         depth_clamp=True),
    draw("crosses near, clipped", [at(140, 120, 0.2), at(250, 180, 3), at(250, 120, 0.25)], rainbow(3, 6),
         cull="none"),
]
scene("depth_clamp.json", "Depth clamp against depth clip: triangles crossing the near and the far plane with "
      "depthClampEnable (no z clipping, depth clamped to the viewport's range [0.1, 0.9]) and one without it.",
      draws)

# ---- interpolation qualifiers: the course's perspective floor ----
floor_camera = {"type": "pinhole", "position": [0, -1, 0], "pitch": -25, "focal_length": F, "near": 0.1, "far": 30}

def floor_strip(x0, x1, z0, z1, rows):
    pts, cols = [], []
    for r in range(rows + 1):
        z = z0 + (z1 - z0) * r / rows
        pts += [[x0, 0, z], [x1, 0, z]]
        c = [1, 1, 1] if r % 2 == 0 else [0.1, 0.1, 0.6]
        cols += [c, [1 - c[0], c[1] * 0.5, 1 - c[2]]]
    return pts, cols

draws = []
for i, (shading, x0) in enumerate([("vertex_color", -3.2), ("vertex_color_noperspective", -1.0),
                                   ("vertex_color_flat", 1.2)]):
    pts, cols = floor_strip(x0, x0 + 2.0, -0.5, 12, 6)
    draws.append(draw(shading, pts, cols, topology="triangle_strip", cull="none", shading=shading))
scene("interpolation.json", "Varying interpolation on a floor receding from the camera and reaching behind it "
      "(the near plane clips it): perspective-correct (left), noperspective (middle: the course's skewed 'not "
      "perspective-correct' figure) and flat (right, the provoking vertex's colour).", draws, camera=floor_camera)

# ---- stability ----
scene("near_plane_triangle.json", "A triangle crossing the near plane: one vertex behind the camera, two in "
      "front. Clipping must produce the same quad in both renderers.",
      [draw("crossing", [[0.0, -0.2, -1.0], [-1.5, 0.8, 3.0], [1.5, 0.8, 3.0]], rainbow(3), cull="none")])

scene("behind_camera.json", "A triangle entirely behind the camera (dropped by clipping, never drawn mirrored) and "
      "a visible reference triangle.",
      [draw("behind", [[-1, -1, -2], [1, -1, -2], [0, 1, -3]], rainbow(3), cull="none"),
       draw("reference", ccw(60, 50, 120, 90, 3), rainbow(3, 4))])

scene("w_zero.json", "Vertices with w = 0: one on the camera plane off-centre and one exactly at the camera "
      "position; the triangles that use them are clipped, not divided by zero.",
      [draw("w0 off-centre", [[0.5, 0.2, 0.0], [-1.0, 0.5, 3.0], [1.0, -0.5, 2.0]], rainbow(3), cull="none"),
       draw("w0 at the eye", [[0.0, 0.0, 0.0], [-1.0, 1.0, 4.0], [1.5, 0.8, 4.0]], rainbow(3, 3), cull="none")])

scene("huge_coordinates.json", "Vertices far outside the view (1e6, 1e7, 1e30 and a vertex behind the camera at "
      "1e6): clipping must keep the visible part exact without overflowing the fixed-point rasterizer.",
      [draw("1e6", [[-1e6, -1e6, 5.0], [0.5, 0.8, 3.0], [1e6, -0.5, 4.0]], rainbow(3), cull="none"),
       draw("1e7 and 1e30", [[1e7, 1e7, 2.0], [-0.8, 0.2, 2.5], [-1e30, 0.4, 3.0]], rainbow(3, 2), cull="none"),
       draw("behind at 1e6", [[0.0, 0.0, -1e6], [-0.6, -0.6, 2.0], [0.6, -0.7, 2.5]], rainbow(3, 5), cull="none")])

scene("z_fighting.json", "Two coplanar overlapping triangles (z-fighting): the second, drawn with LESS, loses "
      "where its depth equals the first's and wins only where rounding makes it nearer; with LESS_OR_EQUAL it wins "
      "ties. Both renderers must pick the same winner at every pixel.",
      [draw("first", [at(20, 20, 2.0), at(20, 170, 5.0), at(230, 60, 3.0)], [[0.9, 0.2, 0.2]] * 3),
       draw("second, less", [at(230, 170, 4.0), at(230, 60, 3.0), at(20, 170, 5.0)][::-1], [[0.2, 0.2, 0.9]] * 3),
       draw("third, less_or_equal", [at(20, 20, 2.0), at(20, 170, 5.0), at(125, 40, 2.5)], [[0.2, 0.9, 0.2]] * 3,
            depth_compare="less_or_equal")])

scene("nan_inf.json", "Vertices with NaN, +Inf and -Inf coordinates: no crash; each triangle using one is dropped "
      "as lavapipe drops it. A reference triangle shows the frame is drawn.",
      [draw("nan", [["nan", 0.0, 2.0], [-1.0, 0.5, 3.0], [1.0, -0.5, 2.0]], rainbow(3), cull="none"),
       draw("inf", [[0.2, "inf", 2.0], [-1.0, 0.5, 3.0], [1.0, -0.5, 2.0]], rainbow(3, 2), cull="none"),
       draw("-inf depth", [[0.2, 0.1, "-inf"], [-1.0, 0.5, 3.0], [1.0, -0.5, 2.0]], rainbow(3, 4), cull="none"),
       draw("reference", ccw(150, 100, 80, 60, 3), rainbow(3, 6))])

# Slivers, needles, sub-pixel and zero-area triangles; the second draw shares its batch with a
# triangle that clips, so lavapipe's float-determinant cull stage sees all of them too.
rng = random.Random(7)
def sliver_set(offset_x):
    pts = []
    for i in range(120):
        x, y = rng.uniform(4, 124) + offset_x, rng.uniform(4, 188)
        kind = i % 4
        if kind == 0:    # needle: long and a fraction of a pixel wide
            a = rng.uniform(0, math.pi)
            l, wdt = rng.uniform(20, 90), rng.uniform(0.01, 0.6)
            dx, dy = math.cos(a) * l, math.sin(a) * l
            tri = [(x, y), (x + dx, y + dy), (x + dx - math.sin(a) * wdt, y + dy + math.cos(a) * wdt)]
        elif kind == 1:  # sliver: nearly collinear
            dx, dy = rng.uniform(-40, 40), rng.uniform(-40, 40)
            t, off = rng.uniform(0.2, 0.8), rng.uniform(-0.02, 0.02)
            tri = [(x, y), (x + dx, y + dy), (x + t * dx - off * dy, y + t * dy + off * dx)]
        elif kind == 2:  # sub-pixel
            tri = [(x, y), (x + rng.uniform(-0.9, 0.9), y + rng.uniform(-0.9, 0.9)),
                   (x + rng.uniform(-0.9, 0.9), y + rng.uniform(-0.9, 0.9))]
        else:            # zero area: collinear or repeated vertices
            dx, dy = rng.uniform(-30, 30), rng.uniform(-30, 30)
            tri = [(x, y), (x + dx, y + dy), (x + 2 * dx, y + 2 * dy)] if i % 8 == 3 else [(x, y), (x, y),
                                                                                          (x + dx, y + dy)]
        z = rng.uniform(1.5, 6)
        pts += [at(px, py, z + rng.uniform(-0.3, 0.3)) for px, py in tri]
    return pts

inside = sliver_set(0)
clipped = sliver_set(128) + [[0.0, 0.0, -1.0], [2.0, 1.0, 3.0], [2.5, -1.0, 3.0]]
scene("slivers.json", "Sliver, needle, sub-pixel and zero-area triangles with back-face culling. The right half's "
      "draw also holds a triangle that clips, so its whole batch goes through lavapipe's draw pipeline and its "
      "float-determinant cull stage before the fixed-point setup.",
      [draw("inside", inside, rainbow(len(inside))), draw("batch with clipping", clipped, rainbow(len(clipped), 3))])

# The room seen from inside, turned: the course's reports show garbage here without clipping.
for yaw in (90, 180):
    scene(f"room_yaw_{yaw}.json", f"The room with two boxes seen from inside with the camera turned {yaw} degrees: "
          "walls pass behind and beside the camera and must be clipped, not wrapped around.",
          [{"name": "cornell_box", "obj": "meshes/cornell_box.obj", "cull": "back"}],
          framebuffer={"width": 320, "height": 240, "clear_colour": [0, 0, 0, 1]},
          camera={"type": "pinhole", "position": [0.1, -0.2, -0.3], "yaw": yaw, "pitch": -10, "focal_length": 120,
                  "near": 0.05, "far": 10})

# ---- depth bias: constant and slope, clamped, on every depth format ----
def bias_scene(filename, fmt, unit, label):
    plane = lambda x, y: [x, y, round(3.0 + 0.4 * x + 0.6 * y, 6)]  # one world-space plane
    quad = lambda y0, y1: [plane(-1.25, y0), plane(-1.25, y1), plane(1.25, y0), plane(1.25, y1)]
    draws = [draw("base", quad(-0.95, 0.95), [[0.5, 0.5, 0.5]] * 4, topology="triangle_strip")]
    for i, (const, slope, clamp) in enumerate([(1, 0, 0), (-4, 0, 0), (0, 1.0, 0), (0, -1.0, 0), (200, 2.0, 0.0001),
                                               (-200, -2.0, -0.0001)]):
        y = -0.9 + i * 0.3
        # The band lies in the base's plane: only the bias decides which of the two is nearer.
        draws.append(draw(f"bias {const}/{slope}/{clamp}", quad(y, y + 0.22), [PALETTE[i]] * 4,
                          topology="triangle_strip", depth_bias={"constant": const, "slope": slope, "clamp": clamp}))
    draws.append(draw("steep", [at(120, 20, 1.0), at(130, 180, 9.0), at(140, 20, 1.2)], rainbow(3), cull="none",
                      depth_bias={"constant": 3, "slope": 4.0}))
    scene(filename, f"Depth bias on {label}: bands lying in the plane of a base surface, pushed towards or away "
          "from the camera by constant and slope factors, with and without a clamp; a steep triangle with a large "
          "slope factor.", draws, framebuffer=dict(FRAMEBUFFER, depth_format=fmt), tolerance={"depth": unit})

bias_scene("depth_bias_d16.json", "d16_unorm", 1.5259022e-05, "D16_UNORM")
bias_scene("depth_bias_d32.json", "d32_sfloat", 5.9604645e-08, "D32_SFLOAT")

# ---- lines ----
def star(cx, cy, r0, r1, n, z0, z1):
    pts = []
    for k in range(n):
        a = 2 * math.pi * (k + 0.13) / n
        pts += [at(cx + r0 * math.cos(a), cy + r0 * math.sin(a), z0), at(cx + r1 * math.cos(a), cy + r1 * math.sin(a), z1)]
    return pts

def line_scene(filename, mode, label):
    draws = [
        draw("star width 1", star(60, 55, 6, 50, 24, 2.0, 3.0), rainbow(48), topology="line_list",
             line_rasterization=mode),
        draw("star width 3", star(190, 55, 8, 50, 12, 3.0, 2.0), rainbow(24, 2), topology="line_list",
             line_width=3.0, line_rasterization=mode),
        draw("strip width 2.5", [at(10 + 236 * k / 11, 120 + (25 if k % 2 else -10) + k * 1.37, 2 + 0.2 * k)
                                 for k in range(12)], rainbow(12, 4), topology="line_strip", line_width=2.5,
             line_rasterization=mode),
        draw("clipped", [[0.0, 0.3, -1.0], [0.5, 0.45, 3.0], [-3.0, 0.6, 2.0], [3.0, 0.7, 2.0]], rainbow(4, 1),
             topology="line_list", line_width=1.5, line_rasterization=mode),
        draw("axis aligned on pixel centres", [at(20.5, 180.5, 2), at(120.5, 180.5, 2), at(140.5, 100.5, 2),
                                               at(140.5, 188.5, 2)], rainbow(4, 6), topology="line_list",
             line_rasterization=mode),
    ]
    scene(filename, f"{label} lines: a star of width-1 and width-3 lines in every direction, a wide line strip, "
          "lines clipped by the near plane and the sides of the view, and axis-aligned lines through pixel "
          "centres (where the fill rule decides the end pixels).", draws)

line_scene("lines.json", "rectangular", "Rectangular (Vulkan's default, strictLines)")
line_scene("lines_bresenham.json", "bresenham", "Bresenham (VK_EXT_line_rasterization, diamond-exit)")

# ---- points ----
pts, sizes = [], []
draws = []
for i, size in enumerate([1.0, 1.5, 2.0, 3.25, 8.0, 20.5]):
    p = [at(14 + 40 * i + 0.37 * j, 20 + 27 * j + 0.21 * i, 2 + 0.3 * j) for j in range(6)]
    draws.append(draw(f"size {size}", p, rainbow(6, i), topology="point_list", point_size=size))
draws.append(draw("near the edges", [at(-3, 80, 2), at(258, 120, 2), at(128, -2, 2), at(128, 193.5, 2),
                                     [0, 0, -1.0], [0, 0, 0.1], [0.2, 0.2, 25.0]], rainbow(7, 3),
                  topology="point_list", point_size=12.0))
scene("points.json", "Points of sizes 1 to 20.5 written by the vertex shader (gl_PointSize), at sub-pixel "
      "positions; large points whose centres lie outside the view (drawn in part: points are not clipped against "
      "x and y) and points behind the camera or beyond the near and far planes (dropped).", draws)

# ---- polygon modes: wireframe and vertex dots of a mesh, clipped by the camera inside it ----
room_camera = {"type": "pinhole", "position": [0, -0.45, -0.98], "pitch": -20, "focal_length": 120, "near": 0.05,
               "far": 10}
room_fb = {"width": 320, "height": 240, "clear_colour": [0, 0, 0, 1]}
scene("room_wireframe.json", "Polygon mode LINE: the room with two boxes as a wireframe (2-pixel lines), camera "
      "inside the room so walls are clipped; edges created along the frustum planes must not be drawn, edges of the "
      "original triangles must be drawn once per triangle, back faces culled by the draw pipeline's float "
      "determinant.", [{"name": "cornell_box", "obj": "meshes/cornell_box.obj", "cull": "back",
                        "polygon_mode": "line", "line_width": 2.0}], framebuffer=room_fb, camera=room_camera)
scene("room_points.json", "Polygon mode POINT: the vertices of the room with two boxes as 5-pixel dots, "
      "including the vertices clipping creates where an edge comes back into the view (but not where one leaves "
      "it, as Mesa's edge flags decide).",
      [{"name": "cornell_box", "obj": "meshes/cornell_box.obj", "cull": "none", "polygon_mode": "point",
        "point_size": 5.0}], framebuffer=room_fb, camera=room_camera)
scene("polygon_mode_strips.json", "Polygon mode LINE on triangle strips and fans (every internal edge drawn by "
      "both of its triangles) and POINT on a list, with a flat varying: all lines and points of a triangle take "
      "its provoking vertex's colour.",
      [draw("strip lines", strip(8, 20, 30, 60, 12, 1.5, 3.0), rainbow(12), topology="triangle_strip",
            polygon_mode="line", cull="none", shading="vertex_color_flat"),
       draw("fan lines", fan(190, 130, 50, 9, 2.2), rainbow(10, 2), topology="triangle_fan", polygon_mode="line",
            cull="none", line_width=1.5),
       draw("list points", ccw(20, 110, 60, 60, 2) + cw(100, 110, 50, 70, 3), rainbow(6, 4), polygon_mode="point",
            cull="none", point_size=4.0)])

# ---- how lavapipe clips in polygon modes (measured, see the description) ----
def quadrant(i):
    return {"x": 64 * (i % 2), "y": 64 * (i // 2), "width": 64, "height": 64}

q = lambda x, y, z=0.5: [x, y, z]
scene("polygon_mode_clipping.json", "Clipping in polygon modes, one draw per quadrant (clip_space camera): point "
      "mode with a vertex at 1.5w (lavapipe keeps it: its 40-pixel point shows at the quadrant's edge) and one "
      "at 2.5w (moved to the guard band at 2w, its colour blended); point mode with a vertex behind the near plane "
      "(the point where the edge comes back in is drawn); line mode with 6-pixel lines through the quadrant's "
      "edge (clipped at w: the order of the lines at the shared vertex shows it). Every primitive is scissored to "
      "its viewport.",
      [draw("point mode, 1.5w", [q(-0.5, -0.5), q(1.5, 0.0, 0.2), q(-0.5, 0.5)], rainbow(3), cull="none",
            polygon_mode="point", point_size=40.0, viewport=quadrant(0)),
       draw("point mode, 2.5w", [q(-0.5, -0.5), q(2.5, 0.0, 0.2), q(-0.5, 0.5)], rainbow(3, 2), cull="none",
            polygon_mode="point", point_size=60.0, viewport=quadrant(1)),
       draw("point mode, near plane", [q(-0.5, -0.5), q(0.5, 0.0, -0.5), q(-0.5, 0.5)], rainbow(3, 4), cull="none",
            polygon_mode="point", point_size=6.0, viewport=quadrant(2)),
       draw("line mode, thick", [q(-0.5, -0.5), q(1.5, 0.2), q(-0.5, 0.5)], rainbow(3, 6), cull="none",
            polygon_mode="line", line_width=6.0, viewport=quadrant(3))],
      framebuffer={"width": 128, "height": 128, "clear_colour": [0, 0, 0, 1]}, camera={"type": "clip_space"})

# ---- camera models of the course material ----
room_draw = [{"name": "cornell_box", "obj": "meshes/cornell_box.obj", "cull": "back"}]
scene("camera_pinhole_outside.json", "The course's pinhole camera outside the room: at (0, 0, -3.001) looking along "
      "+z at the origin, focal length equal to the image height (500 px at 500x500), near 0.1, far 10.",
      room_draw, framebuffer={"width": 500, "height": 500, "clear_colour": [0, 0, 0, 1]},
      camera={"type": "pinhole", "position": [0, 0, -3.001], "focal_length": 500, "near": 0.1, "far": 10})
scene("camera_look_at.json", "A look-at camera with vertical field of view 70 degrees, aspect 4:3, near 0.2 and far "
      "8, from above and to the side of the room, up along -y (the scene's y points down).", room_draw,
      framebuffer={"width": 320, "height": 240, "clear_colour": [0, 0, 0, 1]},
      camera={"type": "look_at", "eye": [0.7, -0.6, -0.9], "target": [0.0, 0.5, 0.5], "up": [0, -1, 0], "fov_y": 70,
              "aspect": 4 / 3, "near": 0.2, "far": 8})
scene("camera_yaw_pitch.json", "A pinhole camera inside the room turned with yaw -35 and pitch 15 degrees (the "
      "command line can turn any camera: --set camera.yaw=90).", room_draw,
      framebuffer={"width": 320, "height": 240, "clear_colour": [0, 0, 0, 1]},
      camera={"type": "pinhole", "position": [0.2, 0.3, -0.5], "yaw": -35, "pitch": 15, "focal_length": 140,
              "near": 0.05, "far": 10})

# ---- a closed mesh covers every pixel inside its silhouette exactly once ----
scene("sphere_coverage.json", "A closed sphere of 9800 triangles with back faces culled, depth test off and "
      "additive blending of 1/255 per fragment: every pixel's red channel counts the fragments that hit it, and "
      "must be exactly 1 inside the silhouette (no cracks, no double hits on shared edges) in both renderers.",
      [{"name": "sphere", "obj": "meshes/sphere.obj", "colour": [1 / 255, 1 / 255, 1 / 255, 1 / 255],
        "cull": "back", "depth_test": False, "blend": {"source": "one", "destination": "one"}}],
      framebuffer={"width": 256, "height": 256, "clear_colour": [0, 0, 0, 0]},
      camera={"type": "pinhole", "position": [0.013, -0.021, -3.2], "yaw": 1.3, "pitch": -0.7, "focal_length": 300,
              "near": 0.5, "far": 10})

# ---- 4x MSAA ----
msaa_fb = {"width": 160, "height": 120, "clear_colour": [0.1, 0.1, 0.1, 1], "samples": 4}
scene("msaa_room.json", "4x MSAA on the room with two boxes: coverage and depth per sample at Vulkan's standard "
      "positions, one shading per pixel, colour resolved by averaging (as lavapipe's resolve blit: float sum in "
      "sample order times 0.25); colour and depth compared on every sample and colour also after the resolve.",
      [{"name": "cornell_box", "obj": "meshes/cornell_box.obj", "cull": "back"}], framebuffer=msaa_fb,
      camera={"type": "pinhole", "position": [0, -0.45, -0.98], "pitch": -20, "focal_length": 60, "near": 0.05,
              "far": 10})
scene("msaa_triangles.json", "4x MSAA on thin, intersecting and overlapping triangles with per-vertex colours: edge "
      "pixels with 1, 2 or 3 covered samples, intersection lines resolved per sample by depth, a sub-pixel triangle "
      "that covers a sample without covering the pixel centre.",
      [draw("slanted A", [at(10, 20, 1.0), at(10, 180, 6.0), at(240, 100, 1.5)], rainbow(3)),
       draw("slanted B", [at(240, 20, 6.0), at(30, 100, 1.2), at(240, 180, 1.0)], rainbow(3, 2)),
       draw("needle", [at(20, 5, 2), at(250, 12, 2), at(20, 6.2, 2)], rainbow(3, 4), cull="none"),
       draw("sub-pixel", [at(200.3, 150.05, 2), at(200.45, 150.05, 2), at(200.3, 150.2, 2)], [[1, 1, 1]] * 3,
            cull="none")],
      framebuffer=dict(FRAMEBUFFER, samples=4))
