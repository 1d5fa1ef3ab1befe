#!/usr/bin/env python3
"""Writes the stability suite, stability/*.json (for `crosscheck stability`; the conformance suite
cross-checks them too): one scene per case of "where methods fail". The cases the stress scenes
of this folder already draw are copies of them under the case's name (mesh paths made relative to
stability/); the new ones (sub-pixel and zero-area triangles apart from the slivers, the tiny near
plane) are made here, seeded, so every run writes the same files.
Run from scenes/:  python3 tools/make_stability_scenes.py"""
import json
import math
import os
import random

OUT = "stability"

# case file -> the stress scene it copies, and what the case is.
COPIES = {
    "near_plane_crossing": ("near_plane_triangle", "Stability: a triangle across the near plane."),
    "inside_room_yaw_90": ("room_yaw_90", "Stability: the camera turned 90 degrees inside the room."),
    "inside_room_yaw_180": ("room_yaw_180", "Stability: the camera turned 180 degrees inside the room."),
    "behind_camera_only": ("behind_camera", "Stability: a triangle behind the camera."),
    "closed_mesh_edges": ("sphere_coverage", "Stability: the shared edges of a closed mesh (cracks and double hits)."),
    "slivers_needles": ("slivers", "Stability: slivers and needles."),
    "huge_coordinate_values": ("huge_coordinates", "Stability: huge coordinates."),
    "coplanar_z_fighting": ("z_fighting", "Stability: coplanar z-fighting."),
    "nan_inf_vertices": ("nan_inf", "Stability: NaN and Inf vertices."),
    "w_zero_vertices": ("w_zero", "Stability: w = 0."),
}

COLOURS = [[0.9, 0.2, 0.2], [0.2, 0.8, 0.2], [0.2, 0.3, 0.9], [0.9, 0.8, 0.2], [0.8, 0.3, 0.8], [0.2, 0.8, 0.8]]


def write(name, scene, compact=False):
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        if compact:
            json.dump(scene, f, separators=(",", ":"))
        else:
            json.dump(scene, f, indent=1)
        f.write("\n")


def copy(name, source, what):
    with open(source + ".json") as f:
        scene = json.load(f)
    scene["description"] = what + " A copy of scenes/" + source + ".json: " + scene["description"]
    for draw in scene["draws"]:
        if "obj" in draw:
            draw["obj"] = "../" + draw["obj"]
    write(name, scene)


def pinhole(near=0.5, far=20):
    return {"type": "pinhole", "position": [0, 0, 0], "focal_length": 200.0, "near": near, "far": far}


def sub_pixel():
    # Triangles of 0.05 to 0.9 pixels across, at random sub-pixel positions over a 48x40 pixel patch
    # at depth 2 (1 pixel = 0.01 units at focal length 200): most cover no pixel centre, some one.
    rng = random.Random(11)
    positions, colours = [], []
    z = 2.0
    unit = z / 200.0
    for i in range(1500):
        cx = rng.uniform(-24, 24) * unit
        cy = rng.uniform(-20, 20) * unit
        size = rng.uniform(0.05, 0.9) * unit
        a = rng.uniform(0, 2 * math.pi)
        for k in range(3):
            t = a + k * 2 * math.pi / 3 + rng.uniform(-0.4, 0.4)
            positions.append([round(cx + size * math.cos(t), 6), round(cy + size * math.sin(t), 6), z])
            colours.append(COLOURS[(i + k) % len(COLOURS)])
    # A reference quad below, so the frame is never empty.
    ref = [[-0.4, 0.3, 2.5], [0.4, 0.3, 2.5], [0.4, 0.45, 2.5], [-0.4, 0.3, 2.5], [0.4, 0.45, 2.5], [-0.4, 0.45, 2.5]]
    return {
        "description": "Stability: sub-pixel triangles, 1500 of them, 0.05 to 0.9 pixels across at random sub-pixel "
        "positions, most covering no pixel centre; cull none; a reference quad below.",
        "framebuffer": {"width": 256, "height": 192, "clear_colour": [0.1, 0.1, 0.1, 1]},
        "camera": pinhole(),
        "draws": [
            {"name": "sub-pixel", "positions": positions, "colours": colours, "cull": "none"},
            {"name": "reference", "positions": ref, "colours": [COLOURS[1]] * 6, "cull": "none"},
        ],
    }


