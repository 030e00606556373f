#!/usr/bin/python3
"""Before/after sheet of scripts/how_real.sh runs: one row per condition, the same view side by side.

Usage: scripts/before_after_sheet.py BEFORE_DIR AFTER_DIR OUT.jpg [SEED [VIEW]]
(SEED 7 and VIEW 3 by default: random view 3 of seed 7 under day clear, day overcast, day rain, dusk, night.)
"""
import os
import sys

import cv2
import numpy as np

SCALE = 0.75  # of each view, to keep the sheet small enough for the README
CONDITIONS = ["day-clear", "day-overcast", "day-rain", "dusk-clear", "night-clear"]


def main():
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    before, after, out = sys.argv[1:4]
    seed = int(sys.argv[4]) if len(sys.argv) > 4 else 7
    view = int(sys.argv[5]) if len(sys.argv) > 5 else 3
    rows = []
    for condition in CONDITIONS:
        pair = []
        for run in (before, after):
            path = os.path.join(run, condition, f"{seed:010d}", "random", "rgb", f"{view:06d}.png")
            image = cv2.imread(path, cv2.IMREAD_COLOR)
            if image is None:
                raise SystemExit(f"before_after_sheet.py: cannot read {path}")
            pair.append(cv2.resize(image, None, fx=SCALE, fy=SCALE, interpolation=cv2.INTER_AREA))
        label = np.zeros((pair[0].shape[0], 112, 3), np.uint8)
        cv2.putText(label, condition.replace("-", " "), (4, pair[0].shape[0] // 2), cv2.FONT_HERSHEY_SIMPLEX, 0.45,
                    (255, 255, 255), 1, cv2.LINE_AA)
        rows.append(np.hstack([label, pair[0], np.full((pair[0].shape[0], 6, 3), 255, np.uint8), pair[1]]))
    sheet = np.vstack(rows)
    cv2.imwrite(out, sheet, [cv2.IMWRITE_JPEG_QUALITY, 82])


if __name__ == "__main__":
    main()
