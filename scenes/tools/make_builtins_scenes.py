#!/usr/bin/env python3
"""Writes the fragment built-in scenes (scenes/builtins_*.json): the builtins_discard model
(discard by a pattern of gl_FragCoord, colour by gl_FrontFacing and gl_FragCoord) over triangles
of both windings and slanted depths, with the depth test and stencil on, single-sample and 4x
MSAA, over two depth/stencil formats; and the builtins_frag_depth model (gl_FragDepth) over the
depth formats, with depth bias (which gl_FragDepth replaces) and depth clamp; both again with
sample shading (4x MSAA, shaded per sample); builtins_sample (gl_SampleID, gl_SamplePosition)
single-sample and 4x MSAA; builtins_sample_mask (gl_SampleMask, gl_SampleMaskIn) single-sample, 4x MSAA
and with sample shading; builtins_discard on unfilled polygons (polygon modes line and point);
and varyings_64
(64 varying components, smooth, flat and noperspective) on triangles that clipping cuts.

Run from the repository root: python3 scenes/tools/make_builtins_scenes.py
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from scene_layout import CAMERA, FRAMEBUFFER, at, draw, scene  # noqa: E402

OUT = os.path.join(os.path.dirname(__file__), "..")


def tri(p0, p1, p2):
    """Three (px, py, camera depth) corners, unprojected."""
    return [at(*p0), at(*p1), at(*p2)]


def quad(x0, y0, x1, y1, z0, z1):
    """Two triangles (counter-clockwise on screen) covering [x0, x1] x [y0, y1], depth z0 at the
    left edge to z1 at the right."""
    return [at(x0, y0, z0), at(x0, y1, z0), at(x1, y0, z1), at(x1, y0, z1), at(x0, y1, z0), at(x1, y1, z1)]


def draws():
    stencil_writes = {"compare_op": "always", "pass_op": "increment_and_clamp", "depth_fail_op": "invert",
                      "back": {"pass_op": "replace", "reference": 128, "depth_fail_op": "zero"}}
    stencil_read_only = {"compare_op": "not_equal", "reference": 3, "write_mask": 0}
    return [
        draw("background", quad(-4, -4, 260, 196, 3.5, 5.0), colour=[0.3, 0.3, 0.35], cull="none",
             stencil={"compare_op": "always", "pass_op": "replace", "reference": 2}),
        # Late depth and stencil (the stencil is written): discarded fragments leave both alone.
        draw("front, ccw, stencil written", tri((12, 10, 2.0), (20, 150, 4.5), (120, 30, 3.0)),
             shading="builtins_discard", cull="none", stencil=stencil_writes),
        draw("back, cw, stencil written", tri((130, 12, 2.5), (245, 40, 4.8), (150, 160, 2.2)),
             shading="builtins_discard", cull="none", stencil=stencil_writes, colour=[0.9, 0.6, 0.1]),
        # The stencil only read: lavapipe tests depth early and defers the depth write to the kill.
        draw("front and back, depth written, stencil read", quad(40, 60, 210, 120, 2.4, 4.2)[:3] +
             [at(210, 120, 4.2), at(40, 120, 2.4), at(210, 60, 4.2)],
             shading="builtins_discard", cull="none", stencil=stencil_read_only, colour=[0.2, 0.8, 0.9]),
        # Clockwise front faces: gl_FrontFacing follows front_face.
        draw("front_face clockwise", tri((60, 140, 2.1), (200, 150, 3.9), (100, 188, 2.9)),
             shading="builtins_discard", cull="none", front_face="clockwise", colour=[0.7, 0.2, 0.7],
             stencil=stencil_writes),
        # Drawn last, between the layers: it shows through the holes the discards left in depth.
        draw("behind, through the holes", quad(0, 0, 256, 192, 3.2, 3.2), colour=[0.9, 0.9, 0.2], cull="none",
             depth_compare="less"),
    ]


def frag_depth_draws():
    return [
        draw("background", quad(-4, -4, 260, 196, 3.5, 5.0), colour=[0.3, 0.3, 0.35], cull="none"),
        draw("frag depth, ccw", tri((8, 8, 2.0), (30, 180, 4.8), (200, 20, 3.4)), shading="builtins_frag_depth",
             cull="none", colour=[0.9, 0.3, 0.2]),
        # gl_FragDepth replaces the depth, bias included (the bias applies to the rasterized depth only).
        draw("frag depth, cw, depth bias", tri((250, 10, 2.2), (120, 100, 4.0), (240, 185, 3.0)),
             shading="builtins_frag_depth", cull="none", colour=[0.2, 0.8, 0.3],
             depth_bias={"constant": 400, "slope": 4, "clamp": 0}),
        # Depth clamp: gl_FragDepth clamped to the viewport's [0.2, 0.95], not only to [0, 1].
        draw("frag depth, depth clamp", tri((60, 120, 2.0), (150, 190, 5.0), (180, 60, 3.0)),
             shading="builtins_frag_depth", cull="none", colour=[0.3, 0.4, 0.9], depth_clamp=True,
             viewport={"x": 0, "y": 0, "width": 256, "height": 192, "min_depth": 0.2, "max_depth": 0.95}),
        # Over everything, depth test only: it shows where the depth buffer lies beyond camera depth 3.
        draw("depth probe", quad(0, 0, 256, 192, 3.0, 3.0), colour=[0.9, 0.9, 0.2], cull="none",
             depth_compare="less_or_equal", depth_write=False),
    ]


def varyings_draws():
    colours = [[0.9, 0.1, 0.3, 1.0], [0.1, 0.8, 0.4, 0.2], [0.3, 0.2, 0.95, 0.6]]
    return [
        draw("64 varyings, slanted", tri((10, 10, 2.0), (40, 180, 6.0), (150, 30, 3.0)), colours, shading="varyings_64",
             cull="none"),
        draw("64 varyings, cw", tri((250, 5, 4.0), (140, 120, 2.5), (245, 185, 8.0)), colours, shading="varyings_64",
             cull="none"),
        # One corner behind the near plane (camera depth 0.5) and one beyond the frame: clipping
        # makes new vertices, each with all 64 components.
        draw("64 varyings, clipped", tri((60, 200, 0.3), (-80, 60, 3.0), (200, 90, 5.0)), colours,
             shading="varyings_64", cull="none"),
    ]


def polygon_mode_draws():
    """Unfilled polygons of both facings drawn by builtins_discard (which reads gl_FrontFacing) and
    one by vertex_color (which does not): front state writes one value, back state another."""
    def faces(front, back):
        return {"front": {"compare_op": "always", "pass_op": "replace", "reference": front},
                "back": {"compare_op": "always", "pass_op": "replace", "reference": back}}
    return [
        draw("background", quad(-4, -4, 260, 196, 3.5, 5.0), colour=[0.3, 0.3, 0.35], cull="none",
             stencil={"compare_op": "always", "pass_op": "replace", "reference": 2}),
        draw("builtins, line mode, front (ccw)", tri((10, 10, 2.0), (20, 90, 3.0), (110, 20, 2.5)),
             shading="builtins_discard", cull="none", polygon_mode="line", stencil=faces(128, 55)),
        draw("builtins, line mode, back (cw)", tri((130, 10, 2.0), (240, 20, 2.5), (140, 90, 3.0)),
             shading="builtins_discard", cull="none", polygon_mode="line", colour=[0.9, 0.6, 0.1],
             stencil=faces(128, 55)),
        draw("builtins, point mode, back (cw)", tri((12, 110, 2.0), (110, 115, 2.5), (30, 180, 3.0)),
             shading="builtins_discard", cull="none", polygon_mode="point", point_size=4, colour=[0.2, 0.8, 0.9],
             stencil=faces(128, 55)),
        draw("builtins, point mode, front (cw with front_face clockwise)",
             tri((60, 120, 2.0), (100, 150, 2.5), (70, 185, 3.0)), shading="builtins_discard", cull="none",
             polygon_mode="point", point_size=4, front_face="clockwise", colour=[0.7, 0.2, 0.7],
             stencil=faces(3, 56)),
        # No gl_FrontFacing in the shader: lavapipe's lines are front-facing, the back state unused.
        draw("vertex colour, line mode, back (cw)", tri((130, 110, 2.0), (240, 120, 2.5), (140, 185, 3.0)),
             colour=[0.9, 0.9, 0.2], cull="none", polygon_mode="line", stencil=faces(66, 77)),
    ]


def sample_mask_draws():
    """builtins_sample_mask (gl_SampleMask, gl_SampleMaskIn) under late tests (stencil written),
    early depth (stencil only read), the sample mask state, alpha to coverage and on lines."""
    counting = {"compare_op": "always", "pass_op": "increment_and_clamp"}
    return [
        draw("background", quad(-4, -4, 260, 196, 3.5, 5.0), colour=[0.3, 0.3, 0.35], cull="none",
             stencil={"compare_op": "always", "pass_op": "replace", "reference": 2}),
        draw("mask, stencil written", tri((8, 8, 2.0), (20, 150, 4.0), (150, 20, 3.0)), shading="builtins_sample_mask",
             cull="none", stencil=counting, colour=[0.2, 0.6, 0.9, 1.0]),
        draw("mask, back-facing, depth written, stencil read", tri((250, 10, 2.2), (245, 180, 3.0), (140, 100, 4.0)),
             shading="builtins_sample_mask", cull="none", colour=[0.9, 0.6, 0.1, 1.0],
             stencil={"compare_op": "not_equal", "reference": 3, "write_mask": 0}),
        draw("mask with the sample mask state 0xb", tri((40, 120, 2.0), (60, 188, 2.5), (130, 150, 2.2)),
             shading="builtins_sample_mask", cull="none", stencil=counting, colour=[0.4, 0.9, 0.4, 1.0],
             multisample={"sample_mask": 11}),
        draw("mask and alpha to coverage (alpha 0.6)", tri((150, 110, 2.0), (170, 188, 2.6), (250, 130, 2.3)),
             shading="builtins_sample_mask", cull="none", colour=[0.9, 0.2, 0.7, 0.6],
             multisample={"alpha_to_coverage": True}),
        draw("Bresenham lines", [at(160, 60, 2.1), at(250, 70, 2.1), at(170, 90, 2.1), at(240, 100, 2.1)],
             shading="builtins_sample_mask", topology="line_list", line_rasterization="bresenham", line_width=3.0,
             colour=[0.9, 0.9, 0.9, 1.0]),
        draw("rectangular line strip", [at(100, 170, 2.1), at(140, 185, 2.1), at(200, 168, 2.1)],
             shading="builtins_sample_mask", topology="line_strip", line_width=2.5, colour=[0.6, 0.9, 0.9, 1.0]),
        # Drawn last, behind the builtins draws: it shows where their dropped samples left the depth.
        draw("behind, through the dropped samples", quad(0, 0, 256, 192, 3.2, 3.2), colour=[0.9, 0.9, 0.2],
             cull="none", depth_compare="less"),
    ]


def sample_draws():
    counting = {"compare_op": "always", "pass_op": "increment_and_clamp"}
    return [
        draw("background", quad(-4, -4, 260, 196, 3.5, 5.0), colour=[0.3, 0.3, 0.35], cull="none"),
        draw("per sample, ccw", tri((10, 12, 2.0), (30, 180, 4.5), (150, 40, 3.0)), [[0.9, 0.2, 0.2, 0.3],
             [0.2, 0.9, 0.2, 0.6], [0.2, 0.2, 0.9, 0.9]], shading="builtins_sample", cull="none", stencil=counting),
        draw("per sample, cw", tri((250, 20, 2.5), (140, 120, 3.8), (245, 185, 2.2)), shading="builtins_sample",
             cull="none", stencil=counting, colour=[0.9, 0.6, 0.1, 0.8]),
        draw("vertex colour over them", tri((100, 60, 2.2), (120, 170, 2.3), (200, 90, 2.4)), colour=[0.2, 0.8, 0.9],
             cull="none", depth_compare="less"),
    ]


def main():
    base = ("The fragment built-ins: builtins_discard discards pixels by a pattern of gl_FragCoord.xy and "
            "colours front faces by gl_FragCoord (x/128, y/128, z, 2w) and back faces by the vertex colour and "
            "1 - z, on triangles of both windings (front_face counter-clockwise and clockwise) and slanted depths "
            "seen through a pinhole camera (so w varies). The stencil is written (lavapipe: late depth and "
            "stencil tests) or only read (early depth test, the write deferred to the kill); a discarded "
            "fragment writes no colour, depth or stencil, which the last draw shows through the holes.")
    fb = dict(FRAMEBUFFER, depth_format="d24_unorm_s8_uint")
    scene(os.path.join(OUT, "builtins_discard.json"), base + " D24_UNORM_S8_UINT, single sample.", draws(), fb, CAMERA)
    scene(os.path.join(OUT, "builtins_discard_msaa.json"),
          base + " D24_UNORM_S8_UINT, 4x MSAA: the fragment is shaded once at the pixel centre (gl_FragCoord.xy = "
          "px + 0.5, z and w at the centre) and a discard drops every sample of it.",
          draws(), dict(fb, samples=4), CAMERA)
    scene(os.path.join(OUT, "builtins_discard_d32.json"), base + " D32_SFLOAT_S8_UINT, single sample.", draws(),
          dict(FRAMEBUFFER, depth_format="d32_sfloat_s8_uint"), CAMERA)

    fd = ("gl_FragDepth (builtins_frag_depth: (gl_FragCoord.z - 0.8) * 8, plus 0.25 on the left half of every "
          "16-pixel period): the depth test and write take the shader's value, clamped to [0, 1] and, with depth "
          "clamp, to the viewport's range; a depth bias does not apply to it; values below 0 and above 1 occur. "
          "A last draw (depth test only) shows the depth buffer in colour.")
    for fmt, label in (("d16_unorm", "D16_UNORM"), ("x8_d24_unorm", "X8_D24_UNORM_PACK32"),
                       ("d32_sfloat", "D32_SFLOAT")):
        scene(os.path.join(OUT, "builtins_frag_depth_%s.json" % fmt.split("_")[1 if fmt.startswith("x8") else 0]),
              fd + " " + label + ", single sample.", frag_depth_draws(), dict(FRAMEBUFFER, depth_format=fmt), CAMERA)
    scene(os.path.join(OUT, "builtins_frag_depth_msaa.json"),
          fd + " D24_UNORM_S8_UINT, 4x MSAA: every covered sample takes the fragment's one gl_FragDepth.",
          frag_depth_draws(), dict(FRAMEBUFFER, depth_format="d24_unorm_s8_uint", samples=4), CAMERA)

    ss = (" D24_UNORM_S8_UINT, 4x MSAA with sample shading (minSampleShading 1 on every draw but two: 0.26 "
          "on the back-facing triangle, which lavapipe also shades per sample as ceil(4 * 0.26) > 1, and 0.25 on "
          "the clockwise one, shaded once at the pixel centre as ceil(4 * 0.25) = 1): the shader runs once per "
          "covered sample with gl_FragCoord.xy at the sample (px + 0.375, py + 0.125 for sample 0, ...) and .z "
          "there, .w and the varyings at the pixel centre; a discard drops only its own sample, so the holes' "
          "edges fall between samples, and each sample of a kept pixel has its own colour.")
    shaded = draws()
    fractions = {"back, cw, stencil written": 0.26, "front_face clockwise": 0.25}
    for d in shaded:
        d["multisample"] = {"min_sample_shading": fractions.get(d["name"], 1.0)}
    scene(os.path.join(OUT, "builtins_discard_sample_shading.json"), base + ss, shaded, dict(fb, samples=4), CAMERA)
    depth_shaded = frag_depth_draws()
    for d in depth_shaded:
        d["multisample"] = {"min_sample_shading": 1.0}
    scene(os.path.join(OUT, "builtins_frag_depth_sample_shading.json"),
          fd + " D24_UNORM_S8_UINT, 4x MSAA with sample shading (minSampleShading 1): each sample's invocation "
          "writes its own gl_FragDepth from gl_FragCoord.z at the sample; the vertex-colour draws give the same "
          "bits as without sample shading.",
          depth_shaded, dict(FRAMEBUFFER, depth_format="d24_unorm_s8_uint", samples=4), CAMERA)

    pm = ("Unfilled polygons (polygon modes line and point) drawn by builtins_discard, which reads "
          "gl_FrontFacing: lavapipe's unfilled stage then gives their lines and points the polygon's facing, for "
          "gl_FrontFacing (back faces coloured by the vertex colour) and for the stencil face (front state writes "
          "128 or 3, back state 55 or 56); the last triangle, drawn by vertex_color, which does not read it, keeps "
          "lavapipe's front state (66, never its back state's 77) whatever its winding.")
    scene(os.path.join(OUT, "builtins_polygon_modes.json"), pm + " D24_UNORM_S8_UINT, single sample.",
          polygon_mode_draws(), fb, CAMERA)
    scene(os.path.join(OUT, "builtins_polygon_modes_msaa.json"), pm + " D24_UNORM_S8_UINT, 4x MSAA.",
          polygon_mode_draws(), dict(fb, samples=4), CAMERA)

    sm = ("gl_SampleMask and gl_SampleMaskIn (builtins_sample_mask: gl_SampleMask = (column + 3 * row) & 15 of "
          "gl_FragCoord's integer parts, red = gl_SampleMaskIn / 16): a sample the mask drops is neither tested nor "
          "written, stencil and depth included, under late tests (stencil written) and early depth (stencil read), "
          "with the sample mask state 0xb, with alpha to coverage, and on Bresenham and rectangular lines; a last "
          "draw shows the depth the dropped samples left.")
    scene(os.path.join(OUT, "builtins_sample_mask.json"),
          sm + " D24_UNORM_S8_UINT, single sample: gl_SampleMaskIn is 1 and bit 0 of gl_SampleMask keeps or drops "
          "the fragment.", sample_mask_draws(), fb, CAMERA)
    scene(os.path.join(OUT, "builtins_sample_mask_msaa.json"),
          sm + " D24_UNORM_S8_UINT, 4x MSAA, shaded once per pixel: gl_SampleMaskIn holds the covered samples (after "
          "the sample mask state) and gl_SampleMask drops samples; the Bresenham lines are drawn with multisampling "
          "off (gl_SampleMaskIn 1, bit 0 decides).", sample_mask_draws(), dict(fb, samples=4), CAMERA)
    shaded_masks = sample_mask_draws()
    for d in shaded_masks:
        # Refused with sample shading (pipeline.hpp), and invalid on Bresenham lines (VUID-...-02766).
        if d["name"] not in ("mask and alpha to coverage (alpha 0.6)", "Bresenham lines"):
            d.setdefault("multisample", {})["min_sample_shading"] = 1.0
    scene(os.path.join(OUT, "builtins_sample_mask_sample_shading.json"),
          sm + " D24_UNORM_S8_UINT, 4x MSAA with sample shading (minSampleShading 1, but on the alpha-to-coverage "
          "draw and the Bresenham lines): each sample's invocation sees only its own bit in gl_SampleMaskIn and keeps its sample by its own "
          "bit of gl_SampleMask.", shaded_masks, dict(fb, samples=4), CAMERA)

    sd = ("The per-sample built-ins (builtins_sample: colour = (gl_SamplePosition.x, gl_SamplePosition.y, "
          "gl_SampleID / 4, vertex alpha); sample 3 discarded where gl_FragCoord.y < 96). Reading gl_SampleID "
          "makes the shader run once per covered sample, without any sample shading state: on triangles of both "
          "windings over a background, with depth and a stencil that counts what each sample kept, and one "
          "vertex-colour triangle drawn over them.")
    scene(os.path.join(OUT, "builtins_sample.json"),
          sd + " D24_UNORM_S8_UINT, single sample: gl_SampleID 0 and gl_SamplePosition (0.5, 0.5).",
          sample_draws(), dict(FRAMEBUFFER, depth_format="d24_unorm_s8_uint"), CAMERA)
    scene(os.path.join(OUT, "builtins_sample_msaa.json"),
          sd + " D24_UNORM_S8_UINT, 4x MSAA: each sample's colour is its own position and index.",
          sample_draws(), dict(FRAMEBUFFER, depth_format="d24_unorm_s8_uint", samples=4), CAMERA)

    vd = ("64 varying components (varyings_64: 16 vec4 outputs, smooth, flat and noperspective in turn, the vertex "
          "colour rotated by index, summed with weights (i + 1) / 256 in a fixed order in both languages): Vulkan's "
          "minimum maxVertexOutputComponents, on slanted triangles of both windings and one clipped by the near "
          "plane and the frame.")
    scene(os.path.join(OUT, "varyings_64.json"), vd + " Single sample.", varyings_draws(), None, CAMERA)
    scene(os.path.join(OUT, "varyings_64_msaa.json"), vd + " 4x MSAA.", varyings_draws(),
          dict(FRAMEBUFFER, samples=4), CAMERA)


if __name__ == "__main__":
    main()
