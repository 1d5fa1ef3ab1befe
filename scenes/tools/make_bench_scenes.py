#!/usr/bin/env python3
"""Writes the bench scenes (bench/*.json, for `crosscheck bench`) and their small copies in this
folder (bench_*.json), which the conformance suite cross-checks in every test run. All but the
lit ones (the per-pixel lit room, the Blinn-Phong quad) use the vertex_color shading model. The spheres are procedural ("sphere" draws), so no large mesh file is
committed; the small triangles are inline and seeded, so every run writes the same files.
Run from scenes/:  python3 tools/make_bench_scenes.py"""
import json
import math
import random

HD_W, HD_H = 1920, 1080

# scenes/room.json's content; its focal length (120 px at 240 px high) scaled with the height, so
# every size sees the same vertical field of view.
with open("room.json") as f:
    ROOM = json.load(f)


def write(path, scene, compact=False):
    with open(path, "w") as f:
        if compact:
            json.dump(scene, f, separators=(",", ":"))
        else:
            json.dump(scene, f, indent=1)
        f.write("\n")


def room(width, height, description, samples=1):
    scene = json.loads(json.dumps(ROOM))
    scene["description"] = description
    scene["framebuffer"]["width"] = width
    scene["framebuffer"]["height"] = height
    if samples > 1:
        scene["framebuffer"]["samples"] = samples
    scene["camera"]["focal_length"] = ROOM["camera"]["focal_length"] * height / ROOM["framebuffer"]["height"]
    for d in scene["draws"]:
        d["obj"] = "../" + d["obj"]  # bench/ is one folder down
    return scene


def quad(z, colour, name):
    """A full-screen quad in clip space (w = 1) at depth z: two triangles, indexed."""
    return {"name": name, "positions": [[-1, -1, z], [1, -1, z], [1, 1, z], [-1, 1, z]],
            "colours": [colour] + [[round(c * f, 4) for c in colour] for f in (0.8, 0.6, 0.9)],
            "indices": [0, 1, 2, 0, 2, 3], "cull": "none", "depth_compare": "less"}


PALETTE = [[0.9, 0.2, 0.2], [0.2, 0.8, 0.2], [0.2, 0.3, 0.9], [0.9, 0.8, 0.2], [0.8, 0.3, 0.8],
           [0.2, 0.8, 0.8], [0.95, 0.55, 0.15], [0.6, 0.6, 0.6], [0.5, 0.9, 0.4], [0.9, 0.5, 0.7]]


def quad_stack(width, height, front_to_back, description):
    depths = [0.9 - 0.05 * i for i in range(10)]  # far to near
    if front_to_back:
        depths.reverse()
    draws = [quad(round(z, 4), PALETTE[i], "quad_%d" % i) for i, z in enumerate(depths)]
    return {"description": description,
            "framebuffer": {"width": width, "height": height, "clear_colour": [0, 0, 0, 1]},
            "camera": {"type": "clip_space"}, "draws": draws}


def sphere_scene(width, height, segments, rings, description, **state):
    draw = {"name": "sphere", "sphere": {"segments": segments, "rings": rings, "radius": 1, "centre": [0, 0, 0]},
            "cull": "back"}
    draw.update(state)
    return {"description": description,
            "framebuffer": {"width": width, "height": height, "clear_colour": [0.05, 0.05, 0.05, 1]},
            "camera": {"type": "pinhole", "position": [0.013, -0.021, -3], "yaw": 1.3, "pitch": -0.7,
                       "focal_length": height, "near": 0.5, "far": 10},
            "draws": [draw]}