def zero_area():
    # Degenerate triangles: three equal vertices, two equal, three collinear (horizontal, vertical,
    # diagonal, along a pixel-centre row), each drawn with both windings, between two reference
    # triangles that share an edge with them.
    tris = []
    z = 2.0
    tris += [[[0.1, 0.1, z]] * 3]
    tris += [[[-0.2, -0.1, z], [-0.2, -0.1, z], [0.3, 0.2, z]]]
    tris += [[[-0.5, 0.0, z], [0.0, 0.0, z], [0.5, 0.0, z]]]                 # along a row
    tris += [[[-0.3, -0.4, z], [-0.3, 0.1, z], [-0.3, 0.4, z]]]              # along a column
    tris += [[[-0.6, -0.6, z], [0.0, 0.0, z], [0.6, 0.6, z]]]                # the diagonal
    tris += [[[-0.6, 0.005, z], [0.0, 0.005, z], [0.6, 0.005, z]]]           # through pixel centres
    tris += [[[0.2, -0.5, 1.5], [0.2, -0.5, 2.0], [0.2, -0.5, 3.0]]]         # collinear in depth
    both = []
    for t in tris:
        both.append(t)
        both.append([t[0], t[2], t[1]])
    positions = [v for t in both for v in t]
    colours = [COLOURS[i % len(COLOURS)] for i in range(len(positions))]
    ref = [[-1.0, 0.5, 2.2], [1.0, 0.5, 2.2], [0.0, 0.9, 2.2], [-1.0, -0.5, 2.2], [0.0, -0.9, 2.2], [1.0, -0.5, 2.2]]
    return {
        "description": "Stability: zero-area triangles (three equal vertices, two equal, collinear along a row, a "
        "column, the diagonal, through pixel centres and in depth), both windings, cull none: none may draw a "
        "pixel; two reference triangles show the frame.",
        "framebuffer": {"width": 256, "height": 192, "clear_colour": [0.1, 0.1, 0.1, 1]},
        "camera": pinhole(),
        "draws": [
            {"name": "zero-area", "positions": positions, "colours": colours, "cull": "none"},
            {"name": "reference", "positions": ref, "colours": [COLOURS[2]] * 6, "cull": "none"},
        ],
    }


def tiny_near_plane():
    # near = 1e-4, far = 1000: window depth near 1 for everything past a few units, so interleaved
    # planes 1% apart at 40 to 60 units fight for the last bits of a 32-bit float depth.
    draws = []
    for i in range(6):
        z0 = 40.0 + 4.0 * i
        tilt = 0.4 if i % 2 == 0 else -0.4
        w = 30.0
        quad = [[-w, -w, z0 - tilt * w], [w, -w, z0 + tilt * w], [w, w, z0 + tilt * w],
                [-w, -w, z0 - tilt * w], [w, w, z0 + tilt * w], [-w, w, z0 - tilt * w]]
        draws.append({"name": "plane %d" % i, "positions": quad, "colours": [COLOURS[i % len(COLOURS)]] * 6,
                      "cull": "none"})
    return {
        "description": "Stability: depth precision with a tiny near plane (near 1e-4, far 1000): six tilted planes "
        "crossing each other 40 to 60 units away, where window depth is within 3e-6 of 1; depth test LESS on D32.",
        "framebuffer": {"width": 256, "height": 192, "clear_colour": [0.1, 0.1, 0.1, 1]},
        "camera": pinhole(near=1e-4, far=1000),
        "draws": draws,
    }


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, (source, what) in COPIES.items():
        copy(name, source, what)
    write("sub_pixel_triangles", sub_pixel(), compact=True)
    write("zero_area_triangles", zero_area())
    write("tiny_near_plane", tiny_near_plane())


if __name__ == "__main__":
    main()
