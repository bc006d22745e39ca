#!/usr/bin/env python3
"""Page economy of a generated set: pages per sheet and per key, and how full each page is.
Usage: python3 bench/page_economy.py OUT_DIR [LABEL]
OUT_DIR is what `epure generate --format svg,pdf` wrote (sheets/*.svg give each sheet's page
count, sheets.pdf and keys.pdf the pages' ink).

A page's fill is the share of its text area (under the header, above the bottom margin) down to
its lowest ink, read from a grey rendering at 24 dpi (pdftoppm): what a teacher sees as the blank
end of a page. A page "less than half full" counts only when it is not its sheet's last.
Prints one line per file, e.g.
  sheets  pages/sheet mean 3.93 max 4  fill mean 0.86 min 0.52  half-empty non-last pages 0
"""
import glob, os, re, subprocess, sys, tempfile

DPI = 24
# The layout's defaults (src/render/layout.h): top margin + header + gap, bottom margin, points.
CONTENT_TOP = 42.5 + 28 + 14
BOTTOM_MARGIN = 42.5
# A grey level darker than this is ink (the paper is 255; the lightest drawn grey, a figure's
# grid, is about 0xdd).
INK = 0xf0


def read_pgm(path):
    data = open(path, "rb").read()
    # P5 width height maxval, then the raster
    m = re.match(rb"P5\s+(\d+)\s+(\d+)\s+(\d+)\s", data)
    w, h = int(m.group(1)), int(m.group(2))
    return w, h, data[m.end():]


def fills(pdf):
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run(["pdftoppm", "-gray", "-r", str(DPI), pdf, f"{tmp}/p"], check=True)
        out = []
        for f in sorted(glob.glob(f"{tmp}/p-*.pgm"), key=lambda p: int(re.findall(r"-(\d+)\.pgm$", p)[0])):
            w, h, raster = read_pgm(f)
            page_h = h * 72 / DPI
            top = int(CONTENT_TOP * DPI / 72) + 1
            bottom = int((page_h - BOTTOM_MARGIN) * DPI / 72)
            last = top
            for y in range(bottom, top, -1):
                if min(raster[y * w:(y + 1) * w]) < INK:
                    last = y
                    break
            out.append(max(0.0, (last - top) / (bottom - top)))
        return out


def main(out_dir, label=""):
    for name in ("sheets", "keys"):
        pdf = os.path.join(out_dir, f"{name}.pdf")
        counts = [len(re.findall(r'class="page"', open(p).read()))
                  for p in sorted(glob.glob(os.path.join(out_dir, name, "*.svg")))]
        f = fills(pdf)
        if sum(counts) != len(f):
            sys.exit(f"{pdf}: {len(f)} pages, the SVGs {sum(counts)}")
        half_empty, i = 0, 0
        for n in counts:
            half_empty += sum(1 for k in range(n - 1) if f[i + k] < 0.5)
            i += n
        non_last = [f[j] for j, _ in enumerate(f)]
        print(f"{label}{name:6}  pages/sheet mean {sum(counts) / len(counts):.2f} max {max(counts)}"
              f"  fill mean {sum(f) / len(f):.2f} min {min(f):.2f}"
              f"  half-empty non-last pages {half_empty} of {len(f)}")


if __name__ == "__main__":
    main(*sys.argv[1:])
