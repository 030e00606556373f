#!/usr/bin/python3
"""Contact sheet of the fern-layer herbs (wood sorrel beside the ferns): one row per stand, the whole random
view (1920x1080, shown at a quarter) and a full-resolution crop of its lower half, RGB. With --before, each
row shows that build's crop of the same place first, and the crop is where the two builds differ most (an
older build needs its own asset library: pass a wrapper that sets SILVA_ASSETS); without, the greenest.

Usage: scripts/herb_sheet.py [--silva build/silva] [--before OLD_SILVA] [--seed 7]
                             [--scratch /tmp/silva-herbs] [--out docs/realism-herbs.jpg]
"""
import subprocess

import cv2
import numpy as np

from labelled_rows import labelled_row, sheet_args, write_sheet

STANDS = [  # label, settings
    ("mixed", []),
    ("spruce", ["vegetation.forest_type=spruce_plantation"]),
    ("beech hall", ["vegetation.forest_type=beech_hall"]),
]
TILE_W, TILE_H = 480, 270
LABEL_W = 100
VIEWS = 4


def render(silva, out, seed, settings):
    """The VIEWS random views of `seed` with `settings` at 4x tile size (1920x1080), as BGR images."""
    command = [str(silva), "generate", "--seed", str(seed), "--quiet", "--overwrite", "--out", str(out),
               "--set", 'captures.sequences=["random"]', "--set", f"captures.random_count={VIEWS}",
               "--set", f"output.resolution={4 * TILE_W}x{4 * TILE_H}", "--set", 'output.types=["rgb"]']
    for setting in settings:
        command += ["--set", setting]
    subprocess.run(command, check=True)
    return [cv2.imread(str(out / f"{seed:010d}" / "random" / "rgb" / f"{k:06d}.png")) for k in range(VIEWS)]


def tiles_below_horizon(view):
    """(row, column) of the full-resolution tiles in the lower half of `view`, half a tile apart."""
    h, w = view.shape[:2]
    return [(y, x) for y in range(h // 2, h - TILE_H + 1, TILE_H // 2) for x in range(0, w - TILE_W + 1, TILE_W // 2)]


def tile(view, at):
    y, x = at
    return view[y:y + TILE_H, x:x + TILE_W]


def score(new, old, at):
    """How much the tile at `at` changed between the builds, or without `old`, how green it is."""
    a = tile(new, at).astype(np.float64)
    if old is not None:
        return float(np.abs(a - tile(old, at).astype(np.float64)).mean())
    b, g, r = a.reshape(-1, 3).mean(axis=0)
    return g - 0.5 * (r + b)


def main():
    args = sheet_args(__doc__, "/tmp/silva-herbs", "docs/realism-herbs.jpg", before=True)
    rows = []
    for k, (label, settings) in enumerate(STANDS):
        new = render(args.silva, args.scratch / f"new{k}", args.seed, settings)
        old = render(args.before, args.scratch / f"old{k}", args.seed, settings) if args.before else [None] * VIEWS
        v, at = max(((v, at) for v in range(VIEWS) for at in tiles_below_horizon(new[v])),
                    key=lambda c: score(new[c[0]], old[c[0]], c[1]))
        tiles = [cv2.resize(new[v], (TILE_W, TILE_H), interpolation=cv2.INTER_AREA), tile(new[v], at)]
        if args.before:
            tiles.insert(1, tile(old[v], at))
        rows.append(labelled_row(f"{label} {v}", tiles, LABEL_W))
    write_sheet(rows, args.out)


if __name__ == "__main__":
    main()
