#!/usr/bin/python3
"""Renders the lighting contact sheet (docs/lighting-sheet.png): one trail view from the ground and
one from the air for every time of day (day, dusk, night) under every weather (clear, overcast,
mist, rain in summer; snow in winter, which lying snow needs), then the day's ground view in autumn and winter; RGB only, in a grid
with the rows labelled. Needs numpy and OpenCV (cv2).

usage: scripts/lighting_sheet.py [--silva build/silva] [--scratch /tmp/silva-lighting] [--out docs/lighting-sheet.png]
"""
import argparse
import pathlib
import subprocess

import cv2
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
SEED = 1234567890
TIMES = ["day", "dusk", "night"]
WEATHERS = ["clear", "overcast", "mist", "rain", "snow"]
VIEWS = ["ground", "aerial"]
SEASON_ROWS = [("day", "ground", "autumn"), ("day", "ground", "winter")]
TILE_W, TILE_H = 384, 216
LABEL_W, HEADER_H = 120, 28


def render(silva, scratch, time, weather, view, season):
    """Renders one frame and returns it as a BGR image."""
    out = scratch / f"{time}-{weather}-{view}-{season}"
    subprocess.run([str(silva), "generate", "--config", str(ROOT / "configs/demo.toml"), "--seed", str(SEED),
                    "--quiet", "--overwrite", "--out", str(out),
                    "--set", f"lighting.time_of_day={time}", "--set", f"lighting.weather={weather}",
                    "--set", f"vegetation.season={'winter' if weather == 'snow' else season}",  # snow needs winter
                    "--set", f"captures.aerial={'true' if view == 'aerial' else 'false'}",
                    "--set", 'captures.sequences=["autopilot"]', "--set", "captures.autopilot_points=3",
                    "--set", "captures.autopilot_yaws=[0.0]", "--set", f"output.resolution={TILE_W}x{TILE_H}",
                    "--set", 'output.types=["rgb"]'], check=True)
    return cv2.imread(str(out / str(SEED) / "autopilot/rgb/000001.png"))


def text(img, s, x, y):
    cv2.putText(img, s, (x, y), cv2.FONT_HERSHEY_SIMPLEX, 0.5, (255, 255, 255), 1, cv2.LINE_AA)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--silva", default=str(ROOT / "build/silva"))
    ap.add_argument("--scratch", default="/tmp/silva-lighting")
    ap.add_argument("--out", default=str(ROOT / "docs/lighting-sheet.png"))
    args = ap.parse_args()
    scratch = pathlib.Path(args.scratch)
    rows = [(t, v, "summer") for t in TIMES for v in VIEWS] + SEASON_ROWS
    sheet = np.full((HEADER_H + len(rows) * TILE_H, LABEL_W + len(WEATHERS) * TILE_W, 3), 24, np.uint8)
    for c, weather in enumerate(WEATHERS):
        text(sheet, weather, LABEL_W + c * TILE_W + 8, 20)
    for r, (time, view, season) in enumerate(rows):
        y = HEADER_H + r * TILE_H
        text(sheet, time, 8, y + TILE_H // 2 - 14)
        text(sheet, view, 8, y + TILE_H // 2 + 6)
        text(sheet, season, 8, y + TILE_H // 2 + 26)
        for c, weather in enumerate(WEATHERS):
            sheet[y:y + TILE_H, LABEL_W + c * TILE_W:LABEL_W + (c + 1) * TILE_W] = render(
                pathlib.Path(args.silva), scratch, time, weather, view, season)
    cv2.imwrite(args.out, sheet)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
