#!/usr/bin/env python3
"""Writes the colour-format scenes of the conformance suite, each with 4x MSAA:
colour_format_bgra (a B8G8R8A8_UNORM target): eight cells, each one triangle over a background
whose colour and alpha differ in every corner, each with a state in which red and blue must not
trade places: a plain store, alpha blending, constant-colour factors with red and blue constants
far apart, SRC_ALPHA_SATURATE, write masks naming red but not blue (and blue but not red), and
logic ops. A strip at the bottom keeps the clear colour (red and blue far apart too).
colour_format_srgb (an R8G8B8A8_SRGB target): twelve cells of blending in linear float, among
them the states lavapipe computes another way (the same factor for source and destination: the
sum or difference times the factor), MIN and MAX, a write mask, a logic op (not applied to sRGB),
vertex colours reaching down into the linear segment of the sRGB curve; the clear colour is one
where lavapipe's clear and its fragment stores encode differently (0.5 gives 188 and 187).
colour_format_10bit (an A2B10G10R10_UNORM_PACK32 target): twelve cells of blending and logic ops in
lavapipe's 16-bit integers, vertex channels at 0 and 1, a clear colour packed by its own rounding.
colour_format_float (an R16G16B16A16_SFLOAT target, drawn into R32G32B32A32_SFLOAT by the test too):
twelve cells of unclamped float blending, colours beyond [0, 1] and past the largest half, tiny ones
for half denormals, a clear colour rounded toward zero.
Run from scenes/:  python3 tools/make_colour_format_scenes.py"""
import os
import random
import sys

sys.path.insert(0, os.path.dirname(__file__))
from clip_layout import clip, dump, quad, BACKGROUND  # noqa: E402


