#!/usr/bin/env python3
"""Rebuilds tests/grading/data/key_small.json: four sheets of the built-in course at seed 5
(sheets 2, 3, 4 and 8), each cut to its first five exercises. Run it after a change that alters
key.json on purpose (question order, tolerances, points), then review the diff:

    python3 tests/tools/make_key_small.py build/epure tests/grading/data/key_small.json
"""
import json
import subprocess
import sys
import tempfile

epure, out = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as tmp:
    subprocess.run([epure, "generate", "--quiet", "--format", "svg", "--sheets", "9", "--seed", "5", "--out", tmp],
                   check=True)
    key = json.load(open(f"{tmp}/key.json", encoding="utf-8"))
keep = [s for s in key["sheets"] if s["index"] in (2, 3, 4, 8)]
for s in keep:
    s["exercises"] = s["exercises"][:5]
key["sheets"] = keep
with open(out, "w", encoding="utf-8") as f:
    json.dump(key, f, ensure_ascii=False, separators=(",", ":"))
    f.write("\n")
