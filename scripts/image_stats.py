#!/usr/bin/python3
"""Tone statistics of a Silva run's RGB frames, the numbers README "How real" reports.

Usage: scripts/image_stats.py RUN_DIR [RUN_DIR ...] [--json] [--plain-aces]

RUN_DIR holds one or more runs (every rgb/ folder below it counts). --plain-aces inverts the tone
curve of builds before the camera's white point (the bare ACES fit) for floor_ratio_scene.

Per run (all frames of every sequence): luma percentiles p1/p50/p99 and RMS contrast of Rec.709
luma on the sRGB values (0..1); the share of pixels with a clipped channel (255); the mean HSV
saturation of pixels with luma above 0.05 (the colourfulness of what is not black); the mean CIELAB
chroma C*ab (D65) of all pixels (colour as a viewer sees it: dark and grey pixels have little); and the sunlit/shaded
floor ratio: the 95th over the 10th percentile of luminance of unclipped ground and trail pixels
nearer than 20 m, on the display-linear image (floor_ratio_display) and on the exposed scene light
(floor_ratio_scene: Silva's tone curve, render/post.hpp, inverted), median over frames (semantic and
depth outputs needed; without them both are left out).
"""
import glob
import json
import os
import sys

import cv2
import numpy as np

FLOOR_CLASSES = (1, 2)  # ground, trail (configs/ontology.json)
FLOOR_REACH_M = 20.0


def srgb_to_linear(c):
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


ACES_WHITE = 2.54 / 3.16  # the ACES fit at 1, the exposed signal the camera maps to white


def aces(x):
    return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)


PLAIN_ACES = "--plain-aces" in sys.argv
_SIGNAL = np.linspace(0.0, 7.0 if PLAIN_ACES else 1.0, 200001)
_DISPLAY = aces(_SIGNAL) / (1.0 if PLAIN_ACES else ACES_WHITE)


def exposed_signal(display_linear):
    """Silva's tone curve (the ACES fit scaled to reach white at signal 1, or bare) inverted."""
    return np.interp(display_linear, _DISPLAY, _SIGNAL)


def frame_paths(run):
    for rgb in sorted(glob.glob(os.path.join(run, "**", "rgb", "*.png"), recursive=True)):
        seq = os.path.dirname(os.path.dirname(rgb))
        name = os.path.basename(rgb)
        yield rgb, os.path.join(seq, "semantic", name), os.path.join(seq, "depth", name)


def run_stats(run):
    luma, sat, chroma, clipped, pixels, floor = [], [], [], 0, 0, []
    for rgb_path, sem_path, depth_path in frame_paths(run):
        rgb = cv2.imread(rgb_path, cv2.IMREAD_COLOR)[:, :, ::-1].astype(np.float64) / 255.0
        y = 0.2126 * rgb[:, :, 0] + 0.7152 * rgb[:, :, 1] + 0.0722 * rgb[:, :, 2]
        luma.append(y.ravel()[::7])
        clipped += int((rgb >= 1.0).any(axis=2).sum())
        pixels += y.size
        hsv = cv2.cvtColor((rgb[:, :, ::-1] * 255).astype(np.uint8), cv2.COLOR_BGR2HSV)
        sat.append((hsv[:, :, 1][y > 0.05] / 255.0).ravel()[::7])
        lab = cv2.cvtColor(rgb[:, :, ::-1].astype(np.float32), cv2.COLOR_BGR2Lab)
        chroma.append(np.hypot(lab[:, :, 1], lab[:, :, 2]).ravel()[::7])
        if os.path.exists(sem_path) and os.path.exists(depth_path):
            sem = cv2.imread(sem_path, cv2.IMREAD_UNCHANGED)
            depth = cv2.imread(depth_path, cv2.IMREAD_UNCHANGED).astype(np.float64) / 1000.0
            mask = np.isin(sem, FLOOR_CLASSES) & (depth > 0) & (depth < FLOOR_REACH_M) & (rgb < 1.0).all(axis=2)
            if mask.sum() > 100:
                lin = srgb_to_linear(rgb[mask])
                ratios = []
                for values in (lin, exposed_signal(lin)):
                    lum = values @ np.array([0.2126, 0.7152, 0.0722])
                    ratios.append(np.percentile(lum, 95) / max(np.percentile(lum, 10), 1e-5))
                floor.append(ratios)
    if not luma:
        raise SystemExit(f"image_stats.py: no rgb frames under {run}")
    y = np.concatenate(luma)
    s = np.concatenate(sat) if sat else np.zeros(1)
    out = {
        "frames": len(luma),
        "luma_p1": float(np.percentile(y, 1)),
        "luma_p50": float(np.percentile(y, 50)),
        "luma_p99": float(np.percentile(y, 99)),
        "rms_contrast": float(y.std()),
        "clipped_share": clipped / pixels,
        "saturation": float(s.mean()),
        "chroma": float(np.concatenate(chroma).mean()),
    }
    if floor:
        out["floor_ratio_display"] = float(np.median([f[0] for f in floor]))
        out["floor_ratio_scene"] = float(np.median([f[1] for f in floor]))
    return out


def main():
    runs = [a for a in sys.argv[1:] if not a.startswith("--")]
    if not runs:
        raise SystemExit(__doc__)
    results = {run: run_stats(run) for run in runs}
    if "--json" in sys.argv:
        print(json.dumps(results, indent=1))
        return
    keys = list(next(iter(results.values())).keys())
    print("| run | " + " | ".join(keys) + " |")
    print("|---" * (len(keys) + 1) + "|")
    for run, r in results.items():
        print(f"| {run} | " + " | ".join(f"{r.get(k, float('nan')):.4g}" for k in keys) + " |")


if __name__ == "__main__":
    main()
