#!/usr/bin/python3
"""Leaf and needle lengths of the tree species in metres, measured on the exported assets.

Usage: scripts/leaf_sizes.py ASSET_DIR [--json]

ASSET_DIR is the output of `silva assets build --glb --out ASSET_DIR`. For every tree variant's
.glb, each alpha-masked (foliage) material records in its extras the drawn leaf length in texture
units (`leaf_length_uv`); each of its cards' size in metres per texture unit is measured on the
mesh (3D length over texture length of a card's first edge). Their product is the leaf length of
that card in metres; the table gives per species the median, 10th and 90th percentile over all
cards of all variants, beside the botanical range of the species.
"""
import glob
import json
import os
import struct
import sys

import numpy as np

# Leaf or needle length, metres: the usual range of each species' mature foliage.
BOTANICAL = {"spruce": (0.010, 0.025), "pine": (0.03, 0.07), "larch": (0.02, 0.04),
             "beech": (0.05, 0.10), "birch": (0.03, 0.07), "oak": (0.07, 0.14)}


def load_glb(path):
    """The JSON chunk and the binary chunk of a .glb file."""
    data = open(path, "rb").read()
    json_len = struct.unpack("<I", data[12:16])[0]
    doc = json.loads(data[20:20 + json_len])
    return doc, data[20 + json_len + 8:]


def accessor(doc, blob, index):
    """An accessor's values as an (count, components) array."""
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    comps = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[a["type"]]
    dtype = {5126: np.float32, 5125: np.uint32, 5123: np.uint16}[a["componentType"]]
    offset = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    return np.frombuffer(blob, dtype, a["count"] * comps, offset).reshape(a["count"], comps)


def card_leaf_lengths(path):
    """Leaf length in metres of every foliage card of one .glb (its full-detail mesh)."""
    doc, blob = load_glb(path)
    out = []
    for prim in doc["meshes"][0]["primitives"]:
        material = doc["materials"][prim.get("material", 0)]
        leaf_uv = material.get("extras", {}).get("leaf_length_uv", 0.0)
        if material.get("alphaMode") != "MASK" or leaf_uv <= 0.0:
            continue
        pos = accessor(doc, blob, prim["attributes"]["POSITION"])
        uv = accessor(doc, blob, prim["attributes"]["TEXCOORD_0"])
        tris = accessor(doc, blob, prim["indices"]).reshape(-1, 3)
        first = tris[::2]  # a card is two triangles
        metres = np.linalg.norm(pos[first[:, 1]] - pos[first[:, 0]], axis=1)
        texture = np.linalg.norm(uv[first[:, 1]] - uv[first[:, 0]], axis=1)
        keep = texture > 1e-6
        out.extend((metres[keep] / texture[keep] * leaf_uv).tolist())
    return out


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(args) != 1:
        sys.exit(__doc__)
    rows = {}
    for species in BOTANICAL:
        lengths = []
        for path in sorted(glob.glob(os.path.join(args[0], species + "_*.glb"))):
            lengths.extend(card_leaf_lengths(path))
        if not lengths:
            continue
        lo, hi = BOTANICAL[species]
        med = float(np.median(lengths))
        rows[species] = {"cards": len(lengths), "median_m": med, "p10_m": float(np.percentile(lengths, 10)),
                         "p90_m": float(np.percentile(lengths, 90)), "botanical_m": [lo, hi],
                         "within": lo <= med <= hi}
    if "--json" in sys.argv:
        print(json.dumps(rows, indent=1))
        return
    print("| species | cards | median leaf/needle (m) | p10 – p90 (m) | botanical (m) | median within |")
    print("|---|---|---|---|---|---|")
    for s, r in rows.items():
        print(f"| {s} | {r['cards']} | {r['median_m']:.3f} | {r['p10_m']:.3f} – {r['p90_m']:.3f} | "
              f"{r['botanical_m'][0]:.3f} – {r['botanical_m'][1]:.3f} | {'yes' if r['within'] else 'no'} |")


if __name__ == "__main__":
    main()
