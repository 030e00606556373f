#!/usr/bin/python3
"""Contact sheet of the sky's glare: one row per stand, the whole autopilot view (1920x1080, shown at a quarter)
and a full-resolution crop of its busiest crown against the sky (as scripts/mask_coverage_sheet.py picks it), RGB.
With --before, each row shows that build's crop of the same place first.

Usage: scripts/glare_sheet.py [--silva build/silva] [--before OLD_SILVA] [--seed 7]
                              [--scratch /tmp/silva-glare] [--out docs/realism-glare.jpg]
"""

from floor_detail_sheet import stand_rows
from labelled_rows import sheet_args, write_sheet
from mask_coverage_sheet import busiest_tile, crop_at

STANDS = [  # label, settings
    ("mixed", []),
    ("beech hall", ["vegetation.forest_type=beech_hall"]),
    ("pine heath", ["vegetation.forest_type=pine_heath"]),
]


def main():
    args = sheet_args(__doc__, "/tmp/silva-glare", "docs/realism-glare.jpg", before=True)
    write_sheet(stand_rows(args, STANDS, lambda view: crop_at(*busiest_tile(view))), args.out)


if __name__ == "__main__":
    main()
