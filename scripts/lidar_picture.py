#!/usr/bin/python3
"""Draws one LiDAR sweep of a Silva dataset coloured by class: top-down, and as the sensor sees it.

Usage: scripts/lidar_picture.py RUN_DIR [--sequence random] [--frame 0] [--out docs/lidar-sweep.png]
RUN_DIR is <output.dir>/<seed>/ of a run with output type lidar. Needs numpy and matplotlib
(Debian: python3-numpy python3-matplotlib).
"""
import argparse
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir", type=pathlib.Path)
    parser.add_argument("--sequence", default="random")
    parser.add_argument("--frame", type=int, default=0)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("docs/lidar-sweep.png"))
    args = parser.parse_args()
    seq = args.run_dir / args.sequence
    name = f"{args.frame:06d}"
    try:
        scan = np.fromfile(seq / "lidar" / f"{name}.bin", dtype="<f4").reshape(-1, 4)
        label = np.fromfile(seq / "lidar_labels" / f"{name}.label", dtype="<u4")
        ontology = json.loads((args.run_dir / "ontology.json").read_text())["classes"]
        sensor = json.loads((args.run_dir / "manifest.json").read_text())["sensors"]["lidar"]
    except (OSError, KeyError, ValueError) as e:
        print(f"lidar_picture: {args.run_dir} has no readable LiDAR sweep {args.sequence}/{name}: {e}", file=sys.stderr)
        return 2
    colour = {c["id"]: np.array(c["color"]) / 255.0 for c in ontology}
    names = {c["id"]: c["name"] for c in ontology}
    cls = label & 0xFFFF
    rgb = np.array([colour.get(int(c), (1.0, 0.0, 1.0)) for c in cls])
    x, y, z = scan[:, 0], scan[:, 1], scan[:, 2]
    rng = np.linalg.norm(scan[:, :3], axis=1)
    azimuth = np.degrees(np.arctan2(y, x))
    elevation = np.degrees(np.arcsin(z / np.maximum(rng, 1e-6)))

    fig = plt.figure(figsize=(12, 9), dpi=110)
    top = fig.add_axes([0.05, 0.36, 0.56, 0.6])
    top.scatter(-y, x, c=rgb, s=0.6, linewidths=0)
    top.set_aspect("equal")
    top.set_xlabel("right of the sensor (m)")
    top.set_ylabel("ahead of the sensor (m)")
    top.set_title(f"{sensor['preset']}: {len(scan):,} returns, top-down")
    top.set_facecolor("#202020")
    legend = fig.add_axes([0.66, 0.36, 0.3, 0.6])
    legend.axis("off")
    for k, cid in enumerate(sorted(set(int(c) for c in cls))):
        share = float(np.mean(cls == cid))
        legend.add_patch(plt.Rectangle((0.0, 0.92 - 0.08 * k), 0.08, 0.05, color=colour[cid]))
        legend.text(0.12, 0.94 - 0.08 * k, f"{names[cid]}  {100 * share:.1f} %", va="center")
    legend.set_xlim(0, 1)
    legend.set_ylim(0, 1)
    side = fig.add_axes([0.05, 0.05, 0.9, 0.25])
    side.scatter(-azimuth, elevation, c=rgb, s=1.5, linewidths=0)
    side.set_xlim(-180, 180)
    side.set_xlabel("azimuth, clockwise from ahead (degrees)")
    side.set_ylabel("elevation (degrees)")
    side.set_title("from the sensor (one point per return)")
    side.set_facecolor("#202020")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out)
    print(f"lidar_picture: wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
