#!/usr/bin/env python3
"""Writes the stencil scenes (scenes/stencil_*.json) and the depth bias scene for polygon modes
line and point (scenes/depth_bias_polygon_modes.json).

Every scene uses the clip_space camera (positions are clip coordinates with w = 1, so z is the
depth) and the vertex_color model; cells are laid out on a grid of whole pixels. Run from the
repository root: python3 scenes/tools/make_stencil_scenes.py
"""
import json
import os

OUT = os.path.join(os.path.dirname(__file__), "..")

OPS = ["keep", "zero", "replace", "increment_and_clamp", "decrement_and_clamp", "invert",
       "increment_and_wrap", "decrement_and_wrap"]
COMPARES = ["never", "less", "equal", "less_or_equal", "greater", "not_equal", "greater_or_equal", "always"]


def clip(px, size):
    """Pixel coordinate (edge) to clip coordinate."""
    return round(2.0 * px / size - 1.0, 6)


def quad(name, x0, y0, x1, y1, w, h, z, colour, **state):
    """An axis-aligned rectangle of pixels [x0, x1) x [y0, y1) at depth z."""
    d = {"name": name,
         "positions": [[clip(x0, w), clip(y0, h), z], [clip(x1, w), clip(y0, h), z],
                       [clip(x0, w), clip(y1, h), z], [clip(x1, w), clip(y1, h), z]],
         "colour": colour, "indices": [0, 2, 1, 1, 2, 3], "cull": "none"}
    d.update(state)
    return d


def write(name, scene):
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")


def framebuffer(w, h, fmt="d24_unorm_s8_uint", **extra):
    fb = {"width": w, "height": h, "clear_colour": [0.05, 0.05, 0.05, 1], "depth_format": fmt}
    fb.update(extra)
    return fb


def show_values(w, h, values, z=0.0):
    """Draws that colour every pixel by its stencil value (one full-screen quad per value, compare
    equal, no stencil writes, depth off): what a viewer sees of the stencil image."""
    draws = []
    for i, v in enumerate(values):
        r, g, b = ((v * 37) % 256) / 255.0, ((v * 91 + 64) % 256) / 255.0, ((v * 53 + 128) % 256) / 255.0
        draws.append(quad("show %d" % v, 0, 0, w, h, w, h, z, [round(r, 3), round(g, 3), round(b, 3), 1],
                          depth_test=False,
                          stencil={"compare_op": "equal", "reference": v, "write_mask": 0}))
    return draws


def stencil_ops():
    # Columns: the eight ops. Rows: for each path (stencil fail, depth fail, both pass) three
    # initial values (0, 0x5a, 255), so the clamped and wrapping ops meet both ends.
    w, h, cw, rh = 256, 288, 32, 32
    initial = [0, 0x5A, 255]
    draws = []
    for k, v in enumerate(initial):
        for path in range(3):
            y = (3 * path + k) * rh
            draws.append(quad("initial %d, path %d" % (v, path), 0, y, w, y + rh, w, h, 0.5, [0.25, 0.25, 0.25, 1],
                              depth_compare="always",
                              stencil={"compare_op": "always", "pass_op": "replace", "reference": v}))
    paths = [("stencil fails", "fail_op", {"compare_op": "never"}, 0.25),
             ("depth fails", "depth_fail_op", {"compare_op": "always"}, 0.75),
             ("both pass", "pass_op", {"compare_op": "always"}, 0.25)]
    for p, (label, key, extra, z) in enumerate(paths):
        for i, op in enumerate(OPS):
            s = {key: op, "reference": 0x3C}
            s.update(extra)
            colour = [0.2 + 0.1 * i, 0.9 - 0.1 * i, 0.3 + 0.2 * p, 1]
            draws.append(quad("%s: %s" % (label, op), i * cw + 2, 3 * p * rh + 2, (i + 1) * cw - 2, 3 * (p + 1) * rh - 2,
                              w, h, z, colour, stencil=s))
    write("stencil_ops", {
        "description": "Every VkStencilOp on each of its three paths: columns are keep, zero, replace (reference 0x3c), "
                       "increment_and_clamp, decrement_and_clamp, invert, increment_and_wrap, decrement_and_wrap; "
                       "the top three rows take the op as failOp (compare never), the middle three as depthFailOp "
                       "(the quad is behind the initial depth), the bottom three as passOp. Within each group the rows "
                       "start at stencil 0, 0x5a and 255, so the clamping and wrapping ops meet both ends of the 8 bits. "
                       "D24_UNORM_S8_UINT; stencil compared exactly.",
        "framebuffer": framebuffer(w, h),
        "camera": {"type": "clip_space"},
        "draws": draws,
    })


