#!/usr/bin/python3
"""Sheet of the demo's views (docs/demo-views.png): for each chosen frame of one run, its RGB above
its semantic colours, the frames side by side. Needs numpy and OpenCV (cv2).

usage: scripts/demo_views.py RUN_DIR OUT.png [SEQUENCE/FRAME ...]
RUN_DIR is <output.dir>/<seed>/ with rgb/ and semantic_color/ (make run writes out/1234567890/);
frames default to four views of configs/demo.toml.
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
    path = run / seq / kind / f"{number}.png"
    img = cv2.imread(str(path), cv2.IMREAD_COLOR)
    if img is None:
        sys.exit(f"demo_views.py: {path} is missing")
    return cv2.resize(img, (WIDTH, img.shape[0] * WIDTH // img.shape[1]), interpolation=cv2.INTER_AREA)


def main() -> None:
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    run, out = Path(sys.argv[1]), Path(sys.argv[2])
    frames = sys.argv[3:] or FRAMES
    columns = [np.vstack([view(run, frame, kind) for kind in ("rgb", "semantic_color")]) for frame in frames]
    cv2.imwrite(str(out), np.hstack(columns))
    print(f"wrote {out}: rows rgb, semantic colours; columns {frames}")


if __name__ == "__main__":
    main()
