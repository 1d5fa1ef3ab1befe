#!/usr/bin/env python3
"""Writes scenes/pass_many_draws.json, the conformance scene of softraster's passes
(softraster/pass.hpp): 160 draws into one 300x200 framebuffer (7 bands of 32 rows, the last in
part; not a multiple of the 32-pixel tiles), which a pass on several threads keeps and then draws
band by band, draw after draw. The draws overlap everywhere and change what each band must see in
order: walls over the whole frame with every depth compare op (each one narrows or opens the
tiles' depth bounds differently), depth writes on and off, scissored walls and scattered small
triangles at assorted depths between them, some in polygon mode line, some with a depth bias.
A deterministic sequence (a fixed linear congruential generator, no library random numbers), so
the file is the same on every run.
Usage:  python3 scripts/make_pass_scene.py   (from the repository's root)"""
import json

WIDTH, HEIGHT = 300, 200
COMPARES = ["less", "less_or_equal", "greater", "greater_or_equal", "equal", "not_equal", "always", "never"]


class Sequence:
    """A linear congruential generator (Knuth's MMIX constants): the same numbers everywhere."""

    def __init__(self, seed):
        self.state = seed

    def unit(self):
        self.state = (self.state * 6364136223846793005 + 1442695040888963407) % 2**64
        return (self.state >> 11) / 2**53

    def pick(self, items):
        return items[int(self.unit() * len(items))]


def rounded(v):
    return round(v, 4)


def wall(name, z, colour, compare, **extra):
    draw = {
        "name": name,
        "positions": [[-1, -1, z], [1, -1, z], [1, 1, z], [-1, 1, z]],
        "colours": [colour, [rounded(c * 0.8) for c in colour], [rounded(c * 0.6) for c in colour], colour],
        "indices": [0, 1, 2, 0, 2, 3],
        "cull": "none",
        "depth_compare": compare,
    }
    draw.update(extra)
    return draw


def triangles(name, seq, count, compare, **extra):
    positions, colours = [], []
    for _ in range(count):
        x, y, size = -1.1 + 2.2 * seq.unit(), -1.1 + 2.2 * seq.unit(), 0.05 + 0.25 * seq.unit()
        z = rounded(seq.pick([0.25, 0.5, 0.75]) if seq.unit() < 0.3 else 0.05 + 0.9 * seq.unit())
        colour = [rounded(0.1 + 0.9 * seq.unit()) for _ in range(3)]
        positions += [[rounded(x), rounded(y), z], [rounded(x + size), rounded(y), z], [rounded(x), rounded(y + size), z]]
        colours += [colour] * 3
    draw = {"name": name, "positions": positions, "colours": colours, "cull": "none", "depth_compare": compare}
    draw.update(extra)
    return draw


def scene():
    seq = Sequence(2026)
    draws = []
    for k in range(160):
        compare = seq.pick(COMPARES[:7]) if k % 9 else "never"
        colour = [rounded(0.1 + 0.9 * seq.unit()) for _ in range(3)]
        extra = {}
        if seq.unit() < 0.2:
            extra["depth_write"] = False
        if k % 4 == 0:  # a wall, at one of the levels the triangles also use (exact ties for equal)
            z = seq.pick([0.25, 0.5, 0.75, 0.9])
            if seq.unit() < 0.3:
                extra["scissor"] = {"x": int(seq.unit() * 150), "y": int(seq.unit() * 100),
                                    "width": 40 + int(seq.unit() * 150), "height": 20 + int(seq.unit() * 100)}
            draws.append(wall(f"{k}: wall at {z}, {compare}", z, colour, compare, **extra))
        else:
            if seq.unit() < 0.15:
                extra["polygon_mode"] = "line"
            if seq.unit() < 0.15:
                extra["depth_bias"] = {"constant": -2000, "slope": 0, "clamp": 0}
            draws.append(triangles(f"{k}: triangles, {compare}", seq, 1 + int(seq.unit() * 12), compare, **extra))
    return {
        "description": "Passes: 160 overlapping draws (walls with every depth compare op, scissored walls, scattered "
                       "triangles, writes on and off, lines, bias) that softraster keeps in one pass and draws band by "
                       "band, draw after draw (scripts/make_pass_scene.py).",
        "framebuffer": {"width": WIDTH, "height": HEIGHT, "clear_colour": [0, 0, 0, 1], "depth_format": "d32_sfloat",
                        "clear_depth": 0.6},
        "camera": {"type": "clip_space"},
        "draws": draws,
    }


# One draw per line: the file stays readable at 160 draws.
s = scene()
draws = s.pop("draws")
text = json.dumps(s, indent=1)[:-2] + ',\n "draws": [\n' + ",\n".join("  " + json.dumps(d) for d in draws) + "\n ]\n}\n"
json.loads(text)
with open("scenes/pass_many_draws.json", "w") as out:
    out.write(text)
