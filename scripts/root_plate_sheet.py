#!/usr/bin/python3
"""Contact sheet of fallen trees' root plates: `silva assets sheet --kind fallen_tree` (each variant alone on
a flat floor in the day preset), the lower left of each variant's RGB view where its root plate stands, one
row per build. With --before, that build's row comes first.

Usage: scripts/root_plate_sheet.py [--silva build/silva] [--before OLD_SILVA] [--seed 7]
                                   [--scratch /tmp/silva-root-plates] [--out docs/realism-root-plate.jpg]
"""
import subprocess

import cv2

from labelled_rows import labelled_row, sheet_args, write_sheet

VARIANTS = 4
CELL = 1000  # pixels per side of one sheet view
CROP = (slice(480, 930), slice(60, 560))  # rows, columns of a view: the root plate at the trunk's base
SCALE = 0.6


def plates(silva, seed, png):
    """The root-plate crop of each variant (asset seed `seed`) from `silva`'s fallen-tree sheet written to `png`."""
    subprocess.run([silva, "assets", "sheet", "--kind", "fallen_tree", "--count", str(VARIANTS), "--columns",
                    str(VARIANTS), "--cell", str(CELL), "--seed", str(seed), "--out", str(png), "--quiet"], check=True)
    sheet = cv2.imread(str(png), cv2.IMREAD_COLOR)
    views = [sheet[:, 2 * k * CELL:(2 * k + 1) * CELL] for k in range(VARIANTS)]  # RGB views; labels between
    return [cv2.resize(v[CROP], None, fx=SCALE, fy=SCALE, interpolation=cv2.INTER_AREA) for v in views]


def main():
    args = sheet_args(__doc__, "/tmp/silva-root-plates", "docs/realism-root-plate.jpg", before=True)
    args.scratch.mkdir(parents=True, exist_ok=True)
    rows = []
    if args.before:
        rows.append(labelled_row("before", plates(args.before, args.seed, args.scratch / "before.png"), 70))
    rows.append(labelled_row("this build", plates(args.silva, args.seed, args.scratch / "after.png"), 70))
    write_sheet(rows, args.out)


if __name__ == "__main__":
    main()