def stencil_compare():
    # Columns: the eight compare ops; rows: reference below, equal to and above the stored 0x80.
    # A passing fragment increments the stencil and draws green; a failing one inverts it.
    w, h, cw, rh = 256, 96, 32, 32
    draws = [quad("initial 0x80", 0, 0, w, h, w, h, 0.5, [0.2, 0.2, 0.2, 1], depth_test=False,
                  stencil={"compare_op": "always", "pass_op": "replace", "reference": 0x80})]
    for i, op in enumerate(COMPARES):
        for r, ref in enumerate([0x40, 0x80, 0xC0]):
            draws.append(quad("%s, reference 0x%x" % (op, ref), i * cw + 3, r * rh + 3, (i + 1) * cw - 3, (r + 1) * rh - 3,
                              w, h, 0.5, [0.1, 0.8, 0.2, 1], depth_test=False,
                              stencil={"compare_op": op, "reference": ref, "pass_op": "increment_and_wrap",
                                       "fail_op": "invert"}))
    write("stencil_compare", {
        "description": "Every stencil compare op (columns: never, less, equal, less_or_equal, greater, not_equal, "
                       "greater_or_equal, always) with the reference below, equal to and above the stored 0x80 (rows): "
                       "Vulkan compares reference OP stored. A passing fragment draws green and increments the stencil, "
                       "a failing one draws nothing and inverts it. D24_UNORM_S8_UINT.",
        "framebuffer": framebuffer(w, h),
        "camera": {"type": "clip_space"},
        "draws": draws,
    })


def stencil_front_back():
    # Two triangles per row, one of each winding, overlapping; top row front_face
    # counter_clockwise, bottom row clockwise. Front and back differ in every field.
    w, h = 256, 192
    front = {"compare_op": "always", "pass_op": "replace", "reference": 1, "write_mask": 0x0F}
    back = {"compare_op": "always", "pass_op": "replace", "reference": 0xE2, "write_mask": 0xF3}
    draws = [quad("initial 0x40", 0, 0, w, h, w, h, 0.5, [0.2, 0.2, 0.2, 1], depth_test=False,
                  stencil={"compare_op": "always", "pass_op": "replace", "reference": 0x40})]
    for row, face in enumerate(["counter_clockwise", "clockwise"]):
        y0, y1 = row * 96 + 8, row * 96 + 88
        a = [[clip(16, w), clip(y0, h), 0.5], [clip(150, w), clip(y1, h), 0.5], [clip(16, w), clip(y1, h), 0.5]]
        b = [[clip(100, w), clip(y0, h), 0.5], [clip(100, w), clip(y1, h), 0.5], [clip(240, w), clip(y0, h), 0.5]]
        draws.append({"name": "two windings, front face " + face, "positions": a + b,
                      "colours": [[0.9, 0.3, 0.2]] * 3 + [[0.2, 0.4, 0.9]] * 3,
                      "cull": "none", "front_face": face, "depth_test": False,
                      "stencil": {"front": front, "back": back}})
        # The second pass tests the faces differently: front passes where stencil has 0x01 in
        # its low bits, back where the high bits hold 0xe0 (compare masks), and each op differs.
        draws.append({"name": "second pass, front face " + face, "positions": a + b,
                      "colours": [[0.9, 0.9, 0.2]] * 3 + [[0.2, 0.9, 0.9]] * 3,
                      "cull": "none", "front_face": face, "depth_test": False,
                      "transform": {"translate": [0.05, 0.03, 0]},
                      "stencil": {"front": {"compare_op": "equal", "reference": 0x01, "compare_mask": 0x0F,
                                            "pass_op": "increment_and_clamp", "fail_op": "zero"},
                                  "back": {"compare_op": "equal", "reference": 0xE0, "compare_mask": 0xF0,
                                           "pass_op": "decrement_and_wrap", "fail_op": "invert"}}})
    write("stencil_front_back", {
        "description": "Front and back stencil state that differ in every field (ops, compare, masks, reference), on "
                       "triangles of both windings with front_face counter_clockwise (top row) and clockwise (bottom "
                       "row): each fragment must take its own triangle's face. A second, shifted pass tests the faces "
                       "with different compare masks and ops. D24_UNORM_S8_UINT.",
        "framebuffer": framebuffer(w, h),
        "camera": {"type": "clip_space"},
        "draws": draws,
    })


