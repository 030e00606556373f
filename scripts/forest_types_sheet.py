#!/usr/bin/python3
"""Contact sheet of the forest types (vegetation.forest_type): one row per type, two ground views and
one aerial view of the same seed, RGB.

Usage: scripts/forest_types_sheet.py [--silva build/silva] [--seed 7] [--scratch /tmp/silva-forest-types]
                                     [--out docs/realism-forest-types.jpg]
"""
import argparse
import pathlib
import subprocess

import cv2
import numpy as np

TYPES = ["mixed", "spruce_plantation", "beech_hall", "pine_heath"]
TILE_W, TILE_H = 480, 270
LABEL_W = 130


def render(silva, scratch, seed, forest, aerial):
    """The random views 0 and 1 of `seed` in forest type `forest`, ground or aerial, as BGR images."""
    out = scratch / f"{forest}-{'aerial' if aerial else 'ground'}"
    subprocess.run([str(silva), "generate", "--seed", str(seed), "--quiet", "--overwrite", "--out", str(out),
                    "--set", f"vegetation.forest_type={forest}",
                    "--set", f"captures.aerial={'true' if aerial else 'false'}",
                    "--set", 'captures.sequences=["random"]', "--set", "captures.random_count=2",
                    "--set", f"output.resolution={2 * TILE_W}x{2 * TILE_H}", "--set", 'output.types=["rgb"]'],
                   check=True)
    folder = out / f"{seed:010d}" / "random" / "rgb"
    return [cv2.resize(cv2.imread(str(folder / f"{k:06d}.png")), (TILE_W, TILE_H), interpolation=cv2.INTER_AREA)
            for k in (0, 1)]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--silva", default="build/silva")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--scratch", default="/tmp/silva-forest-types")
    parser.add_argument("--out", default="docs/realism-forest-types.jpg")
    args = parser.parse_args()
    scratch = pathlib.Path(args.scratch)
    gap = np.full((TILE_H, 4, 3), 255, np.uint8)
    rows = []
    for forest in TYPES:
        ground = render(args.silva, scratch, args.seed, forest, False)
        aerial = render(args.silva, scratch, args.seed, forest, True)
        label = np.zeros((TILE_H, LABEL_W, 3), np.uint8)
        cv2.putText(label, forest.replace("_", " "), (4, TILE_H // 2), cv2.FONT_HERSHEY_SIMPLEX, 0.45,
                    (255, 255, 255), 1, cv2.LINE_AA)
        rows.append(np.hstack([label, ground[0], gap, ground[1], gap, aerial[0]]))
        rows.append(np.full((4, rows[-1].shape[1], 3), 255, np.uint8))
    cv2.imwrite(args.out, np.vstack(rows[:-1]), [cv2.IMWRITE_JPEG_QUALITY, 80])


if __name__ == "__main__":
    main()
