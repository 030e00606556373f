#!/usr/bin/python3
"""Contact sheet of the forest types (vegetation.forest_type): one row per type, two ground views and
one aerial view of the same seed, RGB.

Usage: scripts/forest_types_sheet.py [--silva build/silva] [--seed 7] [--scratch /tmp/silva-forest-types]
                                     [--out docs/realism-forest-types.jpg]
"""
import subprocess

import cv2

from labelled_rows import labelled_row, sheet_args, write_sheet

TYPES = ["mixed", "spruce_plantation", "beech_hall", "pine_heath"]
TILE_W, TILE_H = 480, 270
LABEL_W = 130


def render(silva, scratch, seed, forest, aerial):
    """The random views 0 and 1 of `seed` in forest type `forest`, ground or aerial, as BGR images."""
    out = scratch / f"{forest}-{'aerial' if aerial else 'ground'}"
    subprocess.run([str(silva), "generate", "--seed", str(seed), "--quiet", "--overwrite", "--out", str(out),
                    "--set", f"vegetation.forest_type={forest}",
                    "--set", f"captures.aerial={'true' if aerial else 'false'}",
                    "--set", 'captures.sequences=["random"]', "--set", "captures.random_count=2",
                    "--set", f"output.resolution={2 * TILE_W}x{2 * TILE_H}", "--set", 'output.types=["rgb"]'],
                   check=True)
    folder = out / f"{seed:010d}" / "random" / "rgb"
    return [cv2.resize(cv2.imread(str(folder / f"{k:06d}.png")), (TILE_W, TILE_H), interpolation=cv2.INTER_AREA)
            for k in (0, 1)]


def main():
    args = sheet_args(__doc__, "/tmp/silva-forest-types", "docs/realism-forest-types.jpg")
    rows = []
    for forest in TYPES:
        ground = render(args.silva, args.scratch, args.seed, forest, False)
        aerial = render(args.silva, args.scratch, args.seed, forest, True)
        rows.append(labelled_row(forest, [ground[0], ground[1], aerial[0]], LABEL_W))
    write_sheet(rows, args.out)


if __name__ == "__main__":
    main()