def stencil_masks():
    # Rows start at different stored values; columns combine compare and write masks.
    w, h, cw, rh = 256, 128, 32, 32
    initial = [0x00, 0x5A, 0xA5, 0xFF]
    cells = [  # (compare_mask, write_mask, compare, reference, pass_op, fail_op)
        (0xFF, 0xFF, "always", 0x3C, "replace", "keep"),
        (0x0F, 0xF0, "equal", 0x0A, "invert", "replace"),
        (0xF0, 0x0F, "equal", 0x50, "increment_and_wrap", "invert"),
        (0x3C, 0xFF, "less", 0x18, "decrement_and_wrap", "zero"),
        (0x00, 0x81, "equal", 0xFF, "invert", "keep"),
        (0xC3, 0x7E, "greater_or_equal", 0x81, "replace", "invert"),
        (0x01, 0x55, "not_equal", 0x00, "increment_and_clamp", "decrement_and_clamp"),
        (0x80, 0x00, "always", 0xFF, "zero", "zero"),
    ]
    draws = []
    for r, v in enumerate(initial):
        draws.append(quad("initial 0x%02x" % v, 0, r * rh, w, (r + 1) * rh, w, h, 0.5, [0.2, 0.2, 0.2, 1],
                          depth_test=False, stencil={"compare_op": "always", "pass_op": "replace", "reference": v}))
    for i, (cm, wm, cmp, ref, pas, fail) in enumerate(cells):
        draws.append(quad("compare mask 0x%02x, write mask 0x%02x" % (cm, wm), i * cw + 2, 2, (i + 1) * cw - 2, h - 2,
                          w, h, 0.5, [0.3 + 0.08 * i, 0.7, 0.9 - 0.1 * i, 1], depth_test=False,
                          stencil={"compare_mask": cm, "write_mask": wm, "compare_op": cmp, "reference": ref,
                                   "pass_op": pas, "fail_op": fail}))
    write("stencil_masks", {
        "description": "Compare masks and write masks: each column a (compare mask, write mask, compare, reference, "
                       "pass op, fail op) combination, each row a different stored value (0x00, 0x5a, 0xa5, 0xff). The "
                       "masked compare decides pass or fail per row; the write mask keeps the unwritten bits of the "
                       "stored value (a write mask of 0 writes nothing, a compare mask of 0 makes equal always pass). "
                       "D24_UNORM_S8_UINT.",
        "framebuffer": framebuffer(w, h),
        "camera": {"type": "clip_space"},
        "draws": draws,
    })


