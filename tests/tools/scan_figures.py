#!/usr/bin/env python3
"""What `epure scan` read against what the suite wrote (tests/scan/scan_fixture_main.cpp's
truth.json): per field, right, sent to review, or a silent error (a wrong value not sent to
review); per tick field and per comb cell the same. Prints the figures as JSON; with --check,
fails (exit 1) when a figure passes its bound:

    scan_figures.py TRUTH.json OUT_DIR [LAYOUT.json] [--check] [--max-silent 0.001] [--max-review 0.05]
                    [--min-tick 0.999] [--min-digits 0.99]

With LAYOUT.json, also the digits cell by cell: every cell where a digit was written, read as
that digit (the classifier's best class, whatever its confidence) or not.
"""
import csv
import json
import sys


def norm(v):
    """A value as grade compares it: numbers as numbers (0,90 = 0.9), words as they are."""
    v = v.replace("−", "-").strip()
    try:
        return float(v.replace(",", "."))
    except ValueError:
        return v


def main():
    args = sys.argv[1:]
    check = "--check" in args
    bounds = {"--max-silent": 0.001, "--max-review": 0.05, "--min-tick": 0.999, "--max-tick-review": 1.0,
              "--min-digits": 0.0}
    for k in list(bounds):
        if k in args:
            bounds[k] = float(args[args.index(k) + 1])
    truth = json.load(open(args[0]))
    out = args[1]
    fields = {}
    with open(f"{out}/fields.csv", newline="") as f:
        for row in csv.DictReader(f):
            fields[(row["sheet"], row["question"])] = row
    counts = {"fields": 0, "right": 0, "review": 0, "silent": 0, "missing": 0,
              "tick_fields": 0, "tick_right": 0, "tick_silent": 0, "tick_review": 0,
              "comb_fields": 0, "comb_right": 0, "comb_silent": 0, "comb_review": 0}
    silent = []
    for sheet, t in truth["sheets"].items():
        expected = dict(t["answers"])
        expected["student_number"] = t["student_number"]
        for q, v in expected.items():
            row = fields.get((sheet, q))
            if row is None:
                counts["missing"] += 1  # its page was not scanned (dropped)
                continue
            kind = "comb" if row["cells"] and not row["cells"].startswith(("empty(", "ticked(", "cancelled(", "uncertain(")) else "tick"
            counts["fields"] += 1
            counts[f"{kind}_fields"] += 1
            if row["status"] == "review":
                counts["review"] += 1
                counts[f"{kind}_review"] += 1
            elif norm(row["value"]) == norm(v):
                counts["right"] += 1
                counts[f"{kind}_right"] += 1
            else:
                counts["silent"] += 1
                counts[f"{kind}_silent"] += 1
                silent.append({"sheet": sheet, "question": q, "written": v, "read": row["value"], "cells": row["cells"]})
    # Digits, cell by cell: each comb cell where a digit was written, read as that digit or not
    # (the cells' characters as the classifier read them, whatever their confidence).
    layout = json.load(open(args[2])) if len(args) > 2 and args[2].endswith(".json") else None
    digit_cells = digit_right = 0
    if layout:
        combs = {}
        for sh in layout["sheets"]:
            for p in sh["pages"]:
                for f in p["fields"]:
                    if f["type"] == "comb":
                        combs[(sh["sheet"], f["question"])] = f
        for (sheet, q), row in fields.items():
            f = combs.get((sheet, q))
            t = truth["sheets"].get(sheet)
            if not f or not t or not row["cell_confidence"]:
                continue
            v = t["student_number"] if q == "student_number" else t["answers"].get(q)
            if v is None:
                continue
            n_cells = len(f["cells"]); dec = f.get("decimals", 0); sign = 1 if f.get("sign") else 0
            ints = n_cells - sign - dec
            w = v.replace("−", "-"); neg = w.startswith("-"); w = w.lstrip("-")
            ip, _, dp = w.replace(".", ",").partition(",")
            expected = ([("-" if neg else " ")] if sign else []) + [" "] * (ints - len(ip)) + list(ip) + list(dp) + [" "] * (dec - len(dp))
            read = [c.split(":")[0] for c in row["cell_confidence"].split()]
            for e, r in zip(expected, read):
                if e.isdigit():
                    digit_cells += 1
                    digit_right += r == e
    counts["digit_cells"] = digit_cells
    counts["digit_cells_right"] = digit_right
    n = max(1, counts["fields"])
    figures = dict(counts)
    figures["silent_rate"] = counts["silent"] / n
    figures["review_rate"] = counts["review"] / n
    figures["tick_right_or_review_rate"] = (counts["tick_right"] + counts["tick_review"]) / max(1, counts["tick_fields"])
    figures["digit_accuracy"] = digit_right / digit_cells if digit_cells else None
    figures["silent_errors"] = silent[:20]
    print(json.dumps(figures, indent=1))
    if check:
        bad = []
        if figures["silent_rate"] > bounds["--max-silent"]:
            bad.append(f"silent errors {figures['silent_rate']:.4f} > {bounds['--max-silent']}")
        if figures["review_rate"] > bounds["--max-review"]:
            bad.append(f"fields sent to review {figures['review_rate']:.4f} > {bounds['--max-review']}")
        if figures["tick_right_or_review_rate"] < bounds["--min-tick"]:
            bad.append(f"ticks right or sent to review {figures['tick_right_or_review_rate']:.4f} < {bounds['--min-tick']}")
        tick_review = counts["tick_review"] / max(1, counts["tick_fields"])
        if tick_review > bounds["--max-tick-review"]:
            bad.append(f"tick fields sent to review {tick_review:.4f} > {bounds['--max-tick-review']}")
        if figures["digit_accuracy"] is not None and figures["digit_accuracy"] < bounds["--min-digits"]:
            bad.append(f"digits read right {figures['digit_accuracy']:.4f} < {bounds['--min-digits']}")
        if bad:
            print("scan_figures: " + "; ".join(bad), file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
