"""Shared parts of the realism contact sheets: the command line and rows of tiles behind a label."""
import argparse
import pathlib

import cv2
import numpy as np


def sheet_args(doc, scratch, out, before=False, extra=None):
    """Parses --silva, --seed (7), --scratch and --out (defaults `scratch`, `out`) for a sheet script, with
    `before` --before (an older silva whose crops go first in each row), and what extra(parser) adds."""
    parser = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--silva", default="build/silva")
    if before:
        parser.add_argument("--before", help="an older silva whose crops go first in each row")
    if extra:
        extra(parser)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--scratch", default=scratch)
    parser.add_argument("--out", default=out)
    args = parser.parse_args()
    args.scratch = pathlib.Path(args.scratch)
    return args


def labelled_row(label, tiles, label_w):
    """One row: `label` in white on black, then the BGR tiles (all the same height) 4 px apart."""
    h = tiles[0].shape[0]
    text = np.zeros((h, label_w, 3), np.uint8)
    cv2.putText(text, label.replace("_", " "), (4, h // 2), cv2.FONT_HERSHEY_SIMPLEX, 0.45, (255, 255, 255), 1,
                cv2.LINE_AA)
    gap = np.full((h, 4, 3), 255, np.uint8)
    parts = [text]
    for tile in tiles:
        parts += [tile, gap]
    return np.hstack(parts[:-1])


def write_sheet(rows, out):
    """Stacks `rows` 4 px apart and writes them to `out` as a JPEG of quality 80."""
    spaced = []
    for row in rows:
        spaced += [row, np.full((4, row.shape[1], 3), 255, np.uint8)]
    cv2.imwrite(str(out), np.vstack(spaced[:-1]), [cv2.IMWRITE_JPEG_QUALITY, 80])
