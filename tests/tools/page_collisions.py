#!/usr/bin/env python3
"""Counts pairs of words whose boxes overlap on the pages of PDF files (pdftotext -bbox).
Usage: python3 page_collisions.py [--quiet] FILE.pdf...

Two words collide when their boxes overlap by more than 1 pt both across and down: text printed
over text (a figure's label over a sentence, a label over a grid number). Prints one line per
file with collisions (its first examples, by page) and, last, the total. Exit 1 when any pair
collides. Adapted from ../shared/tools/page_collisions.py so that a fresh clone tests itself.
"""
import re, subprocess, sys
from xml.etree import ElementTree as ET

NS = {"h": "http://www.w3.org/1999/xhtml"}
# Overlap, in points, both across and down, beyond which two words are printed over each other:
# pdftotext's boxes are the fonts' full ascent to descent, so neighbouring lines of one paragraph
# touch, and a subscript's box reaches into its base letter's by a fraction of a point.
TOLERANCE = 1.0


def words_by_page(pdf):
    html = subprocess.run(["pdftotext", "-bbox", pdf, "-"], capture_output=True, text=True, check=True).stdout
    root = ET.fromstring(re.sub(r"<!DOCTYPE[^>]*>", "", html))
    for page in root.findall(".//h:page", NS):
        yield [(float(w.get("xMin")), float(w.get("yMin")), float(w.get("xMax")), float(w.get("yMax")), w.text or "")
               for w in page.findall("h:word", NS)]


def collisions(words):
    words = sorted(words)
    out = []
    for i, a in enumerate(words):
        for b in words[i + 1:]:
            if b[0] >= a[2] - TOLERANCE:
                break
            ox = min(a[2], b[2]) - max(a[0], b[0])
            oy = min(a[3], b[3]) - max(a[1], b[1])
            if ox > TOLERANCE and oy > TOLERANCE:
                out.append((a, b))
    return out


def main(args):
    quiet = "--quiet" in args
    paths = [a for a in args if a != "--quiet"]
    total = pages = bad_pages = 0
    for path in paths:
        n = 0; examples = []
        for pi, words in enumerate(words_by_page(path), 1):
            pages += 1
            c = collisions(words)
            if c:
                bad_pages += 1; n += len(c)
                if len(examples) < 3:
                    examples.append(f"p.{pi}: " + ", ".join(
                        f"'{a[4]}'/'{b[4]}' at ({a[0]:.0f},{a[1]:.0f})" for a, b in c[:3]))
        total += n
        if n and not quiet:
            print(f"{path}: {n} colliding word pairs; " + "; ".join(examples))
    print(f"collisions: {total} overlapping word pairs on {bad_pages} of {pages} pages (want 0)")
    return 0 if total == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