def stencil_d32s8():
    # Depth complexity counting on D32_SFLOAT_S8_UINT: interpenetrating slanted triangles with
    # depth testing; depth-fail increments, pass replaces with a per-draw reference.
    w, h = 256, 192
    draws = []
    tris = [
        ([[-0.9, -0.8, 0.2], [0.7, -0.5, 0.8], [-0.6, 0.9, 0.5]], [0.9, 0.2, 0.2]),
        ([[0.9, -0.9, 0.3], [0.2, 0.8, 0.3], [-0.8, -0.2, 0.9]], [0.2, 0.9, 0.2]),
        ([[-0.2, -0.95, 0.95], [0.95, 0.4, 0.1], [-0.95, 0.6, 0.4]], [0.2, 0.3, 0.9]),
        ([[-0.5, -0.5, 0.45], [0.5, -0.5, 0.45], [0.0, 0.6, 0.45]], [0.9, 0.9, 0.2]),
    ]
    for k, (pos, col) in enumerate(tris):
        draws.append({"name": "slanted %d" % k, "positions": pos, "colour": col, "cull": "none",
                      "stencil": {"compare_op": "not_equal", "reference": 16 * (k + 1), "compare_mask": 0xF0,
                                  "pass_op": "replace", "depth_fail_op": "increment_and_clamp",
                                  "fail_op": "decrement_and_wrap", "write_mask": 0xFF}})
    draws += show_values(w, h, [3, 7, 16, 32, 48, 64])
    write("stencil_d32s8", {
        "description": "D32_SFLOAT_S8_UINT: four interpenetrating slanted triangles with the depth test on; where the "
                       "depth test fails the stencil is incremented (depthFailOp increment_and_clamp), where both pass "
                       "it takes the draw's reference, where the masked stencil test fails it is decremented with wrap "
                       "(from the stencil clear 7). Then the stencil is shown as colour, one full-screen pass per value "
                       "with compare equal.",
        "framebuffer": framebuffer(w, h, "d32_sfloat_s8_uint", clear_stencil=7, clear_depth=1.0),
        "camera": {"type": "clip_space"},
        "draws": draws,
    })


def stencil_two_pass():
    # Pass 1 writes a star into the stencil only (colour write mask empty, depth off); pass 2
    # draws a colourful quad where the stencil equals 1, pass 3 another one where it does not.
    import math
    w, h = 256, 256
    star = [[0.0, 0.0, 0.5]]
    for i in range(11):
        r = 0.85 if i % 2 == 0 else 0.35
        a = math.pi * 2 * i / 10 - math.pi / 2
        star.append([round(r * math.cos(a), 6), round(r * math.sin(a), 6), 0.5])
    draws = [{"name": "star into the stencil", "positions": star, "topology": "triangle_fan", "cull": "none",
              "depth_test": False, "blend": {"enable": False, "write_mask": ""},
              "stencil": {"compare_op": "always", "pass_op": "replace", "reference": 1}},
             {"name": "inside: where equal 1", "positions": [[-1, -1, 0.5], [1, -1, 0.5], [-1, 1, 0.5], [1, 1, 0.5]],
              "colours": [[1, 0.2, 0.2], [0.2, 1, 0.2], [0.2, 0.2, 1], [1, 1, 0.2]], "indices": [0, 2, 1, 1, 2, 3],
              "cull": "none", "depth_test": False,
              "stencil": {"compare_op": "equal", "reference": 1, "write_mask": 0}},
             # A textured model is shaded in whole 2x2 quads: its helper lanes must leave the stencil alone.
             {"name": "inside, textured: where equal 1", "shading": "textured",
              "positions": [[-0.5, -0.45, 0.5], [0.45, -0.5, 0.5], [0.5, 0.45, 0.5], [-0.45, 0.5, 0.5]],
              "texcoords": [[0, 0], [2, 0], [2, 2], [0, 2]], "indices": [0, 1, 2, 0, 2, 3], "cull": "none",
              "depth_test": False, "texture": {"file": "textures/checker_64.png"},
              "stencil": {"compare_op": "equal", "reference": 1, "pass_op": "increment_and_clamp", "fail_op": "invert"}},
             {"name": "outside: where still 0", "positions": [[-1, -1, 0.5], [1, -1, 0.5], [-1, 1, 0.5], [1, 1, 0.5]],
              "colour": [0.15, 0.15, 0.3], "indices": [0, 2, 1, 1, 2, 3], "cull": "none", "depth_test": False,
              "stencil": {"compare_op": "equal", "reference": 0, "pass_op": "increment_and_clamp"}}]
    write("stencil_mask_two_pass", {
        "description": "The stencil as a mask, in two passes: a star is written into the stencil only (reference 1, "
                       "colour write mask empty, depth off), then a colourful quad is drawn where the stencil equals 1; "
                       "a textured quad (shaded in 2x2 quads, with helper pixels that must leave the stencil alone) "
                       "where it equals 1 too, incrementing it there and inverting it where it fails; then a dark quad "
                       "where the stencil is still 0, incrementing it. Edges of the star are exactly the star triangle "
                       "fan's coverage. D24_UNORM_S8_UINT.",
        "framebuffer": framebuffer(w, h),
        "camera": {"type": "clip_space"},
        "draws": draws,
    })


