#!/usr/bin/python3
"""Sunflecks on the floor before and after: the lower bands of two demo autopilot views (configs/demo.toml,
1280x720), an older build's row above this build's. The shadow lookup's filter shapes them: round, they are the
sun's images through the canopy's gaps; square, the shadow map's texels.

Usage: scripts/sunfleck_sheet.py --before OLD_SILVA [--silva build/silva] [--scratch /tmp/silva-sunflecks]
                                 [--out docs/realism-sunflecks.jpg]
"""
import subprocess

import cv2

from labelled_rows import labelled_row, sheet_args, write_sheet

BANDS = [(10, (470, 0)), (16, (470, 480))]  # autopilot frame, (top, left) of its 800x250 band
BAND_W, BAND_H = 800, 250
LABEL_W = 80


def bands(silva, out):
    """The BANDS of the demo's autopilot views rendered by `silva` into `out`."""
    subprocess.run([str(silva), "generate", "--config", "configs/demo.toml", "--quiet", "--overwrite", "--out", str(out),
                    "--set", 'captures.sequences=["autopilot"]', "--set", 'output.types=["rgb"]'], check=True)
    tiles = []
    for frame, (y, x) in BANDS:
        view = cv2.imread(str(out / "1234567890" / "autopilot" / "rgb" / f"{frame:06d}.png"))
        tiles.append(view[y:y + BAND_H, x:x + BAND_W])
    return tiles


def main():
    args = sheet_args(__doc__, "/tmp/silva-sunflecks", "docs/realism-sunflecks.jpg", before=True)
    if not args.before:
        raise SystemExit("sunfleck_sheet.py: --before OLD_SILVA is needed (the row above)")
    write_sheet([labelled_row("before", bands(args.before, args.scratch / "old"), LABEL_W),
                 labelled_row("after", bands(args.silva, args.scratch / "new"), LABEL_W)], args.out)


if __name__ == "__main__":
    main()