def cell_draws(states, rng, w, h, cell_w, cell_h, columns, jitter, margin, colours_of):
    """One triangle per (name, blend) state, cell by cell (left to right, top to bottom): three
    points jittered around the cell's centre (+-jitter in x, +-28 in y; the centre `margin`
    pixels right of the cell's), coloured by colours_of(rng)."""
    draws = []
    for i, (name, blend) in enumerate(states):
        cx, cy = (i % columns) * cell_w + cell_w / 2 + margin, (i // columns) * cell_h + cell_h / 2
        points = [[cx + rng.uniform(-jitter, jitter), cy + rng.uniform(-28, 28)] for _ in range(3)]
        draws.append({"name": f"cell {i} ({name})", "positions": [clip(x, y, w, h) for x, y in points],
                      "colours": colours_of(rng), "cull": "none", "depth_test": False, "blend": blend})
    return draws


W, H = 192, 136
CELL_W, CELL_H = 48, 60
STATES = [
    ("store", {"enable": False}),
    ("over", {"source": "src_alpha", "destination": "one_minus_src_alpha"}),
    ("constants", {"colour": {"source": "constant_color", "destination": "one_minus_constant_color"},
                   "alpha": {"source": "one_minus_constant_alpha", "destination": "constant_alpha"},
                   "constants": [0.9, 0.35, 0.05, 0.6]}),
    ("saturate", {"colour": {"source": "src_alpha_saturate", "destination": "dst_color"},
                  "alpha": {"source": "one", "destination": "one", "op": "max"}}),
    ("write mask r", {"enable": False, "write_mask": "r"}),
    ("additive, write mask ba", {"source": "one", "destination": "one", "write_mask": "ba"}),
    ("xor", {"logic_op": "xor"}),
    ("and_reverse, write mask rg", {"logic_op": "and_reverse", "write_mask": "rg"}),
]

rng = random.Random(71)
draws = [quad("background", 0, 0, W, 2 * CELL_H, BACKGROUND, W, H, depth_test=False)]


def red_blue_apart(rng):
    """Red high and blue low or the other way round, alpha anywhere: a swap shows in every byte."""
    colours = []
    for k in range(3):
        high, low = round(rng.uniform(0.7, 0.97), 3), round(rng.uniform(0.03, 0.3), 3)
        red, blue = (high, low) if k % 2 == 0 else (low, high)
        colours.append([red, round(rng.uniform(0.1, 0.9), 3), blue, round(rng.uniform(0.1, 0.95), 3)])
    return colours


draws += cell_draws(STATES, rng, W, H, CELL_W, CELL_H, columns=4, jitter=22, margin=0, colours_of=red_blue_apart)

dump("colour_format_bgra.json", {
    "description": "A B8G8R8A8_UNORM colour target with 4x MSAA: eight triangles over a background whose colour and "
    "alpha differ in every corner, one per cell (left to right, top to bottom): " +
    "; ".join(name for name, _ in STATES) + ". Red and blue are far apart in every vertex colour, in the blend "
    "constants [0.9, 0.35, 0.05, 0.6] and in the clear colour (the strip at the bottom), and the write masks name "
    "one of them only, so a target read or written in the wrong byte order differs everywhere. lavapipe blends "
    "B8G8R8A8 in the same 8-bit arithmetic as R8G8B8A8, per channel: the frame (read back as R, G, B, A) is the "
    "R8G8B8A8 frame of the same scene, byte for byte.",
    "framebuffer": {"width": W, "height": H, "colour_format": "b8g8r8a8_unorm", "clear_colour": [0.93, 0.5, 0.08, 0.7],
                    "samples": 4},
    "camera": {"type": "clip_space"},
    "draws": draws})

# ---- colour_format_srgb ----
W, H = 256, 136
CELL_W, CELL_H = 42, 60
SRGB_STATES = [
    ("store", {"enable": False}),
    ("over", {"source": "src_alpha", "destination": "one_minus_src_alpha"}),
    ("additive (same factors)", {"source": "one", "destination": "one"}),
    ("src_alpha twice (same factors)", {"source": "src_alpha", "destination": "src_alpha"}),
    ("subtract, dst_color twice (same factors)", {"source": "dst_color", "destination": "dst_color", "op": "subtract"}),
    ("reverse_subtract, constants", {"colour": {"source": "constant_color", "destination": "one_minus_src_color",
                                                "op": "reverse_subtract"},
                                     "alpha": {"source": "one_minus_constant_alpha", "destination": "dst_alpha"},
                                     "constants": [0.72, 0.3, 0.05, 0.6]}),
    ("saturate", {"colour": {"source": "src_alpha_saturate", "destination": "dst_color"},
                  "alpha": {"source": "one", "destination": "one_minus_src_alpha"}}),
    ("min, alpha add one twice (same factors)", {"colour": {"op": "min", "source": "src_alpha",
                                                            "destination": "zero"},
                                                 "alpha": {"source": "one", "destination": "one"}}),
    ("max, alpha src_alpha / dst_alpha", {"colour": {"op": "max"},
                                          "alpha": {"source": "src_alpha", "destination": "dst_alpha"}}),
    ("write mask rb, over", {"source": "src_alpha", "destination": "one_minus_src_alpha", "write_mask": "rb"}),
    ("logic op xor (not applied)", {"logic_op": "xor"}),
    ("dst_alpha / one_minus_dst_color", {"source": "dst_alpha", "destination": "one_minus_dst_color"}),
]
rng = random.Random(83)
draws = [quad("background", 0, 0, W, 2 * CELL_H, BACKGROUND, W, H, depth_test=False)]


def dark_bright_any(rng):
    """One vertex dark (linear values near the sRGB curve's linear segment), one bright, one anywhere."""
    return [[round(rng.uniform(0.0, 0.006), 4) for _ in range(3)] + [round(rng.uniform(0.1, 0.9), 3)],
            [round(rng.uniform(0.75, 1.0), 3) for _ in range(3)] + [round(rng.uniform(0.1, 0.9), 3)],
            [round(rng.uniform(0.0, 1.0), 3) for _ in range(4)]]


draws += cell_draws(SRGB_STATES, rng, W, H, CELL_W, CELL_H, columns=6, jitter=20, margin=1, colours_of=dark_bright_any)

dump("colour_format_srgb.json", {
    "description": "An R8G8B8A8_SRGB colour target with 4x MSAA: twelve triangles over a background whose colour and "
    "alpha differ in every corner, one per cell (left to right, top to bottom): " +
    "; ".join(name for name, _ in SRGB_STATES) + ". lavapipe blends sRGB targets in linear float: the destination "
    "decoded by a cubic, the result encoded by an approximation built on the CPU's reciprocal square root; where "
    "source and destination factors are the same it computes (s op d) * factor; a logic op is not applied. Each "
    "triangle has a vertex whose colour lies near the linear segment of the sRGB curve. The clear colour "
    "[0.5, 0.2, 0.0031, 0.5] (the strip at the bottom) is encoded by the clear's own table, which gives 188 for 0.5 "
    "where a fragment store gives 187.",
    "framebuffer": {"width": W, "height": H, "colour_format": "r8g8b8a8_srgb", "clear_colour": [0.5, 0.2, 0.0031, 0.5],
                    "samples": 4},
    "camera": {"type": "clip_space"},
    "draws": draws})

# ---- colour_format_10bit ----
W, H = 256, 136
CELL_W, CELL_H = 42, 60
TEN_BIT_STATES = [
    ("store", {"enable": False}),
    ("over", {"source": "src_alpha", "destination": "one_minus_src_alpha"}),
    ("additive", {"source": "one", "destination": "one"}),
    ("subtract, constants", {"colour": {"source": "constant_color", "destination": "one_minus_constant_color",
                                        "op": "subtract"},
                             "alpha": {"source": "constant_alpha", "destination": "one_minus_constant_alpha"},
                             "constants": [0.9, 0.35, 0.05, 0.6]}),
    ("reverse_subtract, dst_alpha", {"source": "dst_alpha", "destination": "one_minus_dst_alpha",
                                     "op": "reverse_subtract"}),
    ("saturate", {"colour": {"source": "src_alpha_saturate", "destination": "dst_color"},
                  "alpha": {"source": "one", "destination": "one_minus_src_alpha"}}),
    ("min, alpha max", {"colour": {"op": "min"}, "alpha": {"op": "max"}}),
    ("max, alpha src_color / dst_color", {"colour": {"op": "max"},
                                          "alpha": {"source": "src_color", "destination": "one_minus_dst_color"}}),
    ("write mask gb, over", {"source": "src_alpha", "destination": "one_minus_src_alpha", "write_mask": "gb"}),
    ("logic op xor", {"logic_op": "xor"}),
    ("logic op and_reverse, write mask ra", {"logic_op": "and_reverse", "write_mask": "ra"}),
    ("logic op invert", {"logic_op": "invert"}),
]
rng = random.Random(97)
draws = [quad("background", 0, 0, W, 2 * CELL_H, BACKGROUND, W, H, depth_test=False)]


def any_any_ends(rng):
    """Two vertices anywhere in [0, 1], one at its ends (0 and 1: the conversion's extremes)."""
    return [[round(rng.uniform(0.0, 1.0), 4) for _ in range(4)],
            [round(rng.uniform(0.0, 1.0), 4) for _ in range(4)],
            [float(rng.choice([0, 1])) for _ in range(4)]]


draws += cell_draws(TEN_BIT_STATES, rng, W, H, CELL_W, CELL_H, columns=6, jitter=20, margin=1, colours_of=any_any_ends)

dump("colour_format_10bit.json", {
    "description": "An A2B10G10R10_UNORM_PACK32 colour target with 4x MSAA: twelve triangles over a background whose "
    "colour and alpha differ in every corner, one per cell (left to right, top to bottom): " +
    "; ".join(name for name, _ in TEN_BIT_STATES) + ". lavapipe blends this format in 16-bit integers: the source "
    "converted to UNORM16, the destination widened from 10 bits ((v << 6) | (v >> 4)) and 2 bits, the result "
    "narrowed by a shift (truncating: even a plain store is not round(x * 1023)) and alpha by a rounded multiply. "
    "Each triangle has a vertex whose channels are 0 or 1. The clear colour [0.9995, 0.25, 0.6, 0.5] (the strip at the "
    "bottom) is packed by the clear's own rounding: red 1022, where a fragment store of 0.9995 gives 1023. Compared "
    "on the stored 10-bit and 2-bit values, every sample and the resolve.",
    "framebuffer": {"width": W, "height": H, "colour_format": "a2b10g10r10_unorm",
                    "clear_colour": [0.9995, 0.25, 0.6, 0.5], "samples": 4},
    "camera": {"type": "clip_space"},
    "draws": draws})

# ---- colour_format_float ----
W, H = 256, 136
CELL_W, CELL_H = 42, 60
FLOAT_STATES = [
    ("store", {"enable": False}),
    ("over", {"source": "src_alpha", "destination": "one_minus_src_alpha"}),
    ("additive (constant ONE factors)", {"source": "one", "destination": "one"}),
    ("subtract, dst_color twice (same factors)", {"source": "dst_color", "destination": "dst_color",
                                                  "op": "subtract"}),
    ("reverse_subtract, constants", {"colour": {"source": "constant_color", "destination": "one_minus_src_color",
                                                "op": "reverse_subtract"},
                                     "alpha": {"source": "one_minus_constant_alpha", "destination": "dst_alpha"},
                                     "constants": [0.72, 0.3, 0.05, 0.6]}),
    ("saturate", {"colour": {"source": "src_alpha_saturate", "destination": "dst_color"},
                  "alpha": {"source": "one", "destination": "one_minus_src_alpha"}}),
    ("zero / one (constant factors)", {"source": "zero", "destination": "one"}),
    ("one / zero, alpha one / one (mixed factors)", {"colour": {"source": "one", "destination": "zero"},
                                                     "alpha": {"source": "one", "destination": "one"}}),
    ("min, alpha max", {"colour": {"op": "min"}, "alpha": {"op": "max"}}),
    ("write mask rb, over", {"source": "src_alpha", "destination": "one_minus_src_alpha", "write_mask": "rb"}),
    ("logic op xor (not applied)", {"logic_op": "xor"}),
    ("dst_alpha / one_minus_dst_color", {"source": "dst_alpha", "destination": "one_minus_dst_color"}),
]
rng = random.Random(101)
# A background beyond [0, 1]: bright, negative, and past the largest half (65504) in one corner.
background = [[2.5, -0.75, 0.3, 1.5], [0.25, 3.0, -1.5, 0.5], [70000.0, 0.5, 0.002, -0.25], [0.00001, 0.8, 1.25, 2.0]]
draws = [quad("background", 0, 0, W, 2 * CELL_H, background, W, H, depth_test=False)]


def unit_beyond_tiny(rng):
    """One vertex in [0, 1], one beyond it both ways, one tiny (half denormals, below 2^-14)."""
    return [[round(rng.uniform(0.0, 1.0), 4) for _ in range(4)],
            [round(rng.uniform(-3.0, 40.0), 3) for _ in range(4)],
            [round(rng.uniform(0.0, 0.00004), 9) for _ in range(3)] + [round(rng.uniform(0.1, 0.9), 3)]]


draws += cell_draws(FLOAT_STATES, rng, W, H, CELL_W, CELL_H, columns=6, jitter=20, margin=1,
                    colours_of=unit_beyond_tiny)
# In the bottom strip's right end, a quad whose every value is a half denormal (below 2^-14).
draws.append(quad("half denormals", 180, 2 * CELL_H + 3, 70, 12,
                  [[0.00006, 0.0000001, 0.00003, 0.00005], [0.000001, 0.00004, 0.00006, 0.00002],
                   [0.00002, 0.000059, 0.0000003, 0.00001], [0.00005, 0.00001, 0.00004, 0.00006]], W, H,
                  depth_test=False))

dump("colour_format_float.json", {
    "description": "An R16G16B16A16_SFLOAT colour target with 4x MSAA (the test draws it into R32G32B32A32_SFLOAT "
    "too): twelve triangles over a background whose corners lie beyond [0, 1] (one past the largest half, 65504), one "
    "per cell (left to right, top to bottom): " + "; ".join(name for name, _ in FLOAT_STATES) + ". lavapipe blends "
    "float targets in float without clamping: the same-factor shortcut (s op d) * factor, ONE and ZERO factors for "
    "colour and alpha alike as constants (no multiply), MIN and MAX in minps/maxps order, no logic op; halves are "
    "stored rounding toward zero (finite values past 65504 stay at 65504), floats as they are, under FTZ and DAZ. "
    "Each triangle has a vertex beyond [0, 1] and one tiny enough for half denormals; a quad at the right end of "
    "the bottom strip holds nothing but half denormals. The clear colour "
    "[100000, -2.5, 0.3, 3] (the strip at the bottom) stores as [65504, -2.5, 0.2998, 3] in halves (0.3 rounds "
    "toward zero).",
    "framebuffer": {"width": W, "height": H, "colour_format": "r16g16b16a16_sfloat",
                    "clear_colour": [100000.0, -2.5, 0.3, 3.0], "samples": 4},
    "camera": {"type": "clip_space"},
    "draws": draws})
