#!/usr/bin/python3
"""Contact sheet of leaf masks finer than a pixel: one row per stand, the whole autopilot view (1920x1080,
shown at a quarter) and a full-resolution crop of its busiest crown (the upper-half tile with the most
pixel-to-pixel contrast), RGB. With --before, each row shows that build's crop of the same place first.

Usage: scripts/mask_coverage_sheet.py [--silva build/silva] [--before OLD_SILVA] [--seed 7]
                                      [--scratch /tmp/silva-masks] [--out docs/realism-mask-coverage.jpg]
"""

import cv2
import numpy as np

from floor_detail_sheet import TILE_H, TILE_W, stand_rows
from labelled_rows import sheet_args, write_sheet

STANDS = [  # label, settings
    ("mixed", []),
    ("spruce", ["vegetation.forest_type=spruce_plantation"]),
    ("winter", ["vegetation.season=winter"]),
]
def busiest_tile(view):
    """(x, y) of the full-resolution tile in the upper half of `view` whose neighbouring pixels differ most."""
    grey = cv2.cvtColor(view, cv2.COLOR_BGR2GRAY).astype(np.float32)
    contrast = np.abs(np.diff(grey, axis=1))[:-1, :] + np.abs(np.diff(grey, axis=0))[:, :-1]
    corners = [(x, y) for y in range(0, view.shape[0] // 2 - TILE_H + 1, TILE_H // 2)
               for x in range(0, view.shape[1] - TILE_W + 1, TILE_W // 2)]
    return max(corners, key=lambda c: float(contrast[c[1]:c[1] + TILE_H, c[0]:c[0] + TILE_W].mean()))


def crop_at(x, y):
    """The crop function of the full-resolution tile at (x, y)."""
    return lambda image: image[y:y + TILE_H, x:x + TILE_W]


def main():
    args = sheet_args(__doc__, "/tmp/silva-masks", "docs/realism-mask-coverage.jpg", before=True)
    write_sheet(stand_rows(args, STANDS, lambda view: crop_at(*busiest_tile(view))), args.out)


if __name__ == "__main__":
    main()
