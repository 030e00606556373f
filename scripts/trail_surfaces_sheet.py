#!/usr/bin/python3
"""Contact sheet of the trail surface families (trail.surface): one row per family, two autopilot views
along the trail of the same seed and a full-resolution crop of the trail in front of the camera, RGB.

Usage: scripts/trail_surfaces_sheet.py [--silva build/silva] [--seed 7] [--scratch /tmp/silva-trail-surfaces]
                                       [--out docs/realism-trails.jpg]
"""
import argparse
import pathlib
import subprocess

import cv2
import numpy as np

FAMILIES = ["packed_earth", "gravel", "roots", "leaf_covered", "muddy", "grass_ruts"]
TILE_W, TILE_H = 480, 270
LABEL_W = 120
FRAMES = (3, 9)  # autopilot points 1 and 3, yaw 0 (along the trail)


def render(silva, scratch, seed, family):
    """Two autopilot views of `seed` along the trail in family `family` at 2x tile size, as BGR images."""
    out = scratch / family
    subprocess.run([str(silva), "generate", "--seed", str(seed), "--quiet", "--overwrite", "--out", str(out),
                    "--set", f"trail.surface={family}", "--set", 'captures.sequences=["autopilot"]',
                    "--set", "captures.autopilot_points=6", "--set", "captures.autopilot_yaws=[-45.0, 0.0, 45.0]",
                    "--set", f"output.resolution={2 * TILE_W}x{2 * TILE_H}", "--set", 'output.types=["rgb"]'],
                   check=True)
    folder = out / f"{seed:010d}" / "autopilot" / "rgb"
    return [cv2.imread(str(folder / f"{k - 2:06d}.png")) for k in FRAMES]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--silva", default="build/silva")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--scratch", default="/tmp/silva-trail-surfaces")
    parser.add_argument("--out", default="docs/realism-trails.jpg")
    args = parser.parse_args()
    scratch = pathlib.Path(args.scratch)
    gap = np.full((TILE_H, 4, 3), 255, np.uint8)
    rows = []
    for family in FAMILIES:
        views = render(args.silva, scratch, args.seed, family)
        small = [cv2.resize(v, (TILE_W, TILE_H), interpolation=cv2.INTER_AREA) for v in views]
        h, w = views[0].shape[:2]
        crop = views[0][h - TILE_H:h, (w - TILE_W) // 2:(w + TILE_W) // 2]  # the trail at the camera's feet
        label = np.zeros((TILE_H, LABEL_W, 3), np.uint8)
        cv2.putText(label, family.replace("_", " "), (4, TILE_H // 2), cv2.FONT_HERSHEY_SIMPLEX, 0.45,
                    (255, 255, 255), 1, cv2.LINE_AA)
        rows.append(np.hstack([label, small[0], gap, small[1], gap, crop]))
        rows.append(np.full((4, rows[-1].shape[1], 3), 255, np.uint8))
    cv2.imwrite(args.out, np.vstack(rows[:-1]), [cv2.IMWRITE_JPEG_QUALITY, 80])


if __name__ == "__main__":
    main()
