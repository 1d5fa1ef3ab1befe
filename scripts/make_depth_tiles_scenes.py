#!/usr/bin/env python3
"""Writes the conformance scenes of softraster's per-tile depth bounds (fast/depth_tiles.hpp):
scenes/depth_tiles_d16.json, _x8_d24.json and _d32.json, one per depth format, 300x200 (not a
multiple of the 32-pixel tiles either way). The same sequence of large draws in each: walls that
narrow the tiles, walls behind them (skipped) and at exactly their depth (LESS fails,
LESS_OR_EQUAL passes), a slanted wall crossing one, a triangle and a scissored wall covering
tiles in part (which must not narrow them: the walls after them pass where they did not reach),
ALWAYS, GREATER, GREATER_OR_EQUAL, NOT_EQUAL and EQUAL at one depth, a wall that passes only by
its depth bias and one only by depth clamp, and a wall with depth writes off.
Usage:  python3 scripts/make_depth_tiles_scenes.py   (from the repository's root)"""
import json

WIDTH, HEIGHT = 300, 200


def wall(name, z, colour, compare="less", z_right=None, **extra):
    """A quad over the whole viewport at depth z (z_right: its depth at the right edge)."""
    right = z if z_right is None else z_right
    draw = {
        "name": name,
        "positions": [[-1, -1, z], [1, -1, right], [1, 1, right], [-1, 1, z]],
        "colours": [colour, [c * 0.8 for c in colour], [c * 0.6 for c in colour], [c * 0.9 for c in colour]],
        "indices": [0, 1, 2, 0, 2, 3],
        "cull": "none",
        "depth_compare": compare,
    }
    draw.update(extra)
    return draw


def scene(format_name, bias_units):
    draws = [
        wall("near wall (narrows the tiles it covers whole)", 0.5, [0.9, 0.2, 0.2]),
        wall("behind it: skipped", 0.6, [0.2, 0.9, 0.2]),
        wall("at its depth, less: fails", 0.5, [0.2, 0.2, 0.9]),
        wall("at its depth, less_or_equal: passes", 0.5, [0.9, 0.9, 0.2], "less_or_equal"),
        wall("slanted 0.3 to 0.7: the left passes", 0.3, [0.2, 0.9, 0.9], z_right=0.7),
        {
            "name": "triangle at 0.1 over the upper left (tiles covered in part)",
            "positions": [[-1, -1, 0.1], [0.7, -1, 0.1], [-1, 0.9, 0.1]],
            "colours": [[0.9, 0.5, 0.1]] * 3,
            "cull": "none",
        },
        wall("at 0.2: passes where the triangle did not reach", 0.2, [0.5, 0.1, 0.9]),
        wall("always at 0.9 (every pixel 0.9; ALWAYS leaves the tiles open)", 0.9, [0.3, 0.6, 0.3], "always"),
        wall("greater at 0.8: fails everywhere", 0.8, [0.9, 0.1, 0.5], "greater"),
        wall("greater_or_equal at 0.9: passes", 0.9, [0.1, 0.5, 0.9], "greater_or_equal"),
        wall("not_equal at 0.9: fails", 0.9, [0.9, 0.9, 0.9], "not_equal"),
        wall("equal at 0.9: passes", 0.9, [0.6, 0.3, 0.1], "equal"),
        wall("behind at 0.905, passes by its bias", 0.905, [0.1, 0.6, 0.6],
             depth_bias={"constant": bias_units, "slope": 0, "clamp": 0}),
        wall("far beyond (z 1.5), clamped into [0.3, 0.6]: passes", 1.5, [0.7, 0.7, 0.1], depth_clamp=True,
             viewport={"x": 0, "y": 0, "width": WIDTH, "height": HEIGHT, "min_depth": 0.3, "max_depth": 0.6}),
        wall("at 0.55, writes off: passes, leaves 0.6", 0.55, [0.4, 0.4, 0.8], depth_write=False),
        wall("scissored at 0.1 (tiles covered in part)", 0.1, [0.8, 0.3, 0.6],
             scissor={"x": 37, "y": 21, "width": 150, "height": 101}),
        wall("at 0.58: passes outside the scissor", 0.58, [0.2, 0.7, 0.4]),
    ]
    return {
        "description": f"Per-tile depth bounds on {format_name.upper()}: large walls drawn in an order that narrows, "
                       "skips and must not skip 32x32 tiles (scripts/make_depth_tiles_scenes.py says which is which).",
        "framebuffer": {"width": WIDTH, "height": HEIGHT, "clear_colour": [0, 0, 0, 1], "depth_format": format_name},
        "camera": {"type": "clip_space"},
        "draws": draws,
    }


# The bias's constant in each format's units r: about -0.012 of depth (D16: r = 2^-16; D24 and D32
# at depths in [0.5, 1): r = 2^-24).
for suffix, format_name, units in (("d16", "d16_unorm", -780), ("x8_d24", "x8_d24_unorm", -200000),
                                  ("d32", "d32_sfloat", -200000)):
    with open(f"scenes/depth_tiles_{suffix}.json", "w") as out:
        json.dump(scene(format_name, units), out, indent=1)
        out.write("\n")
