#!/usr/bin/env python3
"""The link annotations of a PDF, read through `qpdf --json=2`, one per line, in page order:
    <page from 1> <uri> <llx> <lly> <urx> <ury> <inside>
where <inside> says whether the rectangle lies within the page's MediaBox ("in" or "out").
Usage: pdf_links.py FILE.pdf"""
import json
import subprocess
import sys


def main(path):
    doc = json.loads(subprocess.run(["qpdf", "--json=2", "--json-key=pages", "--json-key=qpdf", path],
                                    check=True, capture_output=True, text=True).stdout)
    objects = doc["qpdf"][1]

    def get(ref):  # an indirect reference's value; a direct value as it is
        return objects[f"obj:{ref}"]["value"] if isinstance(ref, str) and ref.endswith(" R") else ref

    def text(s):  # qpdf's JSON strings: "u:" text, "b:" hex bytes
        return s[2:] if s.startswith("u:") else bytes.fromhex(s[2:]).decode("latin-1")

    for page in doc["pages"]:
        value = get(page["object"])
        box = get(value.get("/MediaBox", [0, 0, 0, 0]))
        for ref in get(value.get("/Annots", [])):
            annot = get(ref)
            if annot.get("/Subtype") != "/Link":
                continue
            action = get(annot.get("/A", {}))
            uri = text(action["/URI"]) if action.get("/S") == "/URI" else "-"
            rect = [float(x) for x in get(annot["/Rect"])]
            inside = box[0] <= rect[0] < rect[2] <= box[2] and box[1] <= rect[1] < rect[3] <= box[3]
            print(page["pageposfrom1"], uri, *(f"{x:g}" for x in rect), "in" if inside else "out")


if __name__ == "__main__":
    main(sys.argv[1])
