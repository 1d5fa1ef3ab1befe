#!/usr/bin/env python3
"""Writes the blending scenes of the conformance suite: blend_factors, blend_ops, blend_write_mask,
blend_products, transparency, msaa_blend, logic_ops and logic_ops_msaa (one JSON file each).
The 2D scenes use the clip_space camera with positions laid out in pixels (x_win = x * W/2 + W/2),
vertex colours with alpha, and colours chosen off the 1/255 grid so that every product rounds.
Run from scenes/:  python3 tools/make_blend_scenes.py"""
import os
import random
import sys

sys.path.insert(0, os.path.dirname(__file__))
from clip_layout import BACKGROUND, background, clip, dump, quad, scene  # noqa: E402

FACTORS = ["zero", "one", "src_color", "one_minus_src_color", "dst_color", "one_minus_dst_color",
           "src_alpha", "one_minus_src_alpha", "dst_alpha", "one_minus_dst_alpha", "constant_color",
           "one_minus_constant_color", "constant_alpha", "one_minus_constant_alpha", "src_alpha_saturate"]
OPS = ["add", "subtract", "reverse_subtract", "min", "max"]


def rgba(rng, alpha_low=0.05, alpha_high=0.95):
    return [round(rng.uniform(0.04, 0.96), 3) for _ in range(3)] + [round(rng.uniform(alpha_low, alpha_high), 3)]


# ---- blend_factors: every source factor against every destination factor, op ADD ----
rng = random.Random(9)
W = H = 256
draws = [background(W, H)]
for row, source in enumerate(FACTORS):
    for col, destination in enumerate(FACTORS):
        draws.append(quad(f"{source}/{destination}", 8 + 16 * col + 0.5, 8 + 16 * row + 0.5, 14.25, 14.25,
                          [rgba(rng) for _ in range(4)], W, H, depth_test=False,
                          blend={"source": source, "destination": destination,
                                 "constants": [0.3, 0.55, 0.8, 0.45]}))
dump("blend_factors.json", scene(
    "Every blend factor as source (rows, top to bottom: zero, one, src_color, one_minus_src_color, dst_color, "
    "one_minus_dst_color, src_alpha, one_minus_src_alpha, dst_alpha, one_minus_dst_alpha, constant_color, "
    "one_minus_constant_color, constant_alpha, one_minus_constant_alpha, src_alpha_saturate) against every "
    "blend factor as destination (columns, left to right, same order), op ADD for colour and alpha, blend "
    "constants [0.3, 0.55, 0.8, 0.45]. A 15x15 grid of small quads with a different translucent colour in each "
    "corner, over a background whose colour and alpha differ in every corner: the zero/zero cell is transparent "
    "black, "
    "one/zero shows the quad's own colours, zero/one the background. Tests lavapipe's 8-bit blend arithmetic "
    "(rounded products, saturating add) for every factor.", W, H, draws))

# ---- blend_ops: every colour op against every alpha op, with separate colour and alpha factors ----
rng = random.Random(17)
draws = [background(W, H)]
colour_factors = [("src_alpha", "one_minus_src_alpha"), ("one", "one"), ("dst_color", "src_color"),
                  ("constant_color", "one_minus_dst_alpha"), ("src_alpha_saturate", "constant_alpha")]
alpha_factors = [("one", "one_minus_src_alpha"), ("dst_alpha", "one"), ("src_alpha", "src_alpha"),
                 ("one_minus_constant_alpha", "dst_alpha"), ("one", "zero")]
for row, colour_op in enumerate(OPS):
    for col, alpha_op in enumerate(OPS):
        cs, cd = colour_factors[(row + col) % 5]
        a_s, a_d = alpha_factors[(row + 2 * col) % 5]
        x, y = 8 + 48 * col, 8 + 48 * row
        blend = {"colour": {"source": cs, "destination": cd, "op": colour_op},
                 "alpha": {"source": a_s, "destination": a_d, "op": alpha_op},
                 "constants": [0.62, 0.27, 0.44, 0.71]}
        draws.append(quad(f"{colour_op}/{alpha_op}", x + 0.5, y + 0.5, 43.5, 43.5, [rgba(rng) for _ in range(4)],
                          W, H, depth_test=False, blend=blend))
