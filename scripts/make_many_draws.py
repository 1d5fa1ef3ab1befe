#!/usr/bin/env python3
"""Writes a scene of N small draws (default 10 000) with one and the same pipeline state: a
benchmark input for the per-draw cost of the renderers, not a conformance scene (so it is written
outside scenes/, which the cross-check tests read in full).
Each draw is one indexed triangle of about 2x2 pixels on a 100x100 grid over a 256x256 frame.
Usage:  python3 scripts/make_many_draws.py [N] [OUT.json]   (default 10000 /tmp/many_draws.json)
Then:   /usr/bin/time -v build/bin/crosscheck render OUT.json --renderer vulkan -o /tmp/many.png"""
import json
import sys

count = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
out = sys.argv[2] if len(sys.argv) > 2 else "/tmp/many_draws.json"
size = 256
draws = []
for i in range(count):
    # Clip-space position of the draw's cell on a 100x100 grid.
    gx, gy = i % 100, (i // 100) % 100
    x, y = -1 + (gx + 0.5) * 2 / 100, -1 + (gy + 0.5) * 2 / 100
    d = 2.0 / size  # one pixel in clip space
    draws.append({
        "positions": [[round(x - d, 6), round(y - d, 6), 0.5], [round(x + d, 6), round(y - d, 6), 0.5],
                      [round(x, 6), round(y + d, 6), 0.5]],
        "colour": [(gx % 10) / 9, (gy % 10) / 9, 1],
        "indices": [0, 1, 2],
        "cull": "none",
    })
scene = {
    "description": f"Benchmark input: {count} identical small indexed draws (per-draw cost).",
    "framebuffer": {"width": size, "height": size},
    "camera": {"type": "clip_space"},
    "draws": draws,
}
with open(out, "w") as f:
    json.dump(scene, f, separators=(",", ":"))
print(f"wrote {out}: {count} draws")
