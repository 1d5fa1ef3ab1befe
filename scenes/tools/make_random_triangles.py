#!/usr/bin/env python3
"""Writes random_triangles.json: many random triangles with random vertex colours, seen by a
pinhole camera, many of them crossing the near plane, the sides of the view or reaching behind
the camera. Exists to hold the exact method to lavapipe on thousands of arbitrary edges, partial
pixels, perspective-correct colours, clipped polygons, both windings and vertex batches (lavapipe
splits draws into batches of 341 triangles; a batch with any clipped vertex takes a different path).
Run from scenes/:  python3 tools/make_random_triangles.py"""
import json
import random

rng = random.Random(20261123)

def point():
    # Mostly in front of the camera, some behind it (z < 0) and some far to the sides.
    return [round(rng.uniform(-5, 5), 4), round(rng.uniform(-4, 4), 4), round(rng.uniform(-0.5, 12.0), 4)]

def draw(name, count, cull):
    positions, colours = [], []
    for _ in range(count):
        centre = point()
        size = rng.choice([0.02, 0.1, 0.1, 0.3, 0.3, 0.3, 0.8, 1.5])
        for _ in range(3):
            positions.append([round(c + rng.uniform(-size, size), 4) for c in centre])
            colours.append([round(rng.random(), 3) for _ in range(3)])
    return {"name": name, "positions": positions, "colours": colours, "cull": cull}

scene = {
    "description": ("Random triangles with random vertex colours, many crossing the near plane and the sides "
                    "of the view: exact coverage, depth and perspective-correct colour on thousands of "
                    "arbitrary edges, across lavapipe's vertex batches, with and without back-face culling."),
    "framebuffer": {"width": 256, "height": 192, "clear_colour": [0.1, 0.1, 0.1, 1]},
    "camera": {"type": "pinhole", "position": [0, 0, -1], "focal_length": 150, "near": 0.1, "far": 20},
    "draws": [draw("culled", 1200, "back"), draw("unculled", 300, "none")],
    "tolerance": {"colour": 1, "depth": 5.9604645e-08},
}
with open("random_triangles.json", "w") as f:
    json.dump(scene, f, separators=(",", ":"))
    f.write("\n")