# The alpha each op left behind, made visible: the lower half of every cell is multiplied by its
# destination alpha (colour = dst * dst_alpha) and made opaque.
for row in range(5):
    for col in range(5):
        x, y = 8 + 48 * col, 8 + 48 * row
        draws.append(quad(f"show alpha {row},{col}", x, y + 24, 44, 20, [[0.5, 0.5, 0.5, 1]] * 4, W, H,
                          depth_test=False,
                          blend={"colour": {"source": "zero", "destination": "dst_alpha"},
                                 "alpha": {"source": "one", "destination": "zero"}}))
dump("blend_ops.json", scene(
    "Every blend op for colour (rows, top to bottom: add, subtract, reverse_subtract, min, max) against every "
    "blend op for alpha (columns, same order), each cell with its own colour factors and different alpha "
    "factors, over a background whose colour and alpha differ in every corner. The lower half of each cell "
    "is then darkened by the alpha the cell's blend stored (colour times destination alpha, made opaque), so "
    "alpha results show as brightness there (the upper half keeps its alpha, and looks washed out where a viewer "
    "shows alpha as transparency). Subtract cells are darker than add cells; min and max ignore the factors.",
    W, H, draws))

# ---- blend_write_mask: every colour write mask, with blending off and on ----
rng = random.Random(23)
draws = [background(W, H)]
masks = ["", "r", "g", "b", "a", "rg", "rb", "ra", "gb", "ga", "ba", "rgb", "rga", "rba", "gba", "rgba"]
for i, mask in enumerate(masks):
    for half, blend in enumerate([{"enable": False, "write_mask": mask},
                                  {"source": "src_alpha", "destination": "one_minus_src_alpha", "write_mask": mask}]):
        col, row = i % 4, i // 4 + 4 * half
        x, y = 8 + 60 * col, 4 + 31 * row
        draws.append(quad(f"{'blend' if half else 'store'} {mask or 'none'}", x + 0.5, y + 0.5, 56, 27,
                          [rgba(rng) for _ in range(4)], W, H, depth_test=False, blend=blend))
# Alpha written or kept, made visible as in blend_ops: the right part of each cell times its alpha.
for i in range(32):
    col, row = i % 4, i // 4
    x, y = 8 + 60 * col, 4 + 31 * row
    draws.append(quad(f"show alpha {i}", x + 40, y, 17, 28, [[0.5, 0.5, 0.5, 1]] * 4, W, H, depth_test=False,
                      blend={"colour": {"source": "zero", "destination": "dst_alpha"},
                             "alpha": {"source": "one", "destination": "zero"}}))
dump("blend_write_mask.json", scene(
    "Every colour write mask (none, r, g, b, a, rg, rb, ra, gb, ga, ba, rgb, rga, rba, gba, rgba; left to "
    "right, top to bottom) on quads over a background whose colour and alpha differ in every corner: the top "
    "four rows store the quad's colour with blending off, the bottom four blend it with src_alpha / "
    "one_minus_src_alpha. Components left out of the mask keep the background; the right end of each cell is "
    "multiplied by the stored alpha and made opaque, so a written alpha shows as a change of brightness there.", W, H, draws))

# ---- blend_products: all 256 x 256 products of the 8-bit multiply ----
draws = [quad("destination ramps", 0, 0, 256, 256,
              [[0, 0, 1, 0], [1, 0, 0, 1], [0, 1, 1, 0], [1, 1, 0, 1]], 256, 256, depth_test=False),
         quad("source ramps times destination", 0, 0, 256, 256,
              [[0, 1, 0, 0], [0, 0, 1, 0], [1, 1, 0, 1], [1, 0, 1, 1]], 256, 256, depth_test=False,
              blend={"colour": {"source": "dst_color", "destination": "zero"},
                     "alpha": {"source": "one_minus_dst_alpha", "destination": "src_alpha"}})]
dump("blend_products.json", scene(
    "A probe of lavapipe's 8-bit blend multiply: a background of ramps (red and alpha rising left to right, "
    "green top to bottom, blue the other way) multiplied by a quad of ramps running the other way (colour: "
    "source times destination colour; alpha: source times (1 - destination alpha) plus destination alpha "
    "times source alpha). Nearly every pair of bytes meets somewhere, so every rounding of the product shows; "
    "the picture is a smooth product of gradients, dark in the corners where a ramp is zero.",
    256, 256, draws))

