#!/usr/bin/python3
"""Round trip of Silva's LiDAR files through numpy, read the way SemanticKITTI tools read them.

Usage: lidar_numpy_test.py SILVA_BINARY SCRATCH_DIR
Generates a small dataset with output type lidar, then reads every lidar/NNNNNN.bin as float32
(x, y, z, intensity) and lidar_labels/NNNNNN.label as uint32 (class = low 16 bits, instance = high
16 bits) and checks them against the sensor in the manifest and the instance tables. Skipped (exit
77, with a message) when numpy is missing.
"""
import json
import pathlib
import shutil
import subprocess
import sys

try:
    import numpy as np
except ImportError:
    print("lidar_numpy_test: SKIPPED, numpy is not importable (Debian: python3-numpy)")
    sys.exit(77)


def main() -> int:
    silva, scratch = sys.argv[1], pathlib.Path(sys.argv[2])
    shutil.rmtree(scratch, ignore_errors=True)
    scratch.mkdir(parents=True)
    subprocess.run([silva, "generate", "--seed", "21", "--out", str(scratch), "--quiet",
                    "--set", "output.resolution=64x48", "--set", "captures.autopilot_points=1",
                    "--set", "captures.random_count=1", "--set", "world.extent=128",
                    "--set", "world.render_distance=48", "--set", "trail.control_points=6",
                    "--set", "camera.far=40", "--set", 'output.types=["semantic","lidar"]'], check=True)
    run = scratch / "0000000021"
    manifest = json.loads((run / "manifest.json").read_text())
    sensor = manifest["sensors"]["lidar"]
    ontology = json.loads((run / "ontology.json").read_text())
    class_ids = {c["id"] for c in ontology["classes"]}
    scans = 0
    for seq, frames in manifest["frames"].items():
        for f in range(frames):
            scan = np.fromfile(run / seq / "lidar" / f"{f:06d}.bin", dtype="<f4").reshape(-1, 4)
            label = np.fromfile(run / seq / "lidar_labels" / f"{f:06d}.label", dtype="<u4")
            table = json.loads((run / seq / "lidar_labels" / f"{f:06d}.json").read_text())["instances"]
            assert scan.shape[0] == label.shape[0] > 0, (seq, f, scan.shape, label.shape)
            rng = np.linalg.norm(scan[:, :3], axis=1)
            assert rng.min() >= sensor["min_range"] and rng.max() <= sensor["max_range"], (rng.min(), rng.max())
            assert ((scan[:, 3] >= 0) & (scan[:, 3] <= 1)).all()
            elevation = np.degrees(np.arcsin(scan[:, 2] / rng))
            assert elevation.min() >= min(sensor["elevations_deg"]) - 0.5
            assert elevation.max() <= max(sensor["elevations_deg"]) + 0.5
            sem, inst = label & 0xFFFF, label >> 16
            assert set(np.unique(sem).tolist()) <= class_ids
            assert sorted(e["index"] for e in table) == list(range(1, len(table) + 1))
            for e in table:
                assert (sem[inst == e["index"]] == e["class_id"]).all(), e
            assert set(np.unique(inst).tolist()) <= {0} | {e["index"] for e in table}
            scans += 1
    print(f"lidar_numpy_test: {scans} scans read back through numpy")
    shutil.rmtree(scratch, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
