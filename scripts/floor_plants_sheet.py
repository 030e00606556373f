#!/usr/bin/python3
"""Contact sheet of a floor plant (wood sorrel, woodruff, nettle, grass swards or wood anemone): one row per stand, a random view (1920x1080) that
shows the plant, at a quarter size, then a full-resolution crop of it, RGB. With --before, each row shows that
build's view and crop of the same pose first (an older build needs its own asset library: pass a wrapper that
sets SILVA_ASSETS; where placement draws differ between the builds, the plants around the pose differ too).

Usage: scripts/floor_plants_sheet.py [--plant wood_sorrel|woodruff|nettle|grass_sward|wood_anemone] [--silva build/silva]
                                     [--before OLD_SILVA]
                                     [--seed 7] [--scratch /tmp/silva-floor-plants] [--out FILE]
       (--out defaults to docs/realism-herbs.jpg, docs/realism-woodruff.jpg, docs/realism-nettle.jpg,
       docs/realism-grass.jpg or docs/realism-spring.jpg; wood anemone grows in spring and early spring only, so its
       rows show each view in summer, spring and early spring, then a fern in summer and spring (unrolling from
       croziers), then a view in winter and early spring (bracken standing dead, then laid flat), then a beech-hall
       view in summer and spring, and --before is not needed)
"""
import subprocess

import cv2

from labelled_rows import labelled_row, sheet_args, write_sheet

PLANTS = {  # plant: (default sheet, rows of label, settings, random view, (top, left) of a crop showing it, seed 7)
    "wood_sorrel": ("docs/realism-herbs.jpg", [
        ("mixed", [], 1, (700, 180)),
        ("spruce", ["vegetation.forest_type=spruce_plantation"], 4, (760, 100)),
    ]),
    "woodruff": ("docs/realism-woodruff.jpg", [
        ("mixed", [], 5, (610, 0)),
        ("mixed", [], 0, (580, 120)),
    ]),
    "nettle": ("docs/realism-nettle.jpg", [
        ("summer", [], 5, (540, 800)),
        ("winter", ["vegetation.season=winter"], 5, (540, 800)),
    ]),
    "wood_anemone": ("docs/realism-spring.jpg", [
        ("summer", [], 4, (560, 780)),
        ("spring", ["vegetation.season=spring"], 4, (560, 780)),
        ("early spr.", ["vegetation.season=early_spring"], 4, (560, 780)),
        ("summer", [], 0, (60, 1300)),
        ("spring", ["vegetation.season=spring"], 0, (60, 1300)),
        ("early spr.", ["vegetation.season=early_spring"], 0, (60, 1300)),
        ("summer", [], 0, (810, 300)),
        ("spring", ["vegetation.season=spring"], 0, (810, 300)),
        ("winter", ["vegetation.season=winter"], 1, (760, 1100)),
        ("early spr.", ["vegetation.season=early_spring"], 1, (760, 1100)),
        ("beech sum.", ["vegetation.forest_type=beech_hall"], 0, (780, 1040)),
        ("beech spr.", ["vegetation.forest_type=beech_hall", "vegetation.season=spring"], 0, (780, 1040)),
    ]),
    "grass_sward": ("docs/realism-grass.jpg", [
        ("mixed", [], 4, (730, 0)),
        ("pine heath", ["vegetation.forest_type=pine_heath"], 0, (760, 80)),
    ]),
}
TILE_W, TILE_H = 480, 270
LABEL_W = 100
VIEWS = 6


def render(silva, out, seed, settings, view):
    """Random view `view` of `seed` with `settings` at 4x tile size (1920x1080), as a BGR image."""
    command = [str(silva), "generate", "--seed", str(seed), "--quiet", "--overwrite", "--out", str(out),
               "--set", 'captures.sequences=["random"]', "--set", f"captures.random_count={VIEWS}",
               "--set", f"output.resolution={4 * TILE_W}x{4 * TILE_H}", "--set", 'output.types=["rgb"]']
    for setting in settings:
        command += ["--set", setting]
    subprocess.run(command, check=True)
    return cv2.imread(str(out / f"{seed:010d}" / "random" / "rgb" / f"{view:06d}.png"))


def tiles(view, at):
    """`view` at a quarter size and its full-resolution tile with top-left corner `at`."""
    y, x = at
    return [cv2.resize(view, (TILE_W, TILE_H), interpolation=cv2.INTER_AREA), view[y:y + TILE_H, x:x + TILE_W]]


def main():
    args = sheet_args(__doc__, "/tmp/silva-floor-plants", None, before=True,
                      extra=lambda p: p.add_argument("--plant", choices=sorted(PLANTS), default="wood_sorrel"))
    sheet, stands = PLANTS[args.plant]
    rows = []
    for k, (label, settings, view, at) in enumerate(stands):
        row = tiles(render(args.silva, args.scratch / f"new{k}", args.seed, settings, view), at)
        if args.before:
            row = tiles(render(args.before, args.scratch / f"old{k}", args.seed, settings, view), at) + row
        rows.append(labelled_row(label, row, LABEL_W))
    write_sheet(rows, args.out or sheet)


if __name__ == "__main__":
    main()
