#!/usr/bin/python3
"""Contact sheet of the forest floor at the camera's feet: one row per stand (forest type or season), the
whole autopilot view (1920x1080, shown at a quarter) and a full-resolution crop of the brighter, less
green bottom corner, RGB. With --before, each row shows that build's crop of the same place first.

Usage: scripts/floor_detail_sheet.py [--silva build/silva] [--before OLD_SILVA] [--seed 7]
                                     [--scratch /tmp/silva-floor] [--out docs/realism-floor.jpg]
"""
import argparse
import pathlib
import subprocess

import cv2

from labelled_rows import labelled_row, write_sheet

STANDS = [  # label, settings
    ("mixed", []),
    ("beech hall", ["vegetation.forest_type=beech_hall"]),
    ("spruce", ["vegetation.forest_type=spruce_plantation"]),
    ("autumn", ["vegetation.season=autumn"]),
]
TILE_W, TILE_H = 480, 270
LABEL_W = 100
FRAME = 4  # autopilot point 1 at yaw 0 (along the trail)


def render(silva, out, seed, settings):
    """Autopilot view FRAME of `seed` with `settings` at 4x tile size (1920x1080), as a BGR image."""
    command = [str(silva), "generate", "--seed", str(seed), "--quiet", "--overwrite", "--out", str(out),
               "--set", "trail.surface=packed_earth", "--set", 'captures.sequences=["autopilot"]',
               "--set", "captures.autopilot_points=3", "--set", "captures.autopilot_yaws=[-45.0, 0.0, 45.0]",
               "--set", f"output.resolution={4 * TILE_W}x{4 * TILE_H}", "--set", 'output.types=["rgb"]']
    for setting in settings:
        command += ["--set", setting]
    subprocess.run(command, check=True)
    return cv2.imread(str(out / f"{seed:010d}" / "autopilot" / "rgb" / f"{FRAME:06d}.png"))


def floor_window(view):
    """Left edge of the better of the two outer full-resolution tiles along the bottom of `view`: the floor
    beside the trail at the camera's feet, the brighter and less green (fewer ferns) the better."""
    h = view.shape[0]

    def score(x):
        b, g, r = (float(c) for c in view[h - TILE_H:h, x:x + TILE_W].reshape(-1, 3).mean(axis=0))
        return (b + g + r) / 3.0 - 2.0 * max(g - r, 0.0)

    return max((0, view.shape[1] - TILE_W), key=score)


def floor_crop(view, x):
    """The full-resolution tile at the bottom of `view` from column x."""
    h = view.shape[0]
    return view[h - TILE_H:h, x:x + TILE_W]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--silva", default="build/silva")
    parser.add_argument("--before", help="an older silva whose crops go first in each row")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--scratch", default="/tmp/silva-floor")
    parser.add_argument("--out", default="docs/realism-floor.jpg")
    args = parser.parse_args()
    scratch = pathlib.Path(args.scratch)
    rows = []
    for k, (label, settings) in enumerate(STANDS):
        view = render(args.silva, scratch / f"new{k}", args.seed, settings)
        x = floor_window(view)
        tiles = [cv2.resize(view, (TILE_W, TILE_H), interpolation=cv2.INTER_AREA), floor_crop(view, x)]
        if args.before:
            tiles.insert(1, floor_crop(render(args.before, scratch / f"old{k}", args.seed, settings), x))
        rows.append(labelled_row(label, tiles, LABEL_W))
    write_sheet(rows, args.out)


if __name__ == "__main__":
    main()
