#!/usr/bin/env python3
"""Compares two PNG renderings of the same page, for the two backends' agreement test.

usage: png_compare.py PAGE.png STACK.png [--max-mean M] [--max-bad F]

Both images are read with a small PNG decoder (8-bit gray, RGB or RGBA, non-interlaced: what
pdftoppm and rsvg-convert write); PAGE is compared with the top of STACK (a document's pages
stacked in one SVG), which must be as wide and at least as high. Both are turned to gray and blurred with
a 3x3 box (so that a glyph's anti-aliasing, which differs between renderers, is not a
difference), then compared pixel by pixel. Prints the mean absolute difference (0..255) and the
share of pixels that differ by more than 64; exits 1 when either exceeds its limit.
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
        elif kind == b"IEND":
            break
    width, height, depth, colour, _, _, interlace = header
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace:
        raise SystemExit(f"{path}: unsupported PNG (depth {depth}, colour type {colour}, interlace {interlace})")
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    gray = []
    for line in rows:
        if channels <= 2:
            gray.append([line[x * channels] for x in range(width)])
        else:
            gray.append([(line[x * channels] * 299 + line[x * channels + 1] * 587 + line[x * channels + 2] * 114) // 1000
                         for x in range(width)])
    return gray


def blur(img, w, h):
    """3x3 box blur (edges averaged over what exists), done as two 3-tap passes."""
    def tap3(line, n):
        out = [0] * n
        for x in range(n):
            lo, hi = max(0, x - 1), min(n, x + 2)
            out[x] = sum(line[lo:hi]) / (hi - lo)
        return out
    rows = [tap3(row[:w], w) for row in img[:h]]
    cols = [tap3([rows[y][x] for y in range(h)], h) for x in range(w)]
    return [[cols[x][y] for x in range(w)] for y in range(h)]


def main():
    args = sys.argv[1:]
    max_mean, max_bad = 4.0, 0.02
    if "--max-mean" in args:
        i = args.index("--max-mean"); max_mean = float(args[i + 1]); del args[i:i + 2]
    if "--max-bad" in args:
        i = args.index("--max-bad"); max_bad = float(args[i + 1]); del args[i:i + 2]
    a, b = read_png(args[0]), read_png(args[1])
    h, w = min(len(a), len(b)), min(len(a[0]), len(b[0]))
    if len(b) < len(a) - 2 or abs(len(a[0]) - len(b[0])) > 2:
        print(f"sizes differ: {len(a[0])}x{len(a)} and {len(b[0])}x{len(b)}")
        return 1
    a, b = blur(a, w, h), blur(b, w, h)
    total, bad = 0, 0
    for y in range(h):
        for x in range(w):
            d = abs(a[y][x] - b[y][x])
            total += d
            bad += d > 64
    mean, share = total / (w * h), bad / (w * h)
    print(f"mean difference {mean:.2f}/255, {100 * share:.2f} % of pixels differ by more than 64")
    return 0 if mean <= max_mean and share <= max_bad else 1


sys.exit(main())
