#!/usr/bin/python3
"""Contact sheet of the trail surface families (trail.surface): one row per family, two autopilot views
along the trail of the same seed and a full-resolution crop of the trail in front of the camera, RGB.

Usage: scripts/trail_surfaces_sheet.py [--silva build/silva] [--seed 7] [--scratch /tmp/silva-trail-surfaces]
                                       [--out docs/realism-trails.jpg]
"""
import subprocess

import cv2

from labelled_rows import labelled_row, sheet_args, write_sheet

FAMILIES = ["packed_earth", "gravel", "roots", "leaf_covered", "muddy", "grass_ruts"]
TILE_W, TILE_H = 480, 270
LABEL_W = 120
FRAMES = (1, 7)  # autopilot points 0 and 2 at yaw 0 (along the trail): frame = 3 point + yaw index


def render(silva, scratch, seed, family):
    """Two autopilot views of `seed` along the trail in family `family` at 2x tile size, as BGR images."""
    out = scratch / family
    subprocess.run([str(silva), "generate", "--seed", str(seed), "--quiet", "--overwrite", "--out", str(out),
                    "--set", f"trail.surface={family}", "--set", 'captures.sequences=["autopilot"]',
                    "--set", "captures.autopilot_points=6", "--set", "captures.autopilot_yaws=[-45.0, 0.0, 45.0]",
                    "--set", f"output.resolution={2 * TILE_W}x{2 * TILE_H}", "--set", 'output.types=["rgb"]'],
                   check=True)
    folder = out / f"{seed:010d}" / "autopilot" / "rgb"
    return [cv2.imread(str(folder / f"{k:06d}.png")) for k in FRAMES]


def main():
    args = sheet_args(__doc__, "/tmp/silva-trail-surfaces", "docs/realism-trails.jpg")
    rows = []
    for family in FAMILIES:
        views = render(args.silva, args.scratch, args.seed, family)
        small = [cv2.resize(v, (TILE_W, TILE_H), interpolation=cv2.INTER_AREA) for v in views]
        h, w = views[0].shape[:2]
        crop = views[0][h - TILE_H:h, (w - TILE_W) // 2:(w + TILE_W) // 2]  # the trail at the camera's feet
        rows.append(labelled_row(family, small + [crop], LABEL_W))
    write_sheet(rows, args.out)


if __name__ == "__main__":
    main()