def small_triangles(width, height, count, seed, description, area=10.0, groups=10):
    """`count` triangles of about `area` pixels each, scattered over the frame at random depths
    and orientations (both windings, culling off), in clip space; in `groups` draws of one colour
    each (the file stays small: 4 decimals per coordinate, no per-vertex colours)."""
    rng = random.Random(seed)
    side = math.sqrt(4 * area / math.sqrt(3))  # an equilateral triangle of that area
    draws = []
    for g in range(groups):
        positions = []
        for _ in range(count // groups):
            cx, cy = rng.uniform(4, width - 4), rng.uniform(4, height - 4)
            z = rng.uniform(0.05, 0.95)
            angle = rng.uniform(0, 2 * math.pi)
            order = [0, 1, 2] if rng.random() < 0.5 else [0, 2, 1]
            corners = []
            for k in range(3):
                a = angle + 2 * math.pi * k / 3
                px = cx + side / math.sqrt(3) * math.cos(a)
                py = cy + side / math.sqrt(3) * math.sin(a)
                corners.append([round(2 * px / width - 1, 4), round(2 * py / height - 1, 4), round(z, 3)])
            positions.extend(corners[k] for k in order)
        draws.append({"name": "small_triangles_%d" % g, "positions": positions, "colour": PALETTE[g % len(PALETTE)],
                      "cull": "none"})
    return {"description": description,
            "framebuffer": {"width": width, "height": height, "clear_colour": [0, 0, 0, 1]},
            "camera": {"type": "clip_space"}, "draws": draws}


# The bench: each scene stresses one part of the pipeline at 1080p (and the room also at 500x500).
write("bench/room_500.json", room(500, 500, "Bench: scenes/room.json at 500x500: a few large clipped triangles, "
                                            "fill-rate bound at a small size."))
write("bench/room_1080p.json", room(HD_W, HD_H, "Bench: scenes/room.json at 1920x1080: a few large clipped "
                                                "triangles covering the whole frame, fill-rate bound."))
write("bench/room_msaa_1080p.json", room(HD_W, HD_H, "Bench: scenes/room.json at 1920x1080 with 4x MSAA: "
                                                     "per-sample coverage and depth, four times the memory, "
                                                     "and the resolve.", samples=4))
write("bench/quad_1080p.json", {
    "description": "Bench: one full-screen quad (2 triangles) at 1920x1080: the cost of filling every pixel once, "
                   "close to the memory limit.",
    "framebuffer": {"width": HD_W, "height": HD_H, "clear_colour": [0, 0, 0, 1]},
    "camera": {"type": "clip_space"}, "draws": [quad(0.5, [0.3, 0.6, 0.9], "quad")]})
write("bench/quad_stack_back_to_front.json", quad_stack(HD_W, HD_H, False,
      "Bench: 10 full-screen quads at 1920x1080 drawn back to front with depth test LESS: every quad passes, "
      "10x overdraw of shading and depth writes."))
write("bench/quad_stack_front_to_back.json", quad_stack(HD_W, HD_H, True,
      "Bench: 10 full-screen quads at 1920x1080 drawn front to back with depth test LESS: only the first passes, "
      "the other nine are rejected by the depth test (early depth)."))
write("bench/sphere_100k.json", sphere_scene(HD_W, HD_H, 250, 201,
      "Bench: a procedural sphere of 100,000 triangles (250 segments, 201 rings) at 1920x1080, back faces "
      "culled: vertex processing, setup and small triangles."))
write("bench/sphere_1m.json", sphere_scene(HD_W, HD_H, 1000, 501,
      "Bench: a procedural sphere of 1,000,000 triangles (1000 segments, 501 rings) at 1920x1080, back faces "
      "culled: geometry bound, most triangles cover less than a pixel."))
write("bench/small_triangles_1080p.json", small_triangles(HD_W, HD_H, 20000, 2026,
      "Bench: 20,000 scattered triangles of about 10 pixels each at 1920x1080, random depths, both windings: "
      "per-triangle setup cost (10 draws of 2000)."), compact=True)
write("bench/wireframe_sphere_100k.json", sphere_scene(HD_W, HD_H, 250, 201,
      "Bench: the 100,000-triangle sphere in polygon mode LINE at 1920x1080: lavapipe's draw-pipeline path, "
      "three lines per front-facing triangle.", polygon_mode="line"))



def lit_room(width, height, description):
    """The per-pixel lit room (light_room_pixel.json) at another size."""
    with open("light_room_pixel.json") as f:
        scene = json.load(f)
    scene["description"] = description
    scene["framebuffer"]["width"], scene["framebuffer"]["height"] = width, height
    scene["camera"]["focal_length"] = ROOM["camera"]["focal_length"] * height / ROOM["framebuffer"]["height"]
    for d in scene["draws"]:
        d["obj"] = "../" + d["obj"]
    return scene


def phong_quad(width, height, description):
    """A full-screen plane facing the camera, lit per pixel with Blinn-Phong."""
    hw, hh = 2.2, 1.25  # beyond the view at 60 degrees and 16:9 from z = -2
    return {"description": description,
            "framebuffer": {"width": width, "height": height, "clear_colour": [0, 0, 0, 1]},
            "camera": {"type": "look_at", "eye": [0, 0, -2], "target": [0, 0, 0], "up": [0, -1, 0], "fov_y": 60},
            "light": {"position": [0.4, -0.3, -0.6], "colour": [1, 0.95, 0.9]},
            "draws": [{"name": "quad", "positions": [[-hw, -hh, 0], [hw, -hh, 0], [hw, hh, 0], [-hw, hh, 0]],
                       "colours": [[0.8, 0.3, 0.2], [0.3, 0.8, 0.2], [0.2, 0.3, 0.8], [0.7, 0.7, 0.7]],
                       # wound so the flat normal (b - a) x (c - a) faces the camera (-z)
                       "indices": [0, 3, 2, 0, 2, 1], "cull": "none", "shading": "blinn_phong_pixel",
                       "normals": "flat",
                       "material": {"ambient": [0.1, 0.1, 0.1], "specular": [0.6, 0.6, 0.6], "shininess": 32}}],
            "tolerance": {"colour": 0}}


write("bench/light_room_1080p.json", lit_room(HD_W, HD_H, "Bench: scenes/light_room_pixel.json at 1920x1080: the "
      "course's light model evaluated per pixel over the whole frame (two normalizes and a division per pixel)."))
write("bench/phong_quad_1080p.json", phong_quad(HD_W, HD_H,
      "Bench: a full-screen quad lit per pixel with Blinn-Phong at 1920x1080: the cost of a real fragment shader "
      "(three normalizes, a pow) on every pixel. A warm highlight right of centre on a colour-graded plane."))

# Small copies for the conformance suite: the same cases at sizes that cross-check in a moment.
write("bench_quad_stack.json", quad_stack(320, 240, False,
      "Small copy of bench/quad_stack_back_to_front.json: 10 full-screen quads in clip space drawn back to front "
      "with depth test LESS, every one passes; full-screen edges on the framebuffer border."))
write("bench_quad_stack_front_to_back.json", quad_stack(320, 240, True,
      "Small copy of bench/quad_stack_front_to_back.json: 10 full-screen quads drawn front to back with depth test "
      "LESS: the first covers every pixel, the other nine are all rejected by the depth test."))
write("bench_sphere_small.json", sphere_scene(320, 240, 64, 33,
      "Small copy of bench/sphere_100k.json: a procedural sphere of 4096 triangles (64 segments, 33 rings), "
      "colours from its normals, back faces culled: the sphere draw field's mesh and winding."))
write("bench_small_triangles.json", small_triangles(320, 240, 1000, 7,
      "Small copy of bench/small_triangles_1080p.json: 1000 scattered triangles of about 10 pixels, random "
      "depths and windings, culling off, in 10 draws: small-triangle coverage and depth."), compact=True)
write("bench_wireframe_sphere.json", sphere_scene(320, 240, 48, 25,
      "Small copy of bench/wireframe_sphere_100k.json: a procedural sphere of 2304 triangles in polygon mode "
      "LINE, back faces culled: many short lines sharing endpoints.", polygon_mode="line"))
write("bench_phong_quad.json", phong_quad(320, 180,
      "Small copy of bench/phong_quad_1080p.json: a full-screen quad lit per pixel with Blinn-Phong; a highlight right "
      "of centre on a colour-graded plane. Tests the per-pixel Blinn-Phong model over every pixel."))