def stencil_msaa():
    w, h = 256, 192
    draws = []
    tris = [
        [[-0.93, -0.9, 0.3], [0.81, -0.62, 0.6], [-0.35, 0.91, 0.5]],
        [[0.95, -0.85, 0.5], [0.37, 0.93, 0.2], [-0.9, 0.13, 0.7]],
        [[-0.05, -0.97, 0.4], [0.98, 0.71, 0.4], [-0.97, 0.52, 0.4]],
    ]
    for k, pos in enumerate(tris):
        draws.append({"name": "slanted %d" % k, "positions": pos, "colour": [0.3 * (k + 1), 0.8 - 0.2 * k, 0.5],
                      "cull": "none",
                      "stencil": {"compare_op": "always", "pass_op": "increment_and_wrap",
                                  "depth_fail_op": "invert", "write_mask": 0x7F}})
    draws += show_values(w, h, [1, 2, 3, 0xFE, 0xFF])
    write("stencil_msaa", {
        "description": "Stencil with 4x MSAA: three slanted, interpenetrating triangles increment the stencil per "
                       "sample where they pass the depth test and invert it where they fail, so edge pixels hold "
                       "different values in different samples; then each value is shown as colour (compare equal, per "
                       "sample). Colour, depth and stencil are compared on every sample (read back before the resolve), "
                       "colour also after it. D24_UNORM_S8_UINT.",
        "framebuffer": framebuffer(w, h, samples=4),
        "camera": {"type": "clip_space"},
        "draws": draws,
    })


def stencil_polygon_modes():
    # Back-facing triangles drawn as lines and points, lines and points themselves: lavapipe
    # uses the front state for all of them (see docs/lavapipe-rules.md).
    w, h = 256, 128
    front = {"compare_op": "always", "pass_op": "replace", "reference": 0x11}
    back = {"compare_op": "always", "pass_op": "replace", "reference": 0x22}
    cw_tri = [[clip(20, w), clip(10, h), 0.5], [clip(20, w), clip(110, h), 0.5], [clip(110, w), clip(10, h), 0.5]]
    ccw_tri = [[clip(20, w), clip(10, h), 0.5], [clip(110, w), clip(10, h), 0.5], [clip(20, w), clip(110, h), 0.5]]
    draws = []
    for k, (mode, dx) in enumerate([("line", 0), ("point", 128)]):
        for j, tri in enumerate([cw_tri, ccw_tri]):
            pos = [[p[0] + clip(dx, w) + 1 + (0.3 if j else 0), p[1] + (0.05 if j else 0), p[2]] for p in tri]
            pos = [[round(x, 6), round(y, 6), z] for x, y, z in pos]
            draws.append({"name": "%s mode, winding %d" % (mode, j), "positions": pos, "colour": [0.9, 0.5 + 0.4 * j, 0.2],
                          "polygon_mode": mode, "cull": "none", "depth_test": False, "point_size": 3,
                          "stencil": {"front": front, "back": back}})
    draws.append({"name": "lines", "topology": "line_list", "depth_test": False,
                  "positions": [[-0.9, 0.8, 0.5], [0.9, 0.85, 0.5], [0.9, 0.9, 0.5], [-0.9, 0.95, 0.5]],
                  "colour": [0.3, 0.9, 0.3], "stencil": {"front": front, "back": back}})
    draws.append({"name": "points", "topology": "point_list", "depth_test": False, "point_size": 4,
                  "positions": [[-0.5, -0.95, 0.5], [0.0, -0.95, 0.5], [0.5, -0.95, 0.5]],
                  "colour": [0.3, 0.3, 0.9], "stencil": {"front": front, "back": back}})
    draws += show_values(w, h, [0x11, 0x22])
    write("stencil_polygon_modes", {
        "description": "Which stencil face lines and points take: triangles of both windings drawn in polygon mode line "
                       "(left) and point (right), then a line list and a point list, all with front state writing 0x11 "
                       "and back state writing 0x22; then the values shown as colour. Vulkan says fragments of "
                       "back-facing polygons use the back state whatever the polygon mode; lavapipe gives the lines and "
                       "points of unfilled polygons the front state (no gl_FrontFacing in the shader: Mesa's draw module "
                       "injects no facing then), so the back-facing triangle's edges write 0x11 there. softraster "
                       "matches the driver. D24_UNORM_S8_UINT.",
        "framebuffer": framebuffer(w, h),
        "camera": {"type": "clip_space"},
        "draws": draws,
    })


