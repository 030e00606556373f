#!/usr/bin/python3
"""Contact sheet of bark up close: a full-resolution crop around the nearest trunk of four 1920x1080 random
views (a pine on a pine heath, a spruce in a plantation, an oak and a birch's base in mixed forests), one
row per build. With --before, that build's row comes first. The crops are centred on this build's trunk
pixels within 8 m (labels and depth are the same for both builds).

Usage: scripts/bark_sheet.py [--silva build/silva] [--before OLD_SILVA]
                             [--scratch /tmp/silva-bark] [--out docs/realism-bark.jpg]
"""
import subprocess

import cv2
import numpy as np

from labelled_rows import labelled_row, sheet_args, write_sheet

# (label, seed, forest type, random view index)
SCENES = [("pine", 7, "pine_heath", 3), ("spruce", 7, "spruce_plantation", 9), ("oak", 21, "mixed", 6),
          ("birch base", 21, "mixed", 2)]
TILE_W, TILE_H = 300, 400
LABEL_W = 80
TRUNK = 3  # the tree_trunk class id
NEAR_MM = 8000
CONFIG = """seed = {seed}
[output]
dir = "{out}"
resolution = "1920x1080"
types = ["rgb", "semantic", "depth"]
[vegetation]
forest_type = "{forest}"
[captures]
sequences = ["random"]
random_count = {count}
"""


def render(silva, scratch, seed, forest, view):
    """Random view `view` of world `seed` as `forest`, from `silva`: its RGB, semantic and depth images."""
    folder = scratch / f"{seed}-{forest}"
    folder.mkdir(parents=True, exist_ok=True)
    config = folder / "bark.toml"
    config.write_text(CONFIG.format(seed=seed, out=folder / "out", forest=forest, count=view + 1))
    subprocess.run([silva, "generate", "--config", str(config), "--overwrite", "--quiet"], check=True)
    frame = folder / "out" / f"{seed:010d}" / "random"
    name = f"{view:06d}.png"
    return [cv2.imread(str(frame / kind / name), cv2.IMREAD_UNCHANGED) for kind in ("rgb", "semantic", "depth")]


def trunk_window(semantic, depth):
    """Top-left corner of the tile centred on the median of the trunk pixels nearer than NEAR_MM."""
    ys, xs = np.nonzero((semantic == TRUNK) & (depth < NEAR_MM))
    h, w = semantic.shape
    y0 = int(np.clip(np.median(ys) - TILE_H // 2, 0, h - TILE_H))
    x0 = int(np.clip(np.median(xs) - TILE_W // 2, 0, w - TILE_W))
    return y0, x0


def main():
    args = sheet_args(__doc__, "/tmp/silva-bark", "docs/realism-bark.jpg", before=True)
    builds = ([("before", args.before)] if args.before else []) + [("this build", args.silva)]
    tiles = {label: [] for label, _ in builds}
    for name, seed, forest, view in SCENES:
        images = {label: render(silva, args.scratch / label.replace(" ", "-"), seed, forest, view)
                  for label, silva in builds}
        y0, x0 = trunk_window(*images["this build"][1:])
        for label, _ in builds:
            tile = images[label][0][y0:y0 + TILE_H, x0:x0 + TILE_W].copy()
            cv2.rectangle(tile, (0, 0), (12 * len(name) + 12, 28), (0, 0, 0), -1)
            cv2.putText(tile, name, (6, 20), cv2.FONT_HERSHEY_SIMPLEX, 0.55, (255, 255, 255), 1, cv2.LINE_AA)
            tiles[label].append(tile)
    write_sheet([labelled_row(label, tiles[label], LABEL_W) for label, _ in builds], args.out)


if __name__ == "__main__":
    main()
