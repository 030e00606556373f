#!/usr/bin/python3
"""Contact sheet of leaf masks finer than a pixel: one row per stand, the whole autopilot view (1920x1080,
shown at a quarter) and a full-resolution crop of its busiest crown (the upper-half tile with the most
pixel-to-pixel contrast), RGB. With --before, each row shows that build's crop of the same place first.

Usage: scripts/mask_coverage_sheet.py [--silva build/silva] [--before OLD_SILVA] [--seed 7]
                                      [--scratch /tmp/silva-masks] [--out docs/realism-mask-coverage.jpg]
"""
import argparse
import pathlib

import cv2
import numpy as np

from floor_detail_sheet import TILE_H, TILE_W, render
from labelled_rows import labelled_row, write_sheet

STANDS = [  # label, settings
    ("mixed", []),
    ("spruce", ["vegetation.forest_type=spruce_plantation"]),
    ("winter", ["vegetation.season=winter"]),
]
LABEL_W = 100


def busiest_tile(view):
    """(x, y) of the full-resolution tile in the upper half of `view` whose neighbouring pixels differ most."""
    grey = cv2.cvtColor(view, cv2.COLOR_BGR2GRAY).astype(np.float32)
    contrast = np.abs(np.diff(grey, axis=1))[:-1, :] + np.abs(np.diff(grey, axis=0))[:, :-1]
    corners = [(x, y) for y in range(0, view.shape[0] // 2 - TILE_H + 1, TILE_H // 2)
               for x in range(0, view.shape[1] - TILE_W + 1, TILE_W // 2)]
    return max(corners, key=lambda c: float(contrast[c[1]:c[1] + TILE_H, c[0]:c[0] + TILE_W].mean()))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--silva", default="build/silva")
    parser.add_argument("--before", help="an older silva whose crops go first in each row")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--scratch", default="/tmp/silva-masks")
    parser.add_argument("--out", default="docs/realism-mask-coverage.jpg")
    args = parser.parse_args()
    scratch = pathlib.Path(args.scratch)
    rows = []
    for k, (label, settings) in enumerate(STANDS):
        view = render(args.silva, scratch / f"new{k}", args.seed, settings)
        old = render(args.before, scratch / f"old{k}", args.seed, settings) if args.before else None
        x, y = busiest_tile(old if old is not None else view)
        tiles = [cv2.resize(view, (TILE_W, TILE_H), interpolation=cv2.INTER_AREA), view[y:y + TILE_H, x:x + TILE_W]]
        if old is not None:
            tiles.insert(1, old[y:y + TILE_H, x:x + TILE_W])
        rows.append(labelled_row(label, tiles, LABEL_W))
    write_sheet(rows, args.out)


if __name__ == "__main__":
    main()