def depth_bias_polygon_modes():
    # A slanted background; the same triangles again as lines and as points with depth test
    # less: without bias about half of their fragments fail against the filled copy; with a
    # negative bias they pass, with a positive one they fail. Slope and constant both matter.
    w, h = 256, 192
    tris = [[[-0.95, -0.9, 0.30], [0.2, -0.85, 0.55], [-0.8, 0.2, 0.42]],
            [[0.1, -0.9, 0.70], [0.95, -0.2, 0.20], [0.3, 0.1, 0.35]],
            [[-0.9, 0.3, 0.60], [0.0, 0.25, 0.61], [-0.5, 0.95, 0.59]],
            [[0.1, 0.3, 0.10], [0.9, 0.35, 0.90], [0.4, 0.95, 0.50]]]
    draws = []
    for k, pos in enumerate(tris):
        draws.append({"name": "filled %d" % k, "positions": pos, "colour": [0.3, 0.3, 0.35], "cull": "none"})
    biases = [("line", {"constant": -2.0, "slope": -1.0}), ("point", {"constant": -3.0, "slope": 0.5}),
              ("line", {"constant": 1.0, "slope": -2.5, "clamp": -0.0005}), ("point", {"constant": -8.0, "slope": -4.0, "clamp": -0.00002})]
    for k, pos in enumerate(tris):
        mode, bias = biases[k]
        draws.append({"name": "%s mode with bias %d" % (mode, k), "positions": pos, "colour": [0.9, 0.8, 0.2],
                      "cull": "none", "polygon_mode": mode, "point_size": 2, "depth_compare": "less",
                      "depth_bias": bias})
        draws.append({"name": "%s mode with bias %d, back" % (mode, k), "positions": [pos[0], pos[2], pos[1]],
                      "colour": [0.2, 0.8, 0.9], "cull": "none", "polygon_mode": mode, "point_size": 2,
                      "depth_compare": "less_or_equal", "depth_write": False,
                      "depth_bias": {"constant": bias["constant"] * -0.5, "slope": bias["slope"] * 0.5}})
    write("depth_bias_polygon_modes", {
        "description": "Depth bias with polygon modes line and point (Mesa's draw-module offset stage, which computes the "
                       "bias from the whole triangle before it becomes lines or points and saturates each vertex's z): "
                       "four slanted filled triangles, then the same triangles as lines or points with depth test less "
                       "and biases of both signs, slope and constant, with and without clamp, so the biased edges "
                       "pass or fail against the filled copies. D32_SFLOAT here; the test also draws it in D16 and D24.",
        "framebuffer": {"width": w, "height": h, "clear_colour": [0.05, 0.05, 0.05, 1]},
        "camera": {"type": "clip_space"},
        "draws": draws,
    })


if __name__ == "__main__":
    stencil_ops()
    stencil_compare()
    stencil_front_back()
    stencil_masks()
    stencil_d32s8()
    stencil_two_pass()
    stencil_msaa()
    stencil_polygon_modes()
    depth_bias_polygon_modes()
