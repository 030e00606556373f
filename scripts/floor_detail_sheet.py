#!/usr/bin/python3
"""Contact sheet of the forest floor at the camera's feet: one row per stand (forest type or season), the
whole autopilot view (1920x1080, shown at a quarter) and a full-resolution crop of the brighter, less
green bottom corner, RGB. With --before, each row shows that build's crop of the same place first.

Usage: scripts/floor_detail_sheet.py [--silva build/silva] [--before OLD_SILVA] [--seed 7]
                                     [--scratch /tmp/silva-floor] [--out docs/realism-floor.jpg]
"""
import subprocess

import cv2

from labelled_rows import labelled_row, sheet_args, write_sheet

STANDS = [  # label, settings
    ("mixed", []),
    ("beech hall", ["vegetation.forest_type=beech_hall"]),
    ("spruce", ["vegetation.forest_type=spruce_plantation"]),
    ("autumn", ["vegetation.season=autumn"]),
]
TILE_W, TILE_H = 480, 270
LABEL_W = 100
FRAME = 4  # autopilot point 1 at yaw 0 (along the trail)
FLOOR_FRAME = 1  # autopilot point 0 at yaw 0: the floor sheet's view (sunlit floor near the camera in each stand)


def render(silva, out, seed, settings, frame=FRAME):
    """Autopilot view `frame` of `seed` with `settings` at 4x tile size (1920x1080), as a BGR image."""
    command = [str(silva), "generate", "--seed", str(seed), "--quiet", "--overwrite", "--out", str(out),
               "--set", "trail.surface=packed_earth", "--set", 'captures.sequences=["autopilot"]',
               "--set", "captures.autopilot_points=3", "--set", "captures.autopilot_yaws=[-45.0, 0.0, 45.0]",
               "--set", f"output.resolution={4 * TILE_W}x{4 * TILE_H}", "--set", 'output.types=["rgb"]']
    for setting in settings:
        command += ["--set", setting]
    subprocess.run(command, check=True)
    return cv2.imread(str(out / f"{seed:010d}" / "autopilot" / "rgb" / f"{frame:06d}.png"))


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


def stand_rows(args, stands, pick, frame=FRAME):
    """One labelled row per (label, settings) of `stands`: the whole view `frame` at a quarter, then the --before
    build's crop (when given) and this build's, where pick(view) returns the crop function for this build's view."""
    rows = []
    for k, (label, settings) in enumerate(stands):
        view = render(args.silva, args.scratch / f"new{k}", args.seed, settings, frame)
        crop = pick(view)
        tiles = [cv2.resize(view, (TILE_W, TILE_H), interpolation=cv2.INTER_AREA), crop(view)]
        if args.before:
            tiles.insert(1, crop(render(args.before, args.scratch / f"old{k}", args.seed, settings, frame)))
        rows.append(labelled_row(label, tiles, LABEL_W))
    return rows


def main():
    args = sheet_args(__doc__, "/tmp/silva-floor", "docs/realism-floor.jpg", before=True)
    write_sheet(stand_rows(args, STANDS, lambda view: (lambda image, x=floor_window(view): floor_crop(image, x)), FLOOR_FRAME),
                args.out)


if __name__ == "__main__":
    main()
