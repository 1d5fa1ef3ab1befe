#!/usr/bin/env python3
"""Probe lavapipe's UNORM8 blending against competing models of its arithmetic.
For each blend state it renders scenes/blend_products.json three times through crosscheck's Vulkan
side (vulkan.png): the destination alone (draw 1 writes nothing), the source alone (draw 1 with
blending off) and the blend; then it predicts every byte of the blend from the first two under
each model and counts the channels a model gets wrong (of 256 x 256 x 4).
Models: blinn = two products (t + (t >> 8) + 128) >> 8, saturating op (softraster's); float = the
blend in float, rounded once; plus1 = (x * (f + 1)) >> 8; trunc = x * f // 255; minmax_weighted =
blinn with MIN/MAX applied to the weighted terms; lerp = lp_build_blend's lp_build_lerp shortcut
for complementary factors with ADD (blinn otherwise).
Run from the repository root after a build:  python3 scripts/probe_blend.py [all]
("all" probes every source x destination factor pair with op ADD; slow)."""
import json, os, struct, subprocess, sys, tempfile, zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CC = os.path.join(ROOT, "build", "bin", "crosscheck")
SCENE = os.path.join(ROOT, "scenes", "blend_products.json")
OUT = tempfile.mkdtemp(prefix="probe_blend_")

def png(path):
    data = open(path, "rb").read()
    pos, idat, w, h = 8, b"", 0, 0
    while pos < len(data):
        n, = struct.unpack(">I", data[pos:pos+4]); t = data[pos+4:pos+8]; body = data[pos+8:pos+8+n]
        if t == b"IHDR": w, h = struct.unpack(">II", body[:8])
        if t == b"IDAT": idat += body
        pos += 12 + n
    raw = zlib.decompress(idat); bpp, stride = 4, w * 4
    out, prev = [], bytearray(stride); i = 0
    for y in range(h):
        f = raw[i]; line = bytearray(raw[i+1:i+1+stride]); i += 1 + stride
        for x in range(stride):
            a = line[x-bpp] if x >= bpp else 0; b = prev[x]; c = prev[x-bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p-a), abs(p-b), abs(p-c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out.append(bytes(line)); prev = line
    return b"".join(out)

def render(tag, sets):
    d = os.path.join(OUT, tag)
    args = [CC, "compare", SCENE, "--out", d] + sum([["--set", s] for s in sets], [])
    subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return png(d + "/vulkan.png")

def mul_blinn(x, f): t = x * f; return (t + (t >> 8) + 128) >> 8
def mul_plus1(x, f): return (x * (f + 1)) >> 8
def mul_trunc(x, f): return x * f // 255

FACT = ["zero", "one", "src_color", "one_minus_src_color", "dst_color", "one_minus_dst_color", "src_alpha",
        "one_minus_src_alpha", "dst_alpha", "one_minus_dst_alpha", "constant_color", "one_minus_constant_color",
        "constant_alpha", "one_minus_constant_alpha", "src_alpha_saturate"]

def factor(name, c, s, d, k):
    inv = name.startswith("one_minus_"); base = name[10:] if inv else name
    v = {"zero": 0, "one": 255, "src_color": s[c], "dst_color": d[c], "src_alpha": s[3], "dst_alpha": d[3],
         "constant_color": k[c], "constant_alpha": k[3],
         "src_alpha_saturate": 255 if c == 3 else min(s[3], 255 - d[3])}[base]
    return 255 - v if inv else v

def model(kind, op, sf, df, c, s, d, k):
    if kind == "lerp":  # lp_build_blend's shortcut for complementary factors: lp_build_lerp (AVX2)
        if op != "add" or df != "one_minus_" + sf:
            return model("blinn", op, sf, df, c, s, d, k)
        x = factor(sf, c, s, d, k); x += x >> 7
        return (d[c] + ((x * (s[c] - d[c]) * 128 + 16384) >> 15)) & 255
    if kind == "float":  # float blend, one rounding at the end
        S = s[c] / 255 * factor(sf, c, s, d, k) / 255; D = d[c] / 255 * factor(df, c, s, d, k) / 255
        r = {"add": S + D, "subtract": S - D, "reverse_subtract": D - S, "min": min(s[c], d[c]) / 255,
             "max": max(s[c], d[c]) / 255}[op]
        return int(round(min(max(r, 0), 1) * 255))
    mul = {"blinn": mul_blinn, "plus1": mul_plus1, "trunc": mul_trunc, "minmax_weighted": mul_blinn}[kind]
    S = mul(s[c], factor(sf, c, s, d, k)); D = mul(d[c], factor(df, c, s, d, k))
    if op in ("min", "max") and kind != "minmax_weighted": S, D = s[c], d[c]
    return {"add": min(S + D, 255), "subtract": max(S - D, 0), "reverse_subtract": max(D - S, 0),
            "min": min(S, D), "max": max(S, D)}[op]

KINDS = ["blinn", "float", "plus1", "trunc", "minmax_weighted", "lerp"]
dst = render("dst", ['draws.1.blend.write_mask=""'])
src = render("src", ["draws.1.blend.enable=false"])
constants = [0.3, 0.55, 0.8, 0.45]
k = [76, 140, 204, 115]  # the constants as bytes: round half to even of 76.5, 140.25, 204, 114.75
cases = [(x, y, "add") for x in FACT for y in FACT] if "all" in sys.argv else [
    ("src_alpha", "one_minus_src_alpha", "add"), ("constant_color", "one_minus_constant_color", "add"),
    ("dst_color", "zero", "add"), ("src_color", "one_minus_dst_alpha", "add"),
    ("src_alpha_saturate", "one", "add"), ("constant_color", "one_minus_constant_alpha", "add"),
    ("one_minus_src_color", "dst_alpha", "subtract"), ("src_alpha", "dst_color", "reverse_subtract"),
    ("src_alpha", "one_minus_src_alpha", "min"), ("dst_color", "src_alpha", "max"),
    ("constant_alpha", "one_minus_constant_color", "reverse_subtract")]
for sf, df, op in cases:
    blend = json.dumps({"source": sf, "destination": df, "op": op, "constants": constants})
    out = render("out", [f"draws.1.blend={blend}"])
    miss = {kind: 0 for kind in KINDS}
    for p in range(0, len(out), 4):
        s, d, o = src[p:p+4], dst[p:p+4], out[p:p+4]
        for c in range(4):
            for kind in KINDS:
                if model(kind, op, sf, df, c, s, d, k) != o[c]: miss[kind] += 1
    print(f"{sf:>26} {df:>26} {op:>16}: mismatching channels of 262144: " +
          " ".join(f"{kind}={n}" for kind, n in miss.items()), flush=True)
