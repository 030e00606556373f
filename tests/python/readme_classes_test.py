#!/usr/bin/python3
"""README.md's class table ("Classes and instances") says what configs/ontology.json says: per id the
class name (before any note in parentheses), colour, RUGD and RELLIS-3D names and SemanticKITTI class and id.

Usage: readme_classes_test.py REPO_ROOT
"""
import json
import os
import re
import sys

root = sys.argv[1]
classes = json.load(open(os.path.join(root, "configs", "ontology.json")))["classes"]
rows = {}
for line in open(os.path.join(root, "README.md")):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) == 6 and cells[0].isdigit():
        rows[int(cells[0])] = cells
problems = []
for c in classes:
    row = rows.get(c["id"])
    if row is None:
        problems.append(f"class {c['id']} ({c['name']}) has no row")
        continue
    want = [str(c["id"]), c["name"], ",".join(str(v) for v in c["color"]), c["rugd"], c["rellis"],
            f"{c['semantic_kitti']} ({c['semantic_kitti_id']})"]
    got = [row[0], re.sub(r"\s*\(.*\)$", "", row[1]), row[2].replace(" ", ""), row[3], row[4], row[5]]
    for column, w, g in zip(["id", "class", "colour", "RUGD", "RELLIS-3D", "SemanticKITTI"], want, got):
        if w != g:
            problems.append(f"class {c['id']}: README {column} '{g}', ontology.json '{w}'")
if len(rows) != len(classes):
    problems.append(f"README has {len(rows)} class rows, ontology.json {len(classes)} classes")
if problems:
    sys.exit("README.md's class table differs from configs/ontology.json:\n  " + "\n  ".join(problems))
print(f"readme classes: {len(classes)} rows agree with configs/ontology.json")
