"""The layout helpers the feature and topology scene generators share: a 256x192 frame seen through
a pinhole camera at the origin (looking along +z, y down, focal length F), geometry placed in pixels
and unprojected to world positions, draws and scene files in the scene format."""
import json
import math

W, H, F = 256, 192, 200.0
CAMERA = {"type": "pinhole", "position": [0, 0, 0], "focal_length": F, "near": 0.5, "far": 20}
FRAMEBUFFER = {"width": W, "height": H, "clear_colour": [0.1, 0.1, 0.1, 1]}
PALETTE = [[0.9, 0.2, 0.2], [0.2, 0.8, 0.2], [0.2, 0.3, 0.9], [0.9, 0.8, 0.2], [0.8, 0.3, 0.8],
           [0.2, 0.8, 0.8], [0.95, 0.55, 0.15], [0.6, 0.6, 0.6]]


def at(px, py, z):
    """World position seen at pixel (px, py) at camera depth z (with the ordinary viewport)."""
    return [round((px - W / 2) * z / F, 6), round((py - H / 2) * z / F, 6), round(z, 6)]


def ccw(x, y, w, h, z=2.0):
    """Counter-clockwise on screen (Vulkan's sense, y down): top-left, bottom-left, top-right."""
    return [at(x, y, z), at(x, y + h, z), at(x + w, y, z)]


def cw(x, y, w, h, z=2.0):
    return [at(x, y, z), at(x + w, y, z), at(x, y + h, z)]


def strip(x0, y0, step, height, n, z0, z1):
    """n strip vertices zig-zagging between rows y0 and y0 + height, depth from z0 to z1."""
    pts = []
    for i in range(n):
        pts.append(at(x0 + (i // 2) * step, y0 + (height if i % 2 else 0), z0 + (z1 - z0) * i / (n - 1)))
    return pts


def fan(cx, cy, r, n, z, turn=0.9):
    """A fan's centre and n rim vertices over `turn` of a full circle, depth rippling around z."""
    pts = [at(cx, cy, z)]
    for k in range(n):
        a = 2 * math.pi * k / (n - 1) * turn
        pts.append(at(cx + r * math.cos(a), cy - r * math.sin(a), z + 0.3 * math.sin(3 * a)))
    return pts


def draw(name, positions, colours=None, **state):
    d = {"name": name, "positions": positions}
    if colours is not None:
        d["colours"] = colours
    d.update(state)
    return d


def rainbow(n, offset=0):
    return [PALETTE[(i + offset) % len(PALETTE)] for i in range(n)]


def scene(filename, description, draws, framebuffer=None, camera=None, tolerance=None):
    s = {"description": description, "framebuffer": framebuffer or FRAMEBUFFER, "camera": camera or CAMERA,
         "draws": draws}
    if tolerance:
        s["tolerance"] = tolerance
    with open(filename, "w") as f:
        json.dump(s, f, indent=1)
        f.write("\n")
