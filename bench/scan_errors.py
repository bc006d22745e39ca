#!/usr/bin/env python3
"""Where a scan's errors and reviews come from, on stacks made by bench/scan_accuracy.sh (each
directory: truth.json, layout.json, out/fields.csv, figures.json):

    scan_errors.py STACK_DIR... [--threshold 0.82]

Per stack and in total: fields, silent errors, fields sent to review (ticks, combs), digit cells
read right; then, over all stacks, comb cells by what was written (digit, minus, empty) with how
many were misread and how many fell under the review threshold; the digit confusions; why comb
fields went to review (a digit cell under the threshold, an empty or a minus cell, the assembly);
and the threshold's curve (comb fields to review / silent errors) recomputed from the cells'
confidences. A cell's confidence is after scan's second look (field_reading.h) at the cells read
under 0.90 and, in a sign cell, its share of the minus's and the empty cell's probability: the
curve's points under 0.90 are what scan gives with that threshold; its points from 0.90 would
need the second look at more cells.
"""
import collections
import csv
import json
import os
import sys

# a value as grade compares it: the suite's own reading of it
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "tools"))
from scan_figures import norm  # noqa: E402


def expected_cells(f, v):
    n = len(f["cells"]); dec = f.get("decimals", 0); sign = 1 if f.get("sign") else 0
    ints = n - sign - dec
    w = v.replace("−", "-"); neg = w.startswith("-"); w = w.lstrip("-")
    ip, _, dp = w.replace(".", ",").partition(",")
    return ([("-" if neg else " ")] if sign else []) + [" "] * (ints - len(ip)) + list(ip) + list(dp) + [" "] * (dec - len(dp))


THRESHOLDS = (0.5, 0.6, 0.7, 0.75, 0.78, 0.8, 0.81, 0.82, 0.83, 0.84, 0.85, 0.88, 0.9, 0.95, 0.98)


def main():
    args = sys.argv[1:]
    thr = 0.82  # field_reading.h kCellConfidence
    if "--threshold" in args:
        k = args.index("--threshold"); thr = float(args[k + 1]); del args[k:k + 2]
    total = collections.Counter()
    cells = collections.Counter()          # (kind, outcome)
    confusions = collections.Counter()     # (written, read) for digit cells read wrong
    low_right = collections.Counter()      # written digit, cell under threshold but right
    review_why = collections.Counter()
    combs_all = []                         # (min cell confidence, has problem, right) per comb field
    print(f"{'stack':<28} {'fields':>6} {'silent':>6} {'review':>6} {'ticks':>6} {'combs':>6} {'digits right':>16}")
    for d in args:
        fig = json.load(open(os.path.join(d, "figures.json")))
        name = os.path.basename(d.rstrip("/"))
        for k in ("fields", "silent", "review", "tick_review", "comb_review", "digit_cells", "digit_cells_right", "comb_fields", "tick_fields"):
            total[k] += fig[k]
        print(f"{name:<28} {fig['fields']:>6} {fig['silent']:>6} {fig['review']:>6} {fig['tick_review']:>6} {fig['comb_review']:>6} "
              f"{fig['digit_cells_right']:>6}/{fig['digit_cells']:<5} {100 * fig['digit_cells_right'] / max(1, fig['digit_cells']):.2f} %")
        truth = json.load(open(os.path.join(d, "truth.json")))["sheets"]
        layout = json.load(open(os.path.join(d, "layout.json")))
        combs = {(sh["sheet"], f["question"]): f for sh in layout["sheets"] for p in sh["pages"] for f in p["fields"] if f["type"] == "comb"}
        for row in csv.DictReader(open(os.path.join(d, "out", "fields.csv"), newline="")):
            f = combs.get((row["sheet"], row["question"]))
            t = truth.get(row["sheet"])
            if not f or not t or not row["cell_confidence"]:
                continue
            v = t["student_number"] if row["question"] == "student_number" else t["answers"].get(row["question"])
            if v is None:
                continue
            exp = expected_cells(f, v)
            read = [(c.rsplit(":", 1)[0], float(c.rsplit(":", 1)[1])) for c in row["cell_confidence"].split()]
            why = row["why"]
            problem = any(not part.strip().startswith("cell ") for part in why.split(";") if part.strip())
            lows = []
            for e, (r, conf) in zip(exp, read):
                r = " " if r == "_" else r
                kind = "digit" if e.isdigit() else ("minus" if e == "-" else "empty")
                ok = r == e
                cells[(kind, "cells")] += 1
                cells[(kind, "wrong")] += not ok
                cells[(kind, "low")] += conf < thr
                cells[(kind, "low and right")] += conf < thr and ok
                cells[(kind, "high and wrong")] += conf >= thr and not ok
                if kind == "digit" and not ok:
                    confusions[(e, r)] += 1
                if kind == "digit" and ok and conf < thr:
                    low_right[e] += 1
                if conf < thr:
                    lows.append(kind)
            right = norm(row["value"]) == norm(v)
            combs_all.append((min(c for _, c in read), problem, right))
            if row["status"] == "review":
                if problem and not lows:
                    review_why["the assembly only (" + why + ")"] += 1
                elif lows:
                    review_why["a cell under the threshold: " + "+".join(sorted(set(lows)))] += 1
                else:
                    review_why["other: " + why] += 1
    n = max(1, total["fields"])
    print(f"{'total':<28} {total['fields']:>6} {total['silent']:>6} {total['review']:>6} {total['tick_review']:>6} {total['comb_review']:>6} "
          f"{total['digit_cells_right']:>6}/{total['digit_cells']:<5} {100 * total['digit_cells_right'] / max(1, total['digit_cells']):.2f} %")
    print(f"silent {100 * total['silent'] / n:.2f} %, review {100 * total['review'] / n:.2f} % "
          f"(ticks {100 * total['tick_review'] / n:.2f} %, combs {100 * total['comb_review'] / n:.2f} % of all fields, "
          f"{100 * total['comb_review'] / max(1, total['comb_fields']):.2f} % of comb fields)")
    print(f"\ncomb cells (threshold {thr}):")
    for kind in ("digit", "minus", "empty"):
        c = {k[1]: v for k, v in cells.items() if k[0] == kind}
        print(f"  {kind:<6} {c.get('cells', 0):>6} cells, {c.get('wrong', 0):>4} misread, {c.get('low', 0):>5} under the threshold "
              f"({c.get('low and right', 0)} of them right), {c.get('high and wrong', 0)} misread over it")
    print("digit confusions (written -> read: count):", ", ".join(f"{e}->{'empty' if r == ' ' else r}: {k}" for (e, r), k in confusions.most_common()))
    print("digit cells right but under the threshold, by digit:", dict(sorted(low_right.items())))
    print("comb fields to review, why:")
    for w, k in review_why.most_common(8):
        print(f"  {k:>5} {w}")
    curve = []
    for t in THRESHOLDS:
        rev = sum(1 for m, p, r in combs_all if m < t or p)
        sil = sum(1 for m, p, r in combs_all if not (m < t or p) and not r)
        curve.append(f"{t}: {rev}/{sil}")
    print("threshold curve, comb fields to review / silent:", "; ".join(curve))


if __name__ == "__main__":
    sys.exit(main())
