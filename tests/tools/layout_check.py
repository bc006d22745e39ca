#!/usr/bin/env python3
"""layout.json against the PDF it describes (tests/cli/layout_json.sh).

    layout_check.py SET_DIR [--dpi 144]

SET_DIR holds what `epure generate --format pdf` wrote: sheets.pdf, key.json, layout.json. Each
page of sheets.pdf is rendered grey (pdftoppm) and compared with layout.json's page, sheet after
sheet in the PDF's order:
  - the page's size;
  - each corner mark a solid dark square where layout.json puts it, paper around it;
  - the code's rectangle: its three finder patterns' dark corners, paper just outside it;
  - every comb cell and tick box: its four printed sides dark, its inside paper;
and for every sheet, every question id of key.json has a field on the sheet's pages (a point's
coordinates, `1.P.x`, as key.json spells them), and no field names a question the key does not
have but `student_number` and the fields a kind asks whatever its branch (counted). Prints a summary; exit status 1 with what differs.
"""
import json
import os
import subprocess
import sys
import tempfile


def read_pgm(path):
    with open(path, "rb") as f:
        data = f.read()
    # P5 <w> <h> <max>\n<bytes>
    parts, i = [], 0
    while len(parts) < 4:
        while data[i:i + 1].isspace():
            i += 1
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        parts.append(data[i:j])
        i = j
    i += 1
    assert parts[0] == b"P5", path
    w, h = int(parts[1]), int(parts[2])
    return w, h, data[i:i + w * h]


class Page:
    def __init__(self, path, dpi):
        self.w, self.h, self.px = read_pgm(path)
        self.s = dpi / 72

    def at(self, x, y):
        """grey level at (x, y) in points"""
        X = min(max(int(x * self.s), 0), self.w - 1)  # pixel k covers [k, k + 1) / s
        Y = min(max(int(y * self.s), 0), self.h - 1)
        return self.px[Y * self.w + X]

    def darkest_near(self, x, y):
        """the darkest pixel within a pixel: a thin line drawn anti-aliased"""
        r = 1 / self.s
        return min(self.at(x + dx * r, y + dy * r) for dx in (-1, 0, 1) for dy in (-1, 0, 1))


def check_box(page, cell, where, problems):
    x, y, w, h = cell
    sides = []
    for k in range(1, 8):
        t = k / 8
        sides += [(x + t * w, y), (x + t * w, y + h), (x, y + t * h), (x + w, y + t * h)]
    light = [p for p in sides if page.darkest_near(*p) > 160]
    if len(light) > 2:
        problems.append(f"{where}: {len(light)} of {len(sides)} points of its sides are not inked, first at {light[0]}")
    inside = [page.at(x + a * w, y + b * h) for a in (0.3, 0.5, 0.7) for b in (0.3, 0.5, 0.7)]
    if min(inside) < 200:
        problems.append(f"{where}: ink inside the box ({min(inside)})")


def main():
    args = sys.argv[1:]
    dpi = 144
    if "--dpi" in args:
        i = args.index("--dpi")
        dpi = int(args[i + 1])
        del args[i:i + 2]
    d = args[0]
    layout = json.load(open(os.path.join(d, "layout.json")))
    key = json.load(open(os.path.join(d, "key.json")))
    problems = []
    sheets = layout["sheets"]
    if [s["sheet"] for s in sheets] != [s["id"] for s in key["sheets"]]:
        problems.append("layout.json's sheets are not key.json's, in its order")
    # every question of the key has its field, and nothing else is asked
    fields = 0
    extras = [0]
    for sheet, ks in zip(sheets, key["sheets"]):
        names = [f["question"] for p in sheet["pages"] for f in p["fields"]]
        fields += len(names)
        if len(set(names)) != len(names):
            problems.append(f"sheet {sheet['sheet']}: a question with two fields")
        ids = {q["id"] for e in ks["exercises"] for q in e["questions"]}
        missing = ids - set(names)
        extra = set(names) - ids - {"student_number"}
        if missing:
            problems.append(f"sheet {sheet['sheet']}: no field for {sorted(missing)}")
        # A kind whose fields are the same whatever the branch (sheet_fields) asks some the
        # branch leaves out of the key (the point of intersection of segments that do not
        # meet): they are marked as not asked. They are counted, not refused.
        extras[0] += len(extra)
        if "student_number" not in names and "student" not in sheet:
            problems.append(f"sheet {sheet['sheet']}: no student number field and no student")
    # every page against the PDF
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run(["pdftoppm", "-gray", "-r", str(dpi), os.path.join(d, "sheets.pdf"), os.path.join(tmp, "p")], check=True)
        files = sorted(f for f in os.listdir(tmp) if f.endswith(".pgm"))
        expected = sum(len(s["pages"]) for s in sheets)
        if len(files) != expected:
            problems.append(f"sheets.pdf has {len(files)} pages, layout.json {expected}")
        k = 0
        boxes = 0
        for sheet in sheets:
            for p in sheet["pages"]:
                if k >= len(files):
                    break
                page = Page(os.path.join(tmp, files[k]), dpi)
                k += 1
                where = f"sheet {sheet['sheet']} page {p['page']}"
                if abs(page.w / page.s - p["width"]) > 1 or abs(page.h / page.s - p["height"]) > 1:
                    problems.append(f"{where}: the PDF's page is {page.w / page.s:.1f} x {page.h / page.s:.1f} pt, layout.json's {p['width']} x {p['height']}")
                half = p["mark_size"] / 2
                for i, (mx, my) in enumerate(p["marks"]):
                    inner = [page.at(mx + a * half * 0.8, my + b * half * 0.8) for a in (-1, 0, 1) for b in (-1, 0, 1)]
                    outer = [page.at(mx + a * half * 1.6, my + b * half * 1.6) for a in (-1, 1) for b in (-1, 1)]
                    if max(inner) > 80 or min(outer) < 200:
                        problems.append(f"{where}: mark {i + 1} is not a solid square at ({mx}, {my})")
                x, y, w, h = p["code"]
                m = w / 25  # a version-2 code: 25 modules
                corners = [(x + m / 2, y + m / 2), (x + w - m / 2, y + m / 2), (x + m / 2, y + h - m / 2), (x + 3.5 * m, y + 3.5 * m)]
                ring = [(x + 1.5 * m, y + 1.5 * m), (x + w - 1.5 * m, y + 1.5 * m)]
                outside = [(x - 2 * m, y + h / 2), (x + w + 2 * m, y + h / 2), (x + w / 2, y - 2 * m), (x + w / 2, y + h + 2 * m)]
                if any(page.at(*c) > 100 for c in corners) or any(page.at(*c) < 180 for c in ring + outside):
                    problems.append(f"{where}: no QR code's finder patterns at {p['code']}")
                for f in p["fields"]:
                    for i, c in enumerate(f["cells"]):
                        boxes += 1
                        check_box(page, c, f"{where} field {f['question']} cell {i + 1}", problems)
    for p in problems[:30]:
        print(p, file=sys.stderr)
    if problems:
        print(f"{len(problems)} problems", file=sys.stderr)
        return 1
    print(f"{len(sheets)} sheets, {expected} pages, {fields} fields ({extras[0]} not in the key), {boxes} cells and boxes: as layout.json says")
    return 0


if __name__ == "__main__":
    sys.exit(main())
