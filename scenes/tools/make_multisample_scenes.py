#!/usr/bin/env python3
"""Writes the multisample-state scenes of the conformance suite (VkPipelineMultisampleStateCreateInfo:
the sample mask, alpha to coverage, alpha to one) and 4x MSAA points: sample_mask_msaa,
alpha_to_coverage_msaa, alpha_to_coverage, sample_mask_single_sample, points_msaa, lines_msaa and
msaa_bresenham_sample_state (one JSON file each).
2D scenes: the clip_space camera with positions laid out in pixels (x_win = x * W/2 + W/2).
Run from scenes/:  python3 tools/make_multisample_scenes.py"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from clip_layout import background, clip, dump, quad, scene  # noqa: E402


def triangle(name, points, colours, w, h, z=0.5, **state):
    """points: [x, y] in pixels at depth z, or [x, y, z] each."""
    d = {"name": name, "positions": [clip(p[0], p[1], w, h, p[2] if len(p) == 3 else z) for p in points],
         "colours": colours, "cull": "none"}
    d.update(state)
    return d


def gradient(alpha_left, alpha_right, rgb_left=(0.9, 0.3, 0.1), rgb_right=(0.1, 0.5, 0.9)):
    """Corner colours of a quad whose alpha runs from left to right."""
    left = list(rgb_left) + [alpha_left]
    right = list(rgb_right) + [alpha_right]
    return [left, right, left, right]


def flat(rgba):
    return [list(rgba)] * 4


# ---- sample_mask_msaa: every kind of sample mask with 4x MSAA, before depth and stencil ----
W, H = 160, 96
draws = [background(W, H, z=0.9)]
masks = [0x1, 0x2, 0x4, 0x8, 0x5, 0xA, 0x6, 0x9, 0xE, 0x0, 0xFFFFFFF3, 0xF]
for i, mask in enumerate(masks):
    x, y = 6 + (i % 6) * 25, 6 + (i // 6) * 44
    # A triangle whose edges cross sample rows and columns, so partly covered pixels meet the mask.
    draws.append(triangle(f"mask {mask:#x}", [[x + 0.3, y + 0.7], [x + 21.6, y + 3.2], [x + 4.1, y + 37.4]],
                          [[0.95, 0.2, 0.1, 1], [0.2, 0.9, 0.2, 1], [0.1, 0.3, 0.95, 1]], W, H, z=0.4,
                          multisample={"sample_mask": mask},
                          stencil={"compare_op": "always", "pass_op": "increment_and_clamp",
                                   "depth_fail_op": "invert"}))
    # Across it, nearer on one side and farther on the other, with the complementary mask: its
    # samples test against the depth only the first one's kept samples wrote.
    draws.append(triangle(f"mask {(~mask) & 0xF:#x} across mask {mask:#x}",
                          [[x - 1.2, y + 20.3, 0.2], [x + 23.4, y + 14.8, 0.6], [x + 22.1, y + 39.6, 0.6]],
                          [[0.9, 0.9, 0.2, 1], [0.9, 0.2, 0.9, 1], [0.2, 0.9, 0.9, 1]], W, H,
                          multisample={"sample_mask": (~mask) & 0xF},
                          stencil={"compare_op": "equal", "reference": 0, "pass_op": "replace",
                                   "fail_op": "increment_and_wrap", "depth_fail_op": "decrement_and_wrap"}))
dump("sample_mask_msaa.json", scene(
    "4x MSAA with the sample mask (pSampleMask[0]): twelve triangles, each with one mask (left to right, top to "
    "bottom: 0x1, 0x2, 0x4, 0x8, 0x5, 0xa, 0x6, 0x9, 0xe, 0x0, 0xfffffff3 (only bits 0..3 count), 0xf), depth test "
    "on and a stencil that counts what passes, and across each a second triangle with the complementary mask whose "
    "depth runs from in front of the first to behind it, with a stencil test on the value the first left. The mask "
    "narrows coverage before the depth and stencil tests: a sample it drops is neither tested, nor written, nor "
    "counted. D24_UNORM_S8_UINT; every sample of colour, depth and stencil compared.", W, H, draws, samples=4,
    depth_format="d24_unorm_s8_uint"))

# ---- alpha_to_coverage_msaa: alpha to coverage and alpha to one with 4x MSAA ----
W, H = 192, 128
draws = [background(W, H, z=0.9)]
# Row 1: flat alphas at and between the thresholds 0, 0.25, 0.5, 0.75 (a sample is kept where alpha > s / 4).
for i, a in enumerate([0.0, 0.1, 0.25, 0.3, 0.5, 0.6, 0.75, 0.8, 1.0]):
    draws.append(quad(f"alpha {a}", 4 + i * 20.5, 4.5, 18.25, 18.5, flat([0.9, 0.8, 0.1, a]), W, H, z=0.5,
                      depth_test=False, multisample={"alpha_to_coverage": True}))
# Row 2: alpha gradients 0 -> 1 across quads: plain, with alpha to one, with blending, with both.
variants = [("plain", {"alpha_to_coverage": True}, None),
            ("alpha to one", {"alpha_to_coverage": True, "alpha_to_one": True}, None),
            ("blended", {"alpha_to_coverage": True}, {"source": "src_alpha", "destination": "one_minus_src_alpha"}),
            ("blended, alpha to one", {"alpha_to_coverage": True, "alpha_to_one": True},
             {"source": "src_alpha", "destination": "one_minus_src_alpha"})]
for i, (label, ms, blend) in enumerate(variants):
    state = {"depth_test": False, "multisample": ms}
    if blend:
        state["blend"] = blend
    draws.append(quad(f"gradient, {label}", 4.3 + i * 46.5, 28.6, 43.1, 30.2, gradient(0.0, 1.0), W, H, **state))
# Row 3: alpha to one alone (no alpha to coverage) with blending: the blend sees alpha 1.
draws.append(quad("alpha to one alone, blended", 4.6, 64.3, 60.2, 26.7, gradient(0.1, 0.9), W, H, depth_test=False,
                  multisample={"alpha_to_one": True},
                  blend={"source": "src_alpha", "destination": "one_minus_src_alpha"}))
# Depth and stencil: samples alpha to coverage drops are neither tested nor written (the second,
# nearer quad is drawn where the first one's dropped samples left the clear depth).
draws.append(quad("depth and stencil under alpha to coverage", 70.2, 64.6, 56.3, 26.1, gradient(0.05, 0.95), W, H,
                  z=0.6, multisample={"alpha_to_coverage": True},
                  stencil={"compare_op": "always", "pass_op": "increment_and_clamp"}))
draws.append(quad("over it, depth less, stencil equal 0", 74.1, 68.3, 48.7, 18.2, flat([0.2, 0.9, 0.9, 0.7]), W, H,
                  z=0.7, depth_compare="less",
                  stencil={"compare_op": "equal", "reference": 0, "pass_op": "invert", "fail_op": "zero"}))
# With the sample mask: alpha to coverage and the mask both narrow coverage.
draws.append(quad("with sample mask 0x9", 132.2, 64.4, 54.9, 26.4, gradient(1.0, 0.0), W, H, depth_test=False,
                  multisample={"alpha_to_coverage": True, "sample_mask": 0x9}))
# A shader with the fragment built-ins (discard, gl_FragCoord): alpha = 2 * gl_FragCoord.w on front
# faces, 1 - gl_FragCoord.z on back faces (builtins_discard), so coverage follows depth.
draws.append({"name": "built-ins with alpha to coverage (front)", "shading": "builtins_discard",
              "positions": [[-0.95, 0.45, 0.2], [-0.05, 0.5, 0.9], [-0.9, 0.97, 0.5]],
              "colours": [[0.9, 0.2, 0.2, 1], [0.2, 0.9, 0.2, 1], [0.2, 0.2, 0.9, 1]], "cull": "none",
              "depth_test": False, "multisample": {"alpha_to_coverage": True, "alpha_to_one": True}})
draws.append({"name": "built-ins with alpha to coverage (back)", "shading": "builtins_discard",
              "positions": [[0.05, 0.45, 0.1], [0.1, 0.97, 0.95], [0.95, 0.5, 0.5]],
              "colours": [[0.9, 0.6, 0.2, 1], [0.2, 0.6, 0.9, 1], [0.6, 0.2, 0.9, 1]], "cull": "none",
              "depth_test": False, "multisample": {"alpha_to_coverage": True}})
dump("alpha_to_coverage_msaa.json", scene(
    "4x MSAA with alpha to coverage and alpha to one. Top row: quads of one alpha each (0, 0.1, 0.25, 0.3, 0.5, "
    "0.6, 0.75, 0.8, 1): lavapipe keeps sample s where alpha > s/4, no dither, so 0 keeps none and 0.25 keeps only "
    "sample 0. Second row: alpha running 0 to 1 left to right, plain, with alpha to one, blended (src_alpha, "
    "one_minus_src_alpha), blended with alpha to one (the blend then sees alpha 1). Third row: alpha to one alone "
    "with blending; alpha to coverage with depth and stencil writes under a nearer quad that tests both (a dropped "
    "sample is neither tested nor written); alpha to coverage with sample mask 0x9. Bottom: the built-ins shader "
    "(discard, gl_FragCoord) with alpha to coverage, front and back faces. D24_UNORM_S8_UINT; every sample "
    "compared.", W, H, draws, samples=4, depth_format="d24_unorm_s8_uint"))

# ---- alpha_to_coverage: one sample, where lavapipe keeps a fragment iff alpha > 0.5 ----
W, H = 160, 96
draws = [background(W, H, z=0.9)]
for i, a in enumerate([0.0, 0.49, 0.5, 0.51, 1.0]):
    draws.append(quad(f"alpha {a}", 4 + i * 20.5, 4.5, 18.25, 18.5, flat([0.9, 0.8, 0.1, a]), W, H,
                      depth_test=False, multisample={"alpha_to_coverage": True}))
draws.append(quad("gradient", 108.3, 4.6, 48.2, 18.1, gradient(0.0, 1.0), W, H, depth_test=False,
                  multisample={"alpha_to_coverage": True}))
draws.append(quad("gradient, alpha to one, blended", 4.3, 28.4, 72.6, 22.2, gradient(0.0, 1.0), W, H,
                  depth_test=False, multisample={"alpha_to_coverage": True, "alpha_to_one": True},
                  blend={"source": "src_alpha", "destination": "one_minus_src_alpha"}))
draws.append(quad("alpha to one alone, blended", 82.1, 28.2, 74.4, 22.6, gradient(0.2, 0.8), W, H,
                  depth_test=False, multisample={"alpha_to_one": True},
                  blend={"source": "src_alpha", "destination": "dst_alpha", "alpha": {"source": "one",
                                                                                       "destination": "one"}}))
draws.append(quad("depth and stencil under alpha to coverage", 4.4, 56.3, 60.1, 34.4, gradient(1.0, 0.0), W, H,
                  z=0.6, multisample={"alpha_to_coverage": True},
                  stencil={"compare_op": "always", "pass_op": "increment_and_clamp"}))
draws.append(quad("over it, depth less, stencil equal 0", 8.2, 60.1, 52.3, 26.2, flat([0.2, 0.9, 0.9, 1]), W, H,
                  z=0.7, stencil={"compare_op": "equal", "reference": 0, "pass_op": "invert", "fail_op": "zero"}))
# Lines and points: alpha to coverage and alpha to one apply to every primitive.
draws.append({"name": "lines with alpha to coverage", "topology": "line_list",
              "positions": [clip(70 + 4 * k, 56, W, H) if j == 0 else clip(86 + 4 * k, 92, W, H)
                            for k in range(8) for j in range(2)],
              "colours": [[0.9, 0.9, 0.9, (k + 0.5) / 8] if j == 0 else [0.9, 0.2, 0.9, 1 - (k + 0.5) / 8]
                          for k in range(8) for j in range(2)],
              "depth_test": False, "line_width": 2.5, "multisample": {"alpha_to_coverage": True}})
draws.append({"name": "points with alpha to coverage and one", "topology": "point_list",
              "positions": [clip(112 + 6 * (k % 7), 60 + 8 * (k // 7), W, H) for k in range(28)],
              "colours": [[0.3, 0.9, 0.4, k / 27] for k in range(28)], "point_size": 4.0,
              "depth_test": False, "multisample": {"alpha_to_coverage": True, "alpha_to_one": True},
              "blend": {"source": "src_alpha", "destination": "one_minus_src_alpha"}})
dump("alpha_to_coverage.json", scene(
    "One sample with alpha to coverage and alpha to one: lavapipe keeps a fragment iff its alpha > 0.5 (quads of "
    "alpha 0, 0.49, 0.5, 0.51 and 1, then a gradient 0 -> 1); alpha to coverage with alpha to one and blending "
    "(what survives is opaque); alpha to one alone with blending (the blend sees alpha 1); alpha to coverage "
    "with depth and stencil writes under a quad testing both (a killed fragment is neither tested nor written); "
    "wide lines whose alpha runs along them and points of rising alpha: the state applies to every primitive. "
    "D24_UNORM_S8_UINT.", W, H, draws, depth_format="d24_unorm_s8_uint"))

# ---- sample_mask_single_sample: the deviation (lavapipe ignores bit 0 with one sample) ----
W, H = 96, 64
draws = [background(W, H, z=0.9)]
draws.append(quad("sample mask 0xfffffffe", 8.3, 8.6, 40.2, 46.1, gradient(1.0, 1.0), W, H, z=0.4,
                  multisample={"sample_mask": 0xFFFFFFFE},
                  stencil={"compare_op": "always", "pass_op": "replace", "reference": 7}))
draws.append(quad("sample mask 0x1", 52.1, 8.2, 36.4, 46.3, gradient(1.0, 1.0, (0.2, 0.9, 0.3), (0.9, 0.9, 0.2)), W, H,
                  z=0.4, multisample={"sample_mask": 0x1}))
draws.append(quad("sample mask 0x0", 30.2, 20.4, 40.1, 24.3, flat([1, 1, 1, 1]), W, H, z=0.2,
                  multisample={"sample_mask": 0}))
dump("sample_mask_single_sample.json", scene(
    "One sample with a sample mask: the spec ANDs coverage with pSampleMask[0], so with one sample bit 0 decides; "
    "lavapipe only discards a draw whose whole mask is 0. Left: mask 0xfffffffe (bit 0 clear: the spec draws "
    "nothing, lavapipe draws the quad and writes its depth and stencil); right: mask 0x1 (drawn by both); across "
    "them a white quad with mask 0 (drawn by neither). The known deviation sample_mask_one_sample "
    "(crosscheck --deviations spec shows the difference). D24_UNORM_S8_UINT.", W, H, draws,
    depth_format="d24_unorm_s8_uint"))

# ---- points_msaa: points and polygon mode point with 4x MSAA ----
W, H = 128, 96
draws = [background(W, H, z=0.9)]
# Four points of size 1 centred on pixel corners and centres: with MSAA a point's square is
# snapped without the half-pixel offset, so one centred on a corner covers one sample in each of
# the four pixels around it.
draws.append({"name": "size 1 on a corner (20, 30)", "topology": "point_list", "positions": [clip(20, 30, W, H, 0.3)],
              "colour": [0.95, 0.9, 0.1, 1], "point_size": 1.0, "depth_test": False,
              "stencil": {"compare_op": "always", "pass_op": "replace", "reference": 9}})
draws.append({"name": "size 1 on a centre (30.5, 30.5)", "topology": "point_list",
              "positions": [clip(30.5, 30.5, W, H, 0.3)], "colour": [0.1, 0.9, 0.95, 1], "point_size": 1.0,
              "depth_test": False})
# Sizes and fractional centres, depth tested against a slanted triangle, blended.
pts, cols, k = [], [], 0
for size_row, size in enumerate([1.5, 2.7, 4.0, 7.3]):
    for i in range(6):
        pts.append(clip(8.3 + 19.1 * i + 0.37 * size_row, 44.2 + 11.6 * size_row + 0.21 * i, W, H, 0.2 + 0.1 * i))
        cols.append([0.2 + 0.12 * i, 0.9 - 0.15 * size_row, 0.5, 0.4 + 0.1 * size_row])
        k += 1
    draws.append({"name": f"slanted triangle under row {size_row}", "positions": [
        clip(2, 40 + 11.6 * size_row, W, H, 0.1), clip(126, 40 + 11.6 * size_row, W, H, 0.8),
        clip(64, 50 + 11.6 * size_row, W, H, 0.45)], "colour": [0.5, 0.5, 0.5, 1], "cull": "none"})
    draws.append({"name": f"points of size {size}", "topology": "point_list", "positions": pts[-6:], "colours": cols[-6:],
                  "point_size": size, "blend": {"source": "src_alpha", "destination": "one_minus_src_alpha"}})
# A point across the scissor's left and top edges: cut exactly at them (no samples of the column
# left of or the row above the scissor, which a triangle there gets from lavapipe).
draws.append({"name": "size 6 across the scissor corner (80, 10)", "topology": "point_list",
              "positions": [clip(80.2, 10.3, W, H, 0.5)], "colour": [0.9, 0.2, 0.6, 1], "point_size": 6.0,
              "depth_test": False, "scissor": {"x": 80, "y": 10, "width": 40, "height": 20}})
# Polygon mode point: a triangle's corners as points, depth-biased, front and back faces.
draws.append({"name": "polygon mode point, biased", "positions": [clip(100.3, 40.6, W, H, 0.4),
              clip(120.2, 70.1, W, H, 0.5), clip(90.7, 88.4, W, H, 0.6)], "colour": [0.95, 0.5, 0.1, 1],
              "cull": "none", "polygon_mode": "point", "point_size": 3.0,
              "depth_bias": {"constant": 64, "slope": 1.5, "clamp": 0}})
draws.append({"name": "polygon mode point, back face", "positions": [clip(60.3, 12.6, W, H, 0.4),
              clip(50.2, 30.1, W, H, 0.5), clip(70.7, 36.4, W, H, 0.6)], "colour": [0.3, 0.5, 0.95, 1],
              "cull": "none", "polygon_mode": "point", "point_size": 2.5,
              "stencil": {"compare_op": "always", "pass_op": "increment_and_clamp"}})
dump("points_msaa.json", scene(
    "4x MSAA points (point_list and polygon mode point): lavapipe snaps a point's square without the half-pixel "
    "offset when multisampling and covers each sample inside it, so a size-1 point centred on the pixel corner "
    "(20, 30) writes one sample in each of the four pixels around it and one centred on (30.5, 30.5) all four "
    "samples of its pixel; rows of points of sizes 1.5, 2.7, 4 and 7.3 at fractional centres, blended, depth "
    "tested per sample against slanted triangles; a point across the scissor's top-left corner, cut exactly "
    "there (no partial column or row, unlike triangles); a triangle's corners in polygon mode point with depth "
    "bias, and a back-facing one counting the stencil. D24_UNORM_S8_UINT; every sample compared.", W, H, draws,
    samples=4, depth_format="d24_unorm_s8_uint"))

# ---- lines_msaa: lines and polygon mode line with 4x MSAA ----
W, H = 160, 128
draws = [background(W, H, z=0.9)]
draws.append({"name": "slanted triangle", "positions": [clip(0, 70, W, H, 0.1), clip(160, 78, W, H, 0.9),
              clip(80, 128, W, H, 0.5)], "colour": [0.45, 0.45, 0.5, 1], "cull": "none"})
# A star of rectangular lines, widths 1 and 3, colour per vertex (lavapipe's line attribute planes
# keep the half-pixel offset its MSAA fragment code adds again), depth tested against the slanted
# triangle, the stencil counting every sample written.
for k, width in enumerate([1.0, 3.0]):
    cx, cy = 40 + 80 * k + 0.3, 92.6
    pts, cols = [], []
    for i in range(12):
        a = i * math.pi / 6 + 0.13
        pts += [clip(cx, cy, W, H, 0.2), clip(cx + 33 * math.cos(a), cy + 33 * math.sin(a), W, H, 0.7)]
        cols += [[0.95, 0.15 + 0.06 * i, 0.1, 1], [0.1, 0.3, 0.95 - 0.05 * i, 1]]
    draws.append({"name": f"star width {width}", "topology": "line_list", "positions": pts, "colours": cols,
                  "line_width": width, "stencil": {"compare_op": "always", "pass_op": "increment_and_clamp"}})
# Short lines whose left (or top) end lies 0.05..0.95 px before a pixel: lavapipe's bounding box
# starts at the next pixel, and the samples of the pixel before it are drawn only where its
# binning walks there: inside a 64x64 tile it does, across a tile's first column or row not (the
# first four of each kind start inside tile (0, 0), the last four just before x 64 or y 64).
for i in range(8):
    x0 = 4.05 + 1.11 * i if i < 4 else 63.05 + 0.22 * (i - 4)
    y = 3.4 + 5 * i if i < 4 else 30.4 + 3 * (i - 4)
    draws.append({"name": f"short horizontal from x {x0:.2f}", "topology": "line_list",
                  "positions": [clip(x0, y, W, H, 0.5), clip(x0 + 9.6, y + 0.8, W, H, 0.5)],
                  "colours": [[0.9, 0.9, 0.2, 1], [0.2, 0.9, 0.9, 1]], "line_width": 2.0, "depth_test": False})
    x = 24.3 + 4 * i if i < 4 else 44.3 + 4 * (i - 4)
    y0 = 12.05 + 1.11 * i if i < 4 else 63.05 + 0.22 * (i - 4)
    draws.append({"name": f"short vertical from y {y0:.2f}", "topology": "line_list",
                  "positions": [clip(x, y0, W, H, 0.5), clip(x + 0.7, y0 + 10.2, W, H, 0.5)],
                  "colours": [[0.9, 0.3, 0.9, 1], [0.3, 0.9, 0.3, 1]], "line_width": 1.5, "depth_test": False})
# Long lines starting just before a 64-pixel tile boundary (x 63.2, y 63.3) and just before an
# ordinary column: binned to the tiles their box cut to the region touches.
draws.append({"name": "long from x 63.2", "topology": "line_list",
              "positions": [clip(63.2, 20.4, W, H, 0.3), clip(150.7, 40.9, W, H, 0.3)],
              "colour": [0.95, 0.6, 0.1, 1], "line_width": 2.5, "depth_test": False})
draws.append({"name": "long from x 62.2", "topology": "line_list",
              "positions": [clip(62.2, 50.4, W, H, 0.3), clip(150.7, 60.1, W, H, 0.3)],
              "colour": [0.1, 0.95, 0.6, 1], "line_width": 2.5, "depth_test": False})
draws.append({"name": "long from y 63.3", "topology": "line_list",
              "positions": [clip(140.4, 63.3, W, H, 0.3), clip(150.2, 126.1, W, H, 0.3)],
              "colour": [0.6, 0.1, 0.95, 1], "line_width": 3.0, "depth_test": False})
# Against a scissor at x 70 (not on a tile edge): one line starts left of it (the scissor plane,
# +127/256: samples 1 and 3 of column 69), one starts at x 69.3, inside the pixel before the
# scissor, so its box starts at the scissor and it carries no plane (samples 0, 1 and 3 of column
# 69), one starts at 70.3 (nothing there); and a strip crossing the scissor's top edge.
for i, x0 in enumerate([66.6, 69.3, 70.3]):
    draws.append({"name": f"scissored from x {x0}", "topology": "line_list",
                  "positions": [clip(x0, 6.4 + 4 * i, W, H, 0.5), clip(x0 + 12.3, 7.1 + 4 * i, W, H, 0.5)],
                  "colours": [[0.95, 0.95, 0.95, 1], [0.95, 0.2, 0.2, 1]], "line_width": 2.0, "depth_test": False,
                  "scissor": {"x": 70, "y": 5, "width": 60, "height": 40}})
draws.append({"name": "strip across the scissor's top", "topology": "line_strip",
              "positions": [clip(90.2, 2.3, W, H, 0.5), clip(96.7, 4.7, W, H, 0.5), clip(101.1, 1.2, W, H, 0.5),
                            clip(110.4, 12.8, W, H, 0.5)],
              "colour": [0.2, 0.95, 0.95, 1], "line_width": 1.5, "depth_test": False,
              "scissor": {"x": 70, "y": 5, "width": 60, "height": 40}})
# Polygon mode line, rectangular and Bresenham (both multisampled: lavapipe turns multisampling off
# only for line topologies), depth-biased, blended, a back face counting the stencil.
draws.append({"name": "polygon mode line, rectangular, biased", "positions": [clip(110.3, 48.6, W, H, 0.4),
              clip(156.2, 52.1, W, H, 0.5), clip(126.7, 68.4, W, H, 0.6)],
              "colours": [[0.9, 0.2, 0.2, 0.7], [0.2, 0.9, 0.2, 0.7], [0.2, 0.2, 0.9, 0.7]],
              "cull": "none", "polygon_mode": "line", "line_width": 1.5,
              "depth_bias": {"constant": 64, "slope": 1.5, "clamp": 0},
              "blend": {"source": "src_alpha", "destination": "one_minus_src_alpha"}})
draws.append({"name": "polygon mode line, Bresenham, back face", "positions": [clip(90.3, 48.6, W, H, 0.4),
              clip(80.2, 66.1, W, H, 0.5), clip(104.7, 67.4, W, H, 0.6)], "colour": [0.95, 0.8, 0.3, 1],
              "cull": "none", "polygon_mode": "line", "line_rasterization": "bresenham",
              "stencil": {"compare_op": "always", "pass_op": "increment_and_clamp"}})
# Bresenham lines of a line topology: lavapipe draws them with multisampling off: the single-sample
# pixels, depth and stencil tested and written at sample 0 only, the colour in all four samples.
draws.append({"name": "Bresenham line strip, depth tested", "topology": "line_strip",
              "positions": [clip(2.4, 74.3, W, H, 0.05), clip(60.6, 84.8, W, H, 0.95), clip(20.2, 126.5, W, H, 0.3),
                            clip(150.3, 100.7, W, H, 0.6)],
              "colours": [[0.9, 0.9, 0.9, 1], [0.9, 0.1, 0.5, 1], [0.1, 0.9, 0.5, 1], [0.5, 0.1, 0.9, 1]],
              "line_rasterization": "bresenham", "line_width": 2.0,
              "stencil": {"compare_op": "always", "pass_op": "replace", "depth_fail_op": "invert", "reference": 77},
              "blend": {"source": "one", "destination": "one", "op": "max"}})
# Bresenham lines against a scissor (x 90, y 66: not on tile edges) and a viewport at (80.6, 64.75):
# drawn with multisampling off, so the region is cut exactly, with no partial column or row.
draws.append({"name": "Bresenham lines across a scissor", "topology": "line_list",
              "positions": [clip(84.3, 70.2, W, H, 0.3), clip(120.6, 74.9, W, H, 0.3), clip(95.2, 62.1, W, H, 0.3),
                            clip(99.8, 90.6, W, H, 0.3)],
              "colours": [[0.95, 0.95, 0.3, 1], [0.3, 0.95, 0.95, 1], [0.95, 0.3, 0.95, 1], [0.3, 0.3, 0.95, 1]],
              "line_rasterization": "bresenham", "line_width": 3.0, "depth_test": False,
              "scissor": {"x": 90, "y": 66, "width": 40, "height": 30}})
draws.append({"name": "Bresenham lines in an offset viewport", "topology": "line_strip",
              "positions": [[-1.05, -0.6, 0.3], [-0.2, -1.1, 0.3], [0.4, -0.3, 0.3]],
              "colour": [0.6, 0.95, 0.2, 1], "line_rasterization": "bresenham", "line_width": 2.0,
              "depth_test": False, "viewport": {"x": 80.6, "y": 64.75, "width": 40, "height": 30}})
dump("lines_msaa.json", scene(
    "4x MSAA lines (line_list, line_strip, polygon mode line): lavapipe snaps a multisampled line's quad "
    "without the half-pixel offset but keeps it in the attribute planes (colours and depth sit half a "
    "pixel off), and its bounding box starts at the first pixel corner the quad covers, so the samples "
    "left of or above it are drawn only where its binning walks (64x64 tiles: not across a tile edge): "
    "stars of width 1 and 3, depth tested against a slanted triangle and counted in the stencil; short "
    "lines starting 0.05..0.95 px before a pixel inside a tile and before a tile edge, long ones just "
    "before a tile edge; lines against a scissor at x 70 with and without the scissor plane; polygon mode"
    " line, rectangular (biased, blended) and Bresenham (back face, stencil); a Bresenham line strip, "
    "which lavapipe draws with multisampling off (depth and stencil at sample 0, colour in every sample), "
    "and Bresenham lines against a scissor and an offset viewport, which multisampling off cuts exactly."
    " D24_UNORM_S8_UINT; every sample compared.", W, H, draws, samples=4,
    depth_format="d24_unorm_s8_uint"))

# ---- msaa_bresenham_sample_state: the multisample state on lines drawn with multisampling off ----
W, H = 160, 96
draws = [background(W, H, z=0.9)]


def bresenham(name, y, colours, topology="line_list", **state):
    """Three Bresenham lines (a list) or a strip zig-zagging across row y, 3 px wide."""
    xs = [6.3, 52.7, 55.1, 104.6, 107.2, 153.8] if topology == "line_list" else [6.3, 40.2, 78.9, 117.4, 153.8]
    d = {"name": name, "topology": topology, "line_rasterization": "bresenham", "line_width": 3.0,
         "positions": [clip(x, y + (4.6 if k % 2 else 0.3), W, H, 0.4 + 0.05 * k) for k, x in enumerate(xs)],
         "colours": [colours[k % len(colours)] for k in range(len(xs))], "depth_test": False}
    d.update(state)
    return d


opaque = [[0.95, 0.8, 0.2, 1], [0.2, 0.9, 0.9, 1]]
draws.append(bresenham("sample mask 0x5: not applied", 6, opaque, multisample={"sample_mask": 5}))
draws.append(bresenham("sample mask 0x10 (none of the four): drawn whole", 18, opaque,
                       multisample={"sample_mask": 16}))
draws.append(bresenham("sample mask 0x6, depth and stencil", 30, opaque, topology="line_strip", depth_test=True,
                       multisample={"sample_mask": 6}, stencil={"compare_op": "always", "pass_op": "increment_and_clamp"}))
# Alpha to coverage, alpha to one and sample shading are invalid on Bresenham lines
# (VUID-VkGraphicsPipelineCreateInfo-lineRasterizationMode-02766): the mask with blending instead.
fading = [[0.9, 0.3, 0.1, 0.0], [0.1, 0.5, 0.9, 1.0]]
draws.append(bresenham("sample mask 0x8, blended", 42, fading, multisample={"sample_mask": 8},
                       blend={"source": "src_alpha", "destination": "one_minus_src_alpha"}))
draws.append(bresenham("sample mask 0x3, blended", 54, fading, multisample={"sample_mask": 3},
                       blend={"source": "src_alpha", "destination": "one_minus_src_alpha"}))
draws.append(bresenham("sample mask 0x9, blended strip", 66, fading, topology="line_strip",
                       multisample={"sample_mask": 9},
                       blend={"source": "src_alpha", "destination": "one_minus_src_alpha"}))
# Multisampled for comparison: rectangular lines and polygon mode line take the mask per sample.
draws.append(dict(bresenham("rectangular, sample mask 0x5, alpha to coverage", 78, fading,
                            multisample={"sample_mask": 5, "alpha_to_coverage": True}),
                  line_rasterization="rectangular"))
draws.append({"name": "polygon mode line, Bresenham, sample mask 0xa", "polygon_mode": "line",
              "line_rasterization": "bresenham", "line_width": 2.0, "cull": "none", "depth_test": False,
              "positions": [clip(120.4, 60.2, W, H, 0.3), clip(150.7, 92.1, W, H, 0.3), clip(156.3, 58.8, W, H, 0.3)],
              "colour": [0.9, 0.9, 0.9, 1], "multisample": {"sample_mask": 10}})
dump("msaa_bresenham_sample_state.json", scene(
    "The sample mask on 4x MSAA Bresenham lines, which lavapipe draws with multisampling off: the mask is not "
    "applied (0x5, 0x6 with depth and stencil, 0x8, 0x3 and 0x9 blended, and 0x10, none of the four samples, all "
    "drawn whole; only a mask of 0 drops a draw); Vulkan forbids alpha to coverage, alpha to one and sample "
    "shading on Bresenham lines (VUID-VkGraphicsPipelineCreateInfo-lineRasterizationMode-02766). For comparison, "
    "multisampled lines: rectangular lines and polygon mode line (Bresenham), where the mask and alpha to coverage "
    "act per sample. Vulkan applies the mask to every sample: the known deviation msaa_lines covers these lines. "
    "D24_UNORM_S8_UINT; every sample compared.", W, H, draws, samples=4, depth_format="d24_unorm_s8_uint"))
