#!/usr/bin/python3
"""Draws the README's rig picture from a stereo trajectory run with optical flow: left and right RGB, the
disparity, the forward flow in the Middlebury colour wheel, the left semantic colours, and the IMU readings.

Usage: scripts/rig_sheet.py RUN_DIR [--frame 20] [--out docs/rig-sheet.jpg]
RUN_DIR is <output.dir>/<seed>/ of a run with rig.preset = "stereo", the trajectory sequence, trajectory.flow
and output types rgb, semantic_color and depth.
With --presets, each RUN_DIR (one per rig preset, the same trajectory frame) gives a column: its RGB over its
semantic colours, labelled with the run's rig.preset.
Needs numpy and OpenCV (Debian: python3-numpy python3-opencv).
"""
import argparse
import json
import pathlib
import sys

import cv2
import numpy as np

PANEL_W = 480


def labelled(image, text):
    """`image` (BGR) scaled to PANEL_W wide with `text` in its top-left corner."""
    h = int(round(image.shape[0] * PANEL_W / image.shape[1]))
    out = cv2.resize(image, (PANEL_W, h), interpolation=cv2.INTER_AREA)
    cv2.rectangle(out, (0, 0), (12 + 9 * len(text), 24), (0, 0, 0), -1)
    cv2.putText(out, text, (6, 17), cv2.FONT_HERSHEY_SIMPLEX, 0.5, (255, 255, 255), 1, cv2.LINE_AA)
    return out


def flow_colour(png):
    """KITTI flow PNG (BGR as OpenCV reads it) to the Middlebury colour wheel: hue = direction, saturation =
    magnitude (scaled to the frame's 99th percentile), black where invalid."""
    valid = png[:, :, 0] > 0
    u = (png[:, :, 2].astype(np.float64) - 32768) / 64
    v = (png[:, :, 1].astype(np.float64) - 32768) / 64
    mag = np.hypot(u, v)
    scale = max(np.percentile(mag[valid], 99), 1e-6) if valid.any() else 1
    hsv = np.zeros(png.shape[:2] + (3,), np.uint8)
    hsv[..., 0] = ((np.degrees(np.arctan2(-v, -u)) + 180) / 2).astype(np.uint8)
    hsv[..., 1] = np.clip(mag / scale * 255, 0, 255).astype(np.uint8)
    hsv[..., 2] = np.where(valid, 255, 0)
    return cv2.cvtColor(hsv, cv2.COLOR_HSV2BGR)


def disparity_colour(png):
    """KITTI disparity PNG to a colour map (near warm), black where invalid."""
    d = png.astype(np.float64) / 256
    valid = png > 0
    top = max(np.percentile(d[valid], 99), 1e-6) if valid.any() else 1
    out = cv2.applyColorMap(np.clip(d / top * 255, 0, 255).astype(np.uint8), cv2.COLORMAP_INFERNO)
    out[~valid] = 0
    return out


def imu_plot(csv, height):
    """Gyroscope (top) and accelerometer (bottom) readings of imu.csv against time, one colour per axis."""
    data = np.loadtxt(csv, delimiter=",", comments="#")
    t = (data[:, 0] - data[0, 0]) * 1e-9
    canvas = np.full((height, PANEL_W, 3), 255, np.uint8)
    colours = [(40, 40, 220), (40, 160, 40), (200, 90, 20)]  # x red, y green, z blue (BGR)
    half = height // 2
    for k, (cols, name) in enumerate((((1, 2, 3), "gyro rad/s"), ((4, 5, 6), "accel m/s^2"))):
        y0, y1 = k * half + 22, (k + 1) * half - 8
        values = data[:, list(cols)]
        lo, hi = values.min(), values.max()
        span = max(hi - lo, 1e-9)
        for axis, colour in zip(range(3), colours):
            xs = 40 + (t / max(t[-1], 1e-9) * (PANEL_W - 50)).astype(np.int32)
            ys = (y1 - (values[:, axis] - lo) / span * (y1 - y0)).astype(np.int32)
            cv2.polylines(canvas, [np.stack([xs, ys], 1)], False, colour, 1, cv2.LINE_AA)
        cv2.putText(canvas, f"{name}  [{lo:.2f}, {hi:.2f}]  x y z", (42, y0 - 6), cv2.FONT_HERSHEY_SIMPLEX, 0.45,
                    (0, 0, 0), 1, cv2.LINE_AA)
    cv2.putText(canvas, f"IMU, {len(t)} readings over {t[-1]:.1f} s", (42, height - 2), cv2.FONT_HERSHEY_SIMPLEX, 0.4,
                (80, 80, 80), 1, cv2.LINE_AA)
    return canvas


def presets_sheet(run_dirs, frame):
    """One column per run: its trajectory frame's RGB over its semantic colours, labelled with the rig preset."""
    columns = []
    for run_dir in run_dirs:
        manifest = json.loads((run_dir / "manifest.json").read_text())
        preset = manifest["config"]["rig"]["preset"]
        name = f"{frame:06d}.png"
        rgb = cv2.imread(str(run_dir / "trajectory" / "rgb" / name))
        semantic = cv2.imread(str(run_dir / "trajectory" / "semantic_color" / name))
        if rgb is None or semantic is None:
            raise SystemExit(f"rig_sheet: {run_dir} lacks trajectory rgb/semantic_color frame {name}")
        columns.append(np.vstack([labelled(rgb, f"rig.preset = {preset}"),
                                  labelled(semantic, "semantic")]))
    return np.hstack(columns)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir", type=pathlib.Path, nargs="+")
    parser.add_argument("--frame", type=int, default=20)
    parser.add_argument("--presets", action="store_true")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("docs/rig-sheet.jpg"))
    args = parser.parse_args()
    if args.presets:
        cv2.imwrite(str(args.out), presets_sheet(args.run_dir, args.frame), [cv2.IMWRITE_JPEG_QUALITY, 88])
        print(f"wrote {args.out}")
        return 0
    seq = args.run_dir[0] / "trajectory"
    name = f"{args.frame:06d}.png"
    images = {}
    for folder in ("rgb", "rgb_right", "semantic_color", "disparity", "flow_forward"):
        images[folder] = cv2.imread(str(seq / folder / name), cv2.IMREAD_UNCHANGED)
        if images[folder] is None:
            print(f"rig_sheet: {seq / folder / name} is missing; run a stereo trajectory with trajectory.flow and "
                  "output types rgb, semantic_color, depth", file=sys.stderr)
            return 2
    top = np.hstack([labelled(images["rgb"], "left"), labelled(images["rgb_right"], "right"),
                     labelled(disparity_colour(images["disparity"]), "disparity (KITTI PNG)")])
    bottom_row = [labelled(flow_colour(images["flow_forward"]), "optical flow to the next frame"),
                  labelled(images["semantic_color"], "semantic (left)")]
    bottom = np.hstack(bottom_row + [imu_plot(seq / "imu.csv", bottom_row[0].shape[0])])
    cv2.imwrite(str(args.out), np.vstack([top, bottom]), [cv2.IMWRITE_JPEG_QUALITY, 88, cv2.IMWRITE_PNG_COMPRESSION, 9])
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
