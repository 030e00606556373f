#!/usr/bin/python3
"""Sunlit over shaded light on the forest floor, from a run and the same run without the sun.

Usage: scripts/sun_shade_ratio.py RUN_DIR SUNLESS_RUN_DIR [--plain-aces]

Both runs hold the same frames (same seeds, poses, exposure), the second with the sun's intensity at 0
and both without sensor noise. On ground and trail pixels nearer than 20 m, the tone curve inverted
(scripts/image_stats.py) gives each pixel's exposed light with and without the sun; where the sun adds
at least as much again (ratio >= 2) the pixel is sunlit, and its ratio is (sun + sky light) / sky light
at that very spot and material. Prints the median over sunlit floor pixels of all frames and their share.
"""
import glob
import importlib.util
import os
import sys

import cv2
import numpy as np

_spec = importlib.util.spec_from_file_location("image_stats", os.path.join(os.path.dirname(__file__), "image_stats.py"))
stats = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(stats)


def luminance(path):
    rgb = cv2.imread(path, cv2.IMREAD_COLOR)[:, :, ::-1].astype(np.float64) / 255.0
    signal = stats.exposed_signal(stats.srgb_to_linear(rgb))
    return signal @ np.array([0.2126, 0.7152, 0.0722]), (rgb < 1.0).all(axis=2)


def main():
    runs = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(runs) != 2:
        raise SystemExit(__doc__)
    ratios, floor_pixels = [], 0
    for rgb in sorted(glob.glob(os.path.join(runs[0], "**", "rgb", "*.png"), recursive=True)):
        other = os.path.join(runs[1], os.path.relpath(rgb, runs[0]))
        seq = os.path.dirname(os.path.dirname(rgb))
        name = os.path.basename(rgb)
        sem = cv2.imread(os.path.join(seq, "semantic", name), cv2.IMREAD_UNCHANGED)
        depth = cv2.imread(os.path.join(seq, "depth", name), cv2.IMREAD_UNCHANGED).astype(np.float64) / 1000.0
        lit, unclipped = luminance(rgb)
        shade, _ = luminance(other)
        floor = np.isin(sem, stats.FLOOR_CLASSES) & (depth > 0) & (depth < stats.FLOOR_REACH_M) & unclipped
        floor &= shade > 1e-4
        ratio = lit[floor] / shade[floor]
        floor_pixels += int(floor.sum())
        ratios.append(ratio[ratio >= 2.0])
    if not ratios:
        raise SystemExit(f"sun_shade_ratio.py: no rgb frames under {runs[0]}")
    sunlit = np.concatenate(ratios)
    print(f"sunlit/shaded floor: median {np.median(sunlit):.2f} over {sunlit.size} sunlit floor pixels "
          f"({100.0 * sunlit.size / max(floor_pixels, 1):.1f} % of the floor within 20 m), p10 "
          f"{np.percentile(sunlit, 10):.2f}, p90 {np.percentile(sunlit, 90):.2f}")


if __name__ == "__main__":
    main()
