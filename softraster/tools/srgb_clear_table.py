#!/usr/bin/env python3
"""Prints the 104 words of detail/fragment/srgb.hpp's kSrgbClearBuckets: the piecewise-linear
fit of linear -> sRGB that lavapipe's clears use (Mesa's util_format_linear_float_to_srgb_8unorm,
after Fabian Giesen's float -> sRGB8 method; facts from its description, our own code).

Linear values in [2^-13, 1) are split into 13 binades x 8 buckets (by the float's exponent and
its top 3 mantissa bits). In each bucket the sRGB value times 255, plus 0.5, is fitted by least
squares as a + b * t, where t is the next 8 mantissa bits, sampled at every 32nd float of the
bucket. A word holds round(a * 128) in its high half and round(b * 65536) in its low half.
Run: python3 softraster/tools/srgb_clear_table.py"""
import math
import struct

BINADES, BUCKETS_PER_BINADE = 13, 8
FLOATS_PER_BUCKET = 1 << (23 - 3)  # floats in one bucket
STEP = 32                          # every 32nd of them is a sample
SAMPLES = FLOATS_PER_BUCKET // STEP


def encode(linear):
    """The sRGB transfer function (exponent 1/2.4 as Mesa writes it, 0.41666666)."""
    return 12.92 * linear if linear < 0.0031308 else 1.055 * math.pow(linear, 0.41666666) - 0.055


def fraction_bits(sample):
    """t: bits 12..19 of the float, the 8 mantissa bits below the bucket's 3."""
    return (sample * STEP) >> 12


def main():
    n = float(SAMPLES)
    sum_t = sum(fraction_bits(i) for i in range(SAMPLES))
    sum_tt = sum(fraction_bits(i) ** 2 for i in range(SAMPLES))
    inverse_determinant = 1.0 / (n * sum_tt - sum_t * sum_t)
    words = []
    for bucket in range(BINADES * BUCKETS_PER_BINADE):
        first = ((127 - BINADES) << 23) + bucket * FLOATS_PER_BUCKET
        sum_v = sum_tv = 0.0
        for i in range(SAMPLES):
            value = struct.unpack("<f", struct.pack("<I", first + i * STEP))[0]
            v = encode(value) * 255.0 + 0.5
            sum_v += v
            sum_tv += fraction_bits(i) * v
        a = inverse_determinant * (sum_tt * sum_v - sum_t * sum_tv)
        b = inverse_determinant * (n * sum_tv - sum_t * sum_v)
        words.append((int(a * 65536.0 / 512.0 + 0.5) << 16) + int(b * 65536.0 + 0.5))
    for row in range(0, len(words), 6):
        print("    " + " ".join("0x%08x," % w for w in words[row:row + 6]))


if __name__ == "__main__":
    main()
