#!/usr/bin/env python3
"""Writes the project's textures (textures/*.png, small and generated here, so nothing binary comes
from outside) and the texture scenes of the conformance suite (texture_*.json).
Textures: a 64x64 checkerboard with coloured cell borders (mipmapped in the scenes: its 7 levels
blur to grey), 8x8 and 48x40 seeded noise with alpha (every texel differs from its neighbours, so
every filter weight shows), a 16x16 arrow pattern (which way is u, which way is v).
Run from scenes/:  python3 tools/make_texture_scenes.py"""
import json
import math
import random
import struct
import zlib


def write_png(path, width, height, rgba):
    """rgba: a list of height rows of width (r, g, b, a) tuples, 8-bit."""
    raw = b"".join(b"\x00" + bytes(c for texel in row for c in texel) for row in rgba)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def checker(size=64, cell=8):
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            dark = ((x // cell) + (y // cell)) % 2
            edge = x % cell == 0 or y % cell == 0
            if edge:
                row.append((230, 60 + 3 * x, 40 + 3 * y, 255))
            elif dark:
                row.append((30, 40, 90, 255))
            else:
                row.append((240, 235, 200, 255))
        rows.append(row)
    return rows


def noise(width, height, seed):
    rng = random.Random(seed)
    return [[(rng.randrange(256), rng.randrange(256), rng.randrange(256), rng.randrange(64, 256)) for _ in range(width)]
            for _ in range(height)]


def arrows(size=16):
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            if y == size // 2 and x < size - 2:
                row.append((255, 40, 40, 255))      # the u axis: red, left to right
            elif x == size // 2 and y < size - 2:
                row.append((40, 200, 40, 255))      # the v axis: green, top to bottom
            elif (x + y) % 4 == 0:
                row.append((90, 90, 200, 255))
            else:
                row.append((250, 250, 250, 255))
        rows.append(row)
    return rows


def bumps(size=64, cells=4):
    """A tangent-space normal map of round bumps (a cosine hill per cell): the normal of the height
    h(x, y), encoded as (n + 1) / 2 in RGB; x along +u, y along +v, z out of the surface."""
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            cx = (x + 0.5) / size * cells % 1.0 - 0.5
            cy = (y + 0.5) / size * cells % 1.0 - 0.5
            r = math.hypot(cx, cy)
            # h = cos(pi r / 0.45) bump inside r < 0.45; its gradient in texel units.
            if r < 0.45 and r > 0:
                slope = -math.sin(math.pi * r / 0.45) * math.pi / 0.45 * 0.15 * cells
                gx, gy = slope * cx / r, slope * cy / r
            else:
                gx = gy = 0.0
            n = (-gx, -gy, 1.0)
            length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
            row.append(tuple(int(round((c / length * 0.5 + 0.5) * 255)) for c in n) + (255,))
        rows.append(row)
    return rows


def cube_obj(path):
    """A unit cube with one texture square per face (vt) and face normals (vn)."""
    faces = [((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0)), ((1, 0, 0), (0, 0, -1), (0, 1, 0)),
             ((-1, 0, 0), (0, 0, 1), (0, 1, 0)), ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1))]
    lines = ["# A unit cube, one texture square per face, face normals; written by tools/make_texture_scenes.py"]
    vt = [(0, 0), (1, 0), (1, 1), (0, 1)]
    for u, v in vt:
        lines.append(f"vt {u} {v}")
    corner = 0
    for f, (n, a, b) in enumerate(faces):
        lines.append(f"vn {n[0]} {n[1]} {n[2]}")
        for su, sv in [(-1, -1), (1, -1), (1, 1), (-1, 1)]:
            p = [0.5 * n[i] + 0.5 * su * a[i] + 0.5 * sv * b[i] for i in range(3)]
            lines.append(f"v {p[0]:g} {p[1]:g} {p[2]:g}")
        # counter-clockwise seen from outside (n towards the viewer)
        lines.append("f " + " ".join(f"{corner + k + 1}/{k + 1}/{f + 1}" for k in (0, 1, 2, 3)))
        corner += 4
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def write(path, scene):
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")


def quad(x0, y0, x1, y1, uv0, uv1, name, texture, colour=None):
    """A clip-space quad (two triangles) from (x0, y0) to (x1, y1) with texture coordinates from uv0 to uv1."""
    draw = {"name": name, "shading": "textured",
            "positions": [[x0, y0, 0.5], [x1, y0, 0.5], [x1, y1, 0.5], [x0, y1, 0.5]],
            "texcoords": [[uv0[0], uv0[1]], [uv1[0], uv0[1]], [uv1[0], uv1[1]], [uv0[0], uv1[1]]],
            "indices": [0, 1, 2, 0, 2, 3], "cull": "none", "texture": texture}
    if colour:
        draw["colour"] = colour
    return draw


