#!/usr/bin/env python3
"""Before/after sheet of two demo runs: for each chosen frame, the first run's RGB and semantic
colours above the second run's (e.g. the previous and the current binary on configs/demo.toml).

usage: before_after.py BEFORE_RUN AFTER_RUN OUT.png [SEQUENCE/FRAME ...]
RUN folders are <output.dir>/<seed>/ with rgb/ and semantic_color/; frames default to four views.
"""
import sys
from pathlib import Path

import cv2
import numpy as np

FRAMES = ["autopilot/000005", "autopilot/000013", "random/000003", "random/000005"]
WIDTH = 480  # pixels per view


def view(run: Path, frame: str, kind: str) -> np.ndarray:
    """One output image of a frame, scaled to WIDTH pixels across."""
    seq, number = frame.split("/")
    img = cv2.imread(str(run / seq / kind / f"{number}.png"), cv2.IMREAD_COLOR)
    if img is None:
        sys.exit(f"before_after.py: {run / seq / kind / (number + '.png')} is missing")
    return cv2.resize(img, (WIDTH, img.shape[0] * WIDTH // img.shape[1]), interpolation=cv2.INTER_AREA)


def main() -> None:
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    before, after, out = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
    frames = sys.argv[4:] or FRAMES
    columns = []
    for frame in frames:
        cells = [view(run, frame, kind) for run in (before, after) for kind in ("rgb", "semantic_color")]
        columns.append(np.vstack(cells))
    cv2.imwrite(str(out), np.hstack(columns))
    print(f"wrote {out}: rows before rgb, before semantic, after rgb, after semantic; columns {frames}")


if __name__ == "__main__":
    main()