# ---- transparency: opaque objects with depth, then transparent ones back to front ----
def box(name, x0, x1, y0, y1, z0, z1, colour):
    """An axis-aligned box (world space, y down) as an indexed mesh with one colour per face."""
    corners = [[x, y, z] for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
    faces = [(0, 1, 3, 2), (5, 4, 6, 7), (4, 0, 2, 6), (1, 5, 7, 3), (4, 5, 1, 0), (2, 3, 7, 6)]
    shade = [1.0, 0.55, 0.8, 0.7, 0.9, 0.45]
    positions, colours, indices = [], [], []
    for f, face in enumerate(faces):
        base = len(positions)
        for c in face:
            positions.append(corners[c])
            colours.append([round(colour[k] * shade[f], 4) for k in range(3)] + [1])
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return {"name": name, "positions": positions, "colours": colours, "indices": indices, "cull": "none"}


def pane(name, x0, x1, y0, y1, z, colours):
    """A vertical pane facing the camera at depth z (world space, y down); colours per corner."""
    return {"name": name, "positions": [[x0, y0, z], [x1, y0, z], [x0, y1, z], [x1, y1, z]], "colours": colours,
            "indices": [0, 2, 1, 1, 2, 3], "cull": "none", "depth_write": False,
            "blend": {"source": "src_alpha", "destination": "one_minus_src_alpha"}}


floor_colours = [[0.62, 0.6, 0.55, 1], [0.41, 0.43, 0.47, 1], [0.55, 0.5, 0.44, 1], [0.35, 0.36, 0.4, 1]]
draws = [{"name": "floor", "positions": [[-3, 1, 1], [3, 1, 1], [-3, 1, 9], [3, 1, 9]], "colours": floor_colours,
          "indices": [0, 2, 1, 1, 2, 3], "cull": "none"},
         box("red box", -1.6, -0.5, 0.1, 1.0, 4.0, 5.1, [0.85, 0.2, 0.15]),
         box("blue box", 0.4, 1.5, -0.4, 1.0, 5.5, 6.6, [0.2, 0.35, 0.9]),
         box("green post", -0.15, 0.25, -1.2, 1.0, 3.2, 3.6, [0.25, 0.8, 0.3]),
         # Translucent panes, farthest first.
         pane("far pane (behind everything)", -2.2, 2.2, -1.3, 0.95, 7.4,
              [[0.95, 0.85, 0.2, 0.55], [0.9, 0.6, 0.1, 0.35], [0.95, 0.9, 0.3, 0.7], [0.8, 0.5, 0.2, 0.45]]),
         pane("middle pane (between the boxes)", -0.9, 1.9, -0.9, 0.75, 5.3,
              [[0.2, 0.75, 0.85, 0.4], [0.3, 0.9, 0.7, 0.6], [0.1, 0.6, 0.95, 0.25], [0.25, 0.8, 0.8, 0.5]]),
         pane("near pane (in front of the post)", -1.2, 0.45, -0.7, 0.55, 2.9,
              [[0.85, 0.3, 0.75, 0.3], [0.7, 0.2, 0.9, 0.45], [0.9, 0.4, 0.6, 0.2], [0.6, 0.3, 0.85, 0.38]])]
dump("transparency.json", {
    "description": "The course's alpha blending: an opaque floor, a red and a blue box and a green post drawn "
                   "first with the depth test and depth writes on, then three translucent panes drawn back to "
                   "front with the depth test on and depth writes off, blended src_alpha / one_minus_src_alpha "
                   "(colour and alpha). A yellow pane far behind is hidden wherever a box or the post stands in "
                   "front of it; a cyan pane between the two boxes tints the blue box behind it and disappears "
                   "behind the red box; a magenta pane nearest the camera tints the post, the red box and the "
                   "other panes behind it. Each pane's colour and opacity vary across it.",
    "framebuffer": {"width": 320, "height": 240, "clear_colour": [0.08, 0.09, 0.12, 1]},
    "camera": {"type": "pinhole", "position": [0, -0.6, -0.5], "pitch": -8, "focal_length": 200, "near": 0.1,
               "far": 20},
    "draws": draws})

# ---- msaa_blend: blending per sample with 4x MSAA ----
rng = random.Random(31)
W, H = 256, 192
draws = [quad("background", 0, 0, W, H, BACKGROUND, W, H, depth_test=False)]
blends = [{"source": "src_alpha", "destination": "one_minus_src_alpha"},
          {"source": "one", "destination": "one"},
          {"colour": {"source": "dst_color", "destination": "src_alpha_saturate", "op": "add"},
           "alpha": {"source": "one", "destination": "one", "op": "max"}},
          {"colour": {"source": "constant_color", "destination": "one", "op": "reverse_subtract"},
           "alpha": {"source": "one_minus_dst_alpha", "destination": "dst_alpha"}, "constants": [0.4, 0.15, 0.6, 0.3]}]
for i in range(12):
    cx, cy = 30 + (i % 4) * 65 + rng.uniform(-6, 6), 34 + (i // 4) * 62 + rng.uniform(-6, 6)
    pts = [[cx + rng.uniform(-44, 44), cy + rng.uniform(-40, 40)] for _ in range(3)]
    draws.append({"name": f"triangle {i} ({i % 4})", "positions": [clip(x, y, W, H, 0.5) for x, y in pts],
                  "colours": [rgba(rng) for _ in range(3)], "cull": "none", "depth_test": False,
                  "blend": blends[i % 4]})
dump("msaa_blend.json", scene(
    "4x MSAA with blending: a dozen overlapping translucent triangles over a background whose colour and alpha "
    "differ in every corner, blended (in turn) src_alpha / one_minus_src_alpha, additively, dst_color + "
    "src_alpha_saturate with alpha max, and reverse-subtract of the constant colour. Edges blend per sample "
    "(each covered sample blends with its own destination), then the samples are averaged by the resolve.",
    W, H, draws, samples=4))

# ---- logic_ops: every VkLogicOp, plain, with a write mask, and with blendEnable set (ignored) ----
LOGIC_OPS = ["clear", "and", "and_reverse", "copy", "and_inverted", "no_op", "xor", "or", "nor", "equivalent",
             "invert", "or_reverse", "copy_inverted", "or_inverted", "nand", "set"]
rng = random.Random(47)
W, H = 272, 64
draws = [background(W, H)]
for row, extra in enumerate([{}, {"write_mask": "rb"},
                             {"enable": True, "source": "src_alpha", "destination": "one_minus_src_alpha"}]):
    for col, op in enumerate(LOGIC_OPS):
        draws.append(quad(f"{op} ({['plain', 'write mask rb', 'blend enable set'][row]})", 8 + 16 * col + 0.5,
                          6 + 19 * row + 0.5, 14.25, 17.25, [rgba(rng, 0.0, 1.0) for _ in range(4)], W, H,
                          depth_test=False, blend=dict({"logic_op": op}, **extra)))
dump("logic_ops.json", scene(
    "Every logic op (VkLogicOp, columns left to right: clear, and, and_reverse, copy, and_inverted, no_op, xor, "
    "or, nor, equivalent, invert, or_reverse, copy_inverted, or_inverted, nand, set) on the R8G8B8A8_UNORM target "
    "over a background whose colour and alpha differ in every corner, each quad with a different colour in each "
    "corner; top row plain, middle row with write mask rb (g and a keep the background), bottom row with "
    "blendEnable also set (src_alpha / one_minus_src_alpha), which Vulkan ignores with a logic op. The op works "
    "bit by bit on the colour converted to UNORM8 as a store converts it and on the stored byte.", W, H, draws))

# ---- logic_ops_msaa: logic ops per sample with 4x MSAA ----
rng = random.Random(53)
W, H = 192, 128
draws = [background(W, H)]
for i in range(10):
    cx, cy = 24 + (i % 5) * 36 + rng.uniform(-5, 5), 34 + (i // 5) * 60 + rng.uniform(-5, 5)
    pts = [[cx + rng.uniform(-40, 40), cy + rng.uniform(-36, 36)] for _ in range(3)]
    draws.append({"name": f"triangle {i} ({['xor', 'equivalent', 'or_inverted', 'nand', 'and_reverse'][i % 5]})",
                  "positions": [clip(x, y, W, H, 0.5) for x, y in pts], "colours": [rgba(rng, 0.0, 1.0) for _ in range(3)],
                  "cull": "none", "depth_test": False,
                  "blend": {"logic_op": ["xor", "equivalent", "or_inverted", "nand", "and_reverse"][i % 5]}})
dump("logic_ops_msaa.json", scene(
    "4x MSAA with logic ops: ten overlapping triangles over a background whose colour and alpha differ in every "
    "corner, drawn with xor, equivalent, or_inverted, nand and and_reverse in turn: each covered sample combines "
    "with its own stored value, then the samples are averaged by the resolve.", W, H, draws, samples=4))
