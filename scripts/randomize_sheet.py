#!/usr/bin/python3
"""Renders the randomisation sheet (docs/randomize-sheet.png): eight autopilot frames of the demo world
with lighting.randomize on and auto-exposure, from the ground and from the air, each labelled with
its drawn weather, sun elevation and white balance (read from its camera file); then the forest floor
seen from 1.5 m, pitched down, in summer and in autumn (fresh leaf litter). Needs numpy and OpenCV (cv2).

usage: scripts/randomize_sheet.py [--silva build/silva] [--scratch /tmp/silva-randomize] [--out docs/randomize-sheet.png]
"""
import argparse
import json
import pathlib
import subprocess

import cv2
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
SEED = 1234567890
FRAMES = 8
COLS = 4
TILE_W, TILE_H = 320, 180
LABEL_H = 22


def generate(silva, out, sets):
    """Runs silva generate on the demo config with `sets` overrides."""
    args = [str(silva), "generate", "--config", str(ROOT / "configs/demo.toml"), "--seed", str(SEED), "--quiet",
            "--overwrite", "--out", str(out), "--set", f"output.resolution={TILE_W}x{TILE_H}",
            "--set", 'output.types=["rgb"]']
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True)
    return out / str(SEED)


def text(img, s, x, y):
    cv2.putText(img, s, (x, y), cv2.FONT_HERSHEY_SIMPLEX, 0.42, (255, 255, 255), 1, cv2.LINE_AA)


def tile(rgb_png, label):
    """One frame with its label strip above it."""
    t = np.full((LABEL_H + TILE_H, TILE_W, 3), 24, np.uint8)
    t[LABEL_H:] = cv2.imread(str(rgb_png))
    text(t, label, 6, 15)
    return t


def randomized_rows(silva, scratch, view):
    """Two rows of four randomised autopilot frames from `view` (ground or aerial)."""
    run = generate(silva, scratch / view, [
        "lighting.randomize.enabled=true", "lighting.exposure=auto", 'captures.sequences=["autopilot"]',
        f"captures.autopilot_points={FRAMES}", "captures.autopilot_yaws=[0.0]",
        f"captures.aerial={'true' if view == 'aerial' else 'false'}"])
    tiles = []
    for f in range(FRAMES):
        cam = json.loads((run / f"autopilot/camera/{f:06d}.json").read_text())
        lit = cam["lighting"]
        label = (f"{view} {lit['weather']}, sun {lit['sun_elevation_deg']:.0f} deg, {lit['white_balance_k']:.0f} K, "
                 f"EV {lit['ev100']:.1f}")
        tiles.append(tile(run / f"autopilot/rgb/{f:06d}.png", label))
    return [np.hstack(tiles[r * COLS:(r + 1) * COLS]) for r in range(FRAMES // COLS)], run


def floor_row(silva, scratch, run):
    """The floor beside the trail, pitched down 40 degrees, in summer and autumn, at two autopilot points."""
    poses = []
    for f in (2, 5):
        cam = json.loads((run / f"autopilot/camera/{f:06d}.json").read_text())
        m = cam["camera_to_world"]
        poses.append({"position": [m[0][3], m[1][3]], "yaw_deg": cam["yaw_deg"] + 60.0, "pitch_deg": -40.0,
                      "roll_deg": 0.0})
    pose_file = scratch / "floor-poses.json"
    pose_file.write_text(json.dumps({"poses": poses}))
    tiles = []
    for season in ("summer", "autumn"):
        out = generate(silva, scratch / f"floor-{season}", [
            f"vegetation.season={season}", 'captures.sequences=["custom"]', f"captures.poses_file={pose_file}"])
        for f in range(len(poses)):
            tiles.append(tile(out / f"custom/rgb/{f:06d}.png", f"day clear, {season} floor, view {f + 1}"))
    return np.hstack(tiles)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--silva", default=str(ROOT / "build/silva"))
    ap.add_argument("--scratch", default="/tmp/silva-randomize")
    ap.add_argument("--out", default=str(ROOT / "docs/randomize-sheet.png"))
    args = ap.parse_args()
    silva, scratch = pathlib.Path(args.silva), pathlib.Path(args.scratch)
    scratch.mkdir(parents=True, exist_ok=True)
    ground, run = randomized_rows(silva, scratch, "ground")
    aerial, _ = randomized_rows(silva, scratch, "aerial")
    sheet = np.vstack(ground + aerial + [floor_row(silva, scratch, run)])
    cv2.imwrite(args.out, sheet)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