EXACT = {"colour": 0, "depth": 0}


def plane(name, texture, x0=-20, x1=20):
    """A floor from the camera to far away (z from 0.5 to 60), the texture once per 4 units across and 4 deep."""
    return {"name": name, "shading": "textured",
            "positions": [[x0, 1, 0.5], [x1, 1, 0.5], [x1, 1, 60], [x0, 1, 60]],
            "texcoords": [[x0 / 4, 0], [x1 / 4, 0], [x1 / 4, 15], [x0 / 4, 15]],
            "indices": [0, 1, 2, 0, 2, 3], "cull": "none", "texture": texture}


PLANE_CAMERA = {"type": "look_at", "eye": [0, 0, 0], "target": [0, 0.35, 4], "up": [0, -1, 0], "fov_y": 60,
                "near": 0.1, "far": 100}


def main():
    write_png("textures/checker_64.png", 64, 64, checker())
    write_png("textures/noise_8.png", 8, 8, noise(8, 8, 8))
    write_png("textures/noise_48x40.png", 48, 40, noise(48, 40, 4840))
    write_png("textures/arrows_16.png", 16, 16, arrows())
    write_png("textures/bumps_64.png", 64, 64, bumps())
    cube_obj("meshes/textured_cube.obj")

    noise8 = "textures/noise_8.png"
    write("texture_magnify.json", {
        "description": "An 8x8 noise texture magnified about 20 times on two quads: left nearest filtering (sharp squares), "
                       "right linear filtering (smooth blends between texels, lavapipe's 8-bit fixed-point weights). "
                       "The vertex colour modulates the lower half's alpha-weighted texels. Single level, no mipmaps.",
        "framebuffer": {"width": 320, "height": 200, "clear_colour": [0.1, 0.1, 0.1, 1]},
        "camera": {"type": "clip_space"},
        "draws": [
            quad(-0.95, -0.9, -0.05, 0.9, [0, 0], [1, 1], "nearest", {"file": noise8, "mag_filter": "nearest", "min_filter": "nearest"}),
            quad(0.05, -0.9, 0.95, 0.9, [0, 0], [1, 1], "linear", {"file": noise8}),
        ],
        "tolerance": EXACT})

    arrows16 = "textures/arrows_16.png"
    npot = "textures/noise_48x40.png"
    wrap_draws = []
    cells = [("repeat", "repeat"), ("clamp_to_edge", "clamp_to_edge"), ("repeat", "clamp_to_edge"), ("clamp_to_edge", "repeat")]
    for i, (u, v) in enumerate(cells):
        for j, (file, filt) in enumerate([(arrows16, "nearest"), (arrows16, "linear"), (npot, "nearest"), (npot, "linear")]):
            x0 = -0.98 + i * 0.49
            y0 = -0.98 + j * 0.49
            wrap_draws.append(quad(x0, y0, x0 + 0.47, y0 + 0.47, [-1.25, -0.75], [1.75, 2.25], f"{u}_{v}_{file[9:-4]}_{filt}",
                                   {"file": file, "address_mode_u": u, "address_mode_v": v, "mag_filter": filt,
                                    "min_filter": filt}))
    write("texture_wrap.json", {
        "description": "Wrap modes: columns (left to right) repeat/repeat, clamp_to_edge/clamp_to_edge, repeat u with clamped v, "
                       "clamped u with repeat v; rows (top to bottom) the 16x16 arrow texture nearest and linear, the 48x40 "
                       "(non-power-of-two) noise nearest and linear. Texture coordinates run from -1.25 to 1.75 (u) and "
                       "-0.75 to 2.25 (v), so each quad shows three periods, or the edge texels stretched outwards.",
        "framebuffer": {"width": 320, "height": 320, "clear_colour": [0, 0, 0, 1]},
        "camera": {"type": "clip_space"},
        "draws": wrap_draws,
        "tolerance": EXACT})

    float_draws = []
    cells = [("mirrored_repeat", "mirrored_repeat", "transparent_black"), ("clamp_to_border", "clamp_to_border", "opaque_white"),
             ("mirrored_repeat", "clamp_to_border", "opaque_black"), ("clamp_to_border", "repeat", "transparent_black")]
    for i, (u, v, border) in enumerate(cells):
        for j, (file, filt) in enumerate([(arrows16, "nearest"), (arrows16, "linear"), (npot, "nearest"), (npot, "linear")]):
            x0 = -0.98 + i * 0.49
            y0 = -0.98 + j * 0.49
            float_draws.append(quad(x0, y0, x0 + 0.47, y0 + 0.47, [-1.25, -0.75], [1.75, 2.25], f"{u}_{v}_{file[9:-4]}_{filt}",
                                    {"file": file, "address_mode_u": u, "address_mode_v": v, "mag_filter": filt,
                                     "min_filter": filt, "border_colour": border}))
    write("texture_wrap_float.json", {
        "description": "The wrap modes lavapipe filters in float: columns (left to right) mirrored_repeat both ways, "
                       "clamp_to_border both ways with an opaque white border, mirrored u with a clamped-to-border v "
                       "(opaque black), clamped-to-border u (transparent black, the clear colour shows) with repeat v; "
                       "rows as in texture_wrap.json (arrows nearest and linear, 48x40 noise nearest and linear). "
                       "Mirrored copies flip at every integer; the border colour fills everything outside [0, 1].",
        "framebuffer": {"width": 320, "height": 320, "clear_colour": [0.2, 0.3, 0.4, 1]},
        "camera": {"type": "clip_space"},
        "draws": float_draws,
        "tolerance": EXACT})

    checker64 = "textures/checker_64.png"
    write("texture_srgb.json", {
        "description": "An sRGB texture (R8G8B8A8_SRGB): texels decoded to linear light before filtering (lavapipe's "
                       "cubic approximation), so it looks darker than the same bytes as UNORM. Left: the 8x8 noise "
                       "magnified, nearest and linear; right: the mipmapped checker floor with trilinear filtering, the "
                       "same bytes as UNORM on the far right for comparison.",
        "framebuffer": {"width": 480, "height": 240, "clear_colour": [0.1, 0.1, 0.1, 1]},
        "camera": {"type": "clip_space"},
        "draws": [
            quad(-0.98, -0.9, -0.68, 0.9, [0, 0], [1, 1], "srgb nearest", {"file": noise8, "format": "srgb",
                                                                            "mag_filter": "nearest", "min_filter": "nearest"}),
            quad(-0.66, -0.9, -0.36, 0.9, [0, 0], [1, 1], "srgb linear", {"file": noise8, "format": "srgb"}),
            quad(-0.3, -0.95, 0.32, 0.95, [0, 0], [6, 6], "srgb trilinear minified",
                 {"file": checker64, "format": "srgb", "mipmaps": True, "mipmap_mode": "linear"}),
            quad(0.36, -0.95, 0.98, 0.95, [0, 0], [6, 6], "unorm trilinear minified",
                 {"file": checker64, "mipmaps": True, "mipmap_mode": "linear"}),
        ],
        "tolerance": EXACT})
    for filt in ["nearest", "linear"]:
        for mip in ["nearest", "linear", "none"]:
            texture = {"file": checker64, "mag_filter": filt, "min_filter": filt, "mipmaps": mip != "none"}
            if mip != "none":
                texture["mipmap_mode"] = mip
            what = ("one level only (no mipmaps): far squares alias into moire" if mip == "none" else
                    f"mipmaps chosen {'per quad as the nearest level' if mip == 'nearest' else 'and blended between the two nearest levels'}"
                    f"{' (bands where the level changes)' if mip == 'nearest' else ''}")
            write(f"texture_plane_{filt}_mip_{mip}.json", {
                "description": f"A checkerboard floor receding to the horizon, {filt} filtering, {what}. Minification is "
                               "where filters differ: the level of detail comes from each 2x2 quad's texture-coordinate "
                               "differences, as lavapipe computes it (fast_log2 of rho squared).",
                "framebuffer": {"width": 320, "height": 240, "clear_colour": [0.5, 0.7, 0.9, 1]},
                "camera": PLANE_CAMERA,
                "draws": [plane("floor", texture)],
                "tolerance": EXACT})

    lod_draws = []
    variants = [("bias +1.5", {"mip_lod_bias": 1.5}), ("bias -1", {"mip_lod_bias": -1}), ("min_lod 2", {"min_lod": 2}),
                ("max_lod 1.5", {"max_lod": 1.5}), ("min = max = 1", {"min_lod": 1, "max_lod": 1}),
                ("min nearest, mag linear", {"min_filter": "nearest", "mag_filter": "linear"})]
    for i, (name, fields) in enumerate(variants):
        texture = {"file": checker64, "mipmaps": True, "mipmap_mode": "linear"}
        texture.update(fields)
        x0 = -18 + i * 6
        lod_draws.append(plane(name, texture, x0, x0 + 6))
    write("texture_lod.json", {
        "description": "Six strips of the mipmapped checker floor, left to right: sampler LOD bias +1.5 (blurrier), bias -1 "
                       "(sharper, more aliasing), min_lod 2 (never sharper than level 2), max_lod 1.5 (never blurrier than "
                       "between levels 1 and 2), min_lod = max_lod = 1 (always level 1), nearest minification with linear "
                       "magnification (sharp far away, smooth near the camera where it is magnified).",
        "framebuffer": {"width": 480, "height": 240, "clear_colour": [0.5, 0.7, 0.9, 1]},
        "camera": PLANE_CAMERA,
        "draws": lod_draws,
        "tolerance": EXACT})


    write("texture_msaa.json", {
        "description": "The trilinear checker floor with 4x MSAA: coverage and depth per sample, the texture sampled once "
                       "per pixel at its centre with the level of detail of its 2x2 quad (as single-sample), then the "
                       "resolve; the horizon's edge is smoothed.",
        "framebuffer": {"width": 320, "height": 240, "clear_colour": [0.5, 0.7, 0.9, 1], "samples": 4},
        "camera": PLANE_CAMERA,
        "draws": [plane("floor", {"file": checker64, "mipmaps": True, "mipmap_mode": "linear"})],
        "tolerance": EXACT})

    write("texture_lit_obj.json", {
        "description": "A textured, lit OBJ: a cube with texture coordinates (vt) and normals (vn) per face, the mipmapped "
                       "checker on every face (trilinear), lit per pixel with Blinn-Phong (ambient, diffuse, specular) by the "
                       "scene's light; turned by time (spin), so --set time=T shows other faces at other levels of detail.",
        "framebuffer": {"width": 320, "height": 240, "clear_colour": [0.05, 0.05, 0.08, 1]},
        "camera": {"type": "look_at", "eye": [0, -1.2, -2.6], "target": [0, 0, 0], "up": [0, -1, 0], "fov_y": 45},
        "time": 0.7,
        "light": {"position": [1.5, -2, -2], "colour": [1, 1, 1]},
        "draws": [{"name": "cube", "obj": "meshes/textured_cube.obj", "shading": "blinn_phong_textured",
                   "transform": {"rotate": [20, 0, 0], "spin": [0, 35, 0]},
                   "material": {"ambient": [0.15, 0.15, 0.15], "specular": [0.4, 0.4, 0.4], "shininess": 40},
                   "texture": {"file": checker64, "mipmaps": True, "mipmap_mode": "linear"}}],
        "tolerance": EXACT})

    write("texture_normal_map.json", {
        "description": "A normal-mapped quad: the checker as its colour and a generated bump map (textures/bumps_64.png, 4x4 "
                       "round hills) as its tangent-space normals, tangents computed from the texture coordinates. Lit "
                       "per pixel with Blinn-Phong from the upper left, so each flat quad shows 16 shaded domes, lit on the "
                       "side facing the light with a highlight; the tests move the light (--set light.position).",
        "framebuffer": {"width": 320, "height": 240, "clear_colour": [0.05, 0.05, 0.08, 1]},
        "camera": {"type": "look_at", "eye": [0, 0, -2.2], "target": [0, 0, 0], "up": [0, -1, 0], "fov_y": 50},
        "light": {"position": [-1.2, -1.2, -1.2], "colour": [1, 1, 1]},
        "draws": [{"name": "bumpy quad", "shading": "blinn_phong_normal_mapped",
                   "positions": [[-1, -0.8, 0], [1, -0.8, 0], [1, 0.8, 0], [-1, 0.8, 0]],
                   "normals": [[0, 0, -1], [0, 0, -1], [0, 0, -1], [0, 0, -1]],
                   "texcoords": [[0, 0], [1.25, 0], [1.25, 1], [0, 1]],
                   "indices": [0, 2, 1, 0, 3, 2], "cull": "none",
                   "material": {"ambient": [0.1, 0.1, 0.1], "specular": [0.5, 0.5, 0.5], "shininess": 30},
                   "texture": {"file": checker64, "mipmaps": True, "mipmap_mode": "linear"},
                   "normal_map": {"file": "textures/bumps_64.png", "mipmaps": True, "mipmap_mode": "linear"}}],
        "tolerance": EXACT})


if __name__ == "__main__":
    main()
