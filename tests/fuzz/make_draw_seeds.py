#!/usr/bin/env python3
# Writes the draw fuzzer's seed corpus (corpus/draw/) in the byte layout draw_fuzzer.cpp reads:
# a few ordinary draws (a triangle, an indexed MSAA quad with blending, wide and Bresenham lines,
# points, polygon mode line with a perspective matrix, a viewport and scissor) for libFuzzer to
# start from. Run from anywhere; rewrites the files.
# Deliberately no random inputs: mutation is libFuzzer's job.
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def num(v):
    # ByteReader::number(): kind < 160, then an int16 in 1/64 steps.
    return bytes([0]) + struct.pack('<h', int(round(v * 64)))


def flag(b):
    return bytes([1 if b else 0])


def draw(width=32, height=32, samples=1, fmt=2, clear=(0, 0, 0, 1), clear_depth_quarters=4, topology=3,
         viewport=None, scissor=None, polygon=0, cull=0, front=0, clamp=False, bias=None, line_width=1,
         bresenham=False, depth=(True, True, 1), blend=None, matrix='identity', point_size=1, indexed=False,
         vertices=(), indices=()):
    out = bytes([width - 1, height - 1]) + flag(samples == 4) + bytes([fmt])
    out += b''.join(num(c) for c in clear) + flag(False) + bytes([clear_depth_quarters])
    out += bytes([topology])
    out += flag(viewport is not None) + (b''.join(num(v) for v in viewport) if viewport else b'')
    out += flag(scissor is not None)
    if scissor:
        out += flag(False) + bytes(v & 0xFF for v in scissor)
    out += bytes([polygon, cull, front]) + flag(clamp)
    out += flag(bias is not None) + b''.join(num(v) for v in (bias or (0, 0, 0)))
    out += flag(False) + bytes([line_width - 1]) + flag(bresenham)
    out += flag(depth[0]) + flag(depth[1]) + bytes([depth[2]])
    b = blend or (False, 1, 0, 0, 1, 0, 0, 15, (0, 0, 0, 0))
    out += flag(b[0]) + bytes(b[1:8]) + b''.join(num(c) for c in b[8])
    if matrix == 'identity':
        out += flag(False) + flag(False)
    else:
        out += flag(False) + flag(True)
    out += flag(False) + bytes([point_size - 1])
    out += flag(indexed) + bytes([len(vertices)])
    for position, colour in vertices:
        out += b''.join(num(v) for v in position) + b''.join(num(c) for c in colour)
    out += bytes([len(indices)]) + bytes(indices)
    return out


red, green, blue, white = (1, 0, 0, 1), (0, 1, 0, 1), (0, 0, 1, 1), (1, 1, 1, 0.5)
tri = [((-0.9, -0.9, 0.5), red), ((0.9, -0.8, 0.25), green), ((0.0, 0.9, 0.75), blue)]
quad = [((-0.8, -0.8, 0.5), red), ((0.8, -0.8, 0.5), green), ((-0.8, 0.8, 0.5), blue), ((0.8, 0.8, 0.5), white)]
seeds = {
    'triangle': draw(vertices=tri),
    'msaa_quad_blend_d16': draw(samples=4, fmt=0, topology=4, indexed=True, vertices=quad, indices=[0, 1, 2, 3],
                                blend=(True, 6, 7, 0, 1, 7, 0, 15, (0.25, 0.5, 0.75, 1))),
    'wide_lines': draw(topology=2, line_width=3, vertices=quad),
    'bresenham_lines_d24': draw(fmt=1, topology=1, bresenham=True, vertices=quad),
    'points': draw(topology=0, point_size=4, vertices=quad + tri),
    'polygon_line_perspective': draw(polygon=1, cull=2, matrix='perspective',
                                     vertices=[((x, y, 1 + 0.5 * i), c) for i, ((x, y, _), c) in enumerate(quad)],
                                     topology=5),
    'viewport_scissor_bias': draw(viewport=(4, 2, 20, 24, 0.25, 0.75), scissor=(3, 5, 16, 12), bias=(1, 2, 0.5),
                                  depth=(True, False, 3), vertices=tri),
}
os.makedirs(os.path.join(HERE, 'corpus', 'draw'), exist_ok=True)
for name, data in seeds.items():
    with open(os.path.join(HERE, 'corpus', 'draw', name), 'wb') as f:
        f.write(data)
