#!/usr/bin/env python3
"""Tiles the outputs of one frame from the runs written by scripts/gallery.sh into one PNG.

usage: contact_sheet.py RUNS_DIR SEED FRAME OUT.png
Rows: <time>-<view> run folders (day/dusk/night x ground/aerial); columns: output types.
Instance ids (uint16) are shown through a fixed pseudo-colour so neighbouring ids differ.
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROWS = [f"{t}-{v}" for t in ("day", "dusk", "night") for v in ("ground", "aerial")]
COLUMNS = ["rgb", "semantic_color", "instance", "depth_preview", "normal"]


def instance_colours(ids: np.ndarray) -> np.ndarray:
    """Maps uint16 instance ids to RGB by a multiplicative hash; id 0 (none) is black."""
    h = (ids.astype(np.uint32) * np.uint32(2654435761)) & np.uint32(0xFFFFFF)
    rgb = np.stack([(h >> 16) & 255, (h >> 8) & 255, h & 255], axis=-1).astype(np.float32) / 255
    rgb[ids == 0] = 0
    return rgb


def load(path: Path, column: str) -> np.ndarray:
    """Reads one output PNG as an RGB float image."""
    image = plt.imread(path)
    if column == "instance":
        return instance_colours(np.rint(image * 65535).astype(np.uint16))
    if image.ndim == 2:
        return np.stack([image] * 3, axis=-1)
    return image[..., :3]


def main() -> None:
    runs, seed, frame, out = Path(sys.argv[1]), sys.argv[2], int(sys.argv[3]), Path(sys.argv[4])
    fig, axes = plt.subplots(len(ROWS), len(COLUMNS), figsize=(2.6 * len(COLUMNS), 1.6 * len(ROWS)), dpi=110)
    for r, row in enumerate(ROWS):
        for c, column in enumerate(COLUMNS):
            ax = axes[r][c]
            ax.imshow(load(runs / row / seed / "autopilot" / column / f"{frame:06d}.png", column))
            ax.set_xticks([])
            ax.set_yticks([])
            if r == 0:
                ax.set_title(column, fontsize=8)
            if c == 0:
                ax.set_ylabel(row, fontsize=8)
    fig.tight_layout(pad=0.3)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out)


if __name__ == "__main__":
    main()
