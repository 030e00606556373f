#!/usr/bin/python3
"""Contact sheet of wood at the ground: fallen trees' root plates (`silva assets sheet --kind fallen_tree`, each
variant alone on a flat floor in the day preset, the lower left of its view where the plate stands) and a
beech-hall view's lower band (trunk feet, a fallen tree), one row per build. With --before, that build's rows
come first.

Usage: scripts/wood_sheet.py [--silva build/silva] [--before OLD_SILVA] [--seed 7]
                             [--scratch /tmp/silva-wood] [--out docs/realism-wood.jpg]
"""
import subprocess

import cv2

from labelled_rows import labelled_row, sheet_args, write_sheet

VARIANTS = 4
CELL = 1000  # pixels per side of one asset-sheet view
PLATE = (slice(480, 930), slice(60, 560))  # rows, columns of an asset view: the root plate at the trunk's base
PLATE_SCALE = 0.6
LABEL_W = 70
VIEW_BAND = slice(300, 560)  # rows of the 1280x720 view: the trunks' feet and the floor
CONFIG = """seed = {seed}
[output]
dir = "{out}"
resolution = "1280x720"
types = ["rgb"]
[vegetation]
forest_type = "beech_hall"
[captures]
sequences = ["random"]
random_count = 1
"""


def plates(silva, seed, png):
    """The root-plate crop of each variant (asset seed `seed`) from `silva`'s fallen-tree sheet written to `png`."""
    subprocess.run([silva, "assets", "sheet", "--kind", "fallen_tree", "--count", str(VARIANTS), "--columns",
                    str(VARIANTS), "--cell", str(CELL), "--seed", str(seed), "--out", str(png), "--quiet"], check=True)
    sheet = cv2.imread(str(png), cv2.IMREAD_COLOR)
    views = [sheet[:, 2 * k * CELL:(2 * k + 1) * CELL] for k in range(VARIANTS)]  # RGB views; labels between
    return [cv2.resize(v[PLATE], None, fx=PLATE_SCALE, fy=PLATE_SCALE, interpolation=cv2.INTER_AREA) for v in views]


def view_band(silva, seed, scratch, width):
    """The lower band of random view 0 of world `seed` as a beech hall, from `silva`, scaled to `width` pixels."""
    config = scratch / "wood.toml"
    config.write_text(CONFIG.format(seed=seed, out=scratch / "out"))
    subprocess.run([silva, "generate", "--config", str(config), "--overwrite", "--quiet"], check=True)
    view = cv2.imread(str(scratch / "out" / f"{seed:010d}" / "random" / "rgb" / "000000.png"), cv2.IMREAD_COLOR)
    band = view[VIEW_BAND]
    return cv2.resize(band, (width, round(band.shape[0] * width / band.shape[1])), interpolation=cv2.INTER_AREA)


def build_rows(label, silva, args, scratch):
    """The plate row and the view row of one build."""
    scratch.mkdir(parents=True, exist_ok=True)
    plate_row = labelled_row(label, plates(silva, args.seed, scratch / "plates.png"), LABEL_W)
    band = view_band(silva, args.seed, scratch, plate_row.shape[1] - LABEL_W)
    return [plate_row, labelled_row(label, [band], LABEL_W)]


def main():
    args = sheet_args(__doc__, "/tmp/silva-wood", "docs/realism-wood.jpg", before=True)
    rows = []
    if args.before:
        rows += build_rows("before", args.before, args, args.scratch / "before")
    rows += build_rows("this build", args.silva, args, args.scratch / "after")
    write_sheet(rows, args.out)


if __name__ == "__main__":
    main()
