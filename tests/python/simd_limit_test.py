#!/usr/bin/python3
"""The same files on a CPU with fewer vector instructions: a small dataset of every image type and LiDAR, made on
this machine's best SIMD code, then again as an AVX2 machine without FMA in libm would make it
(SILVA_SIMD_LIMIT=avx2 caps Highway's targets and Embree's kernels; GLIBC_TUNABLES keeps glibc's maths off
its FMA variants) and as an SSE4 machine would. Every file but run*.json must be byte-identical, on SSE4 but
the LiDAR scans, their labels and the card that counts them: points may differ where Embree's SSE4.2 kernels
meet a foliage mask at a texel edge (docs/CONTRACT.md "LiDAR"), but only a few in a thousand may. A bad
SILVA_SIMD_LIMIT is exit 2.

Usage: simd_limit_test.py SILVA_BINARY SCRATCH_DIR
"""
import hashlib
import json
import os
import pathlib
import shutil
import struct
import subprocess
import sys

NO_FMA = "glibc.cpu.hwcaps=-AVX2,-FMA,-AVX512F"


def generate(silva, out, env):
    """Generates the test dataset into `out` with the environment additions `env`; returns its run folder."""
    subprocess.run([silva, "generate", "--seed", "33", "--out", str(out), "--quiet", "--threads", "2",
                    "--set", "output.resolution=160x96", "--set", "captures.autopilot_points=1",
                    "--set", "captures.random_count=1", "--set", "lidar.preset=hdl32e",
                    "--set", 'output.types=["rgb","semantic","instance","depth","normal","lidar"]'],
                   check=True, env={**os.environ, **env})
    return out / "0000000033"


def hashes(run):
    """sha256 of every file of `run` but run*.json, by relative path."""
    return {str(p.relative_to(run)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(run.rglob("*")) if p.is_file() and not p.name.startswith("run")}


def points(path):
    """The (x, y, z, intensity) points of a KITTI .bin scan."""
    data = path.read_bytes()
    return [struct.unpack_from("<4f", data, 16 * i) for i in range(len(data) // 16)]


def lidar_or_card(name):
    """True for the files that hold LiDAR points or count them: scans, their labels, the dataset card."""
    return "/lidar/" in name or "/lidar_labels/" in name or name in ("card.json", "CARD.md")


def main() -> int:
    silva, scratch = sys.argv[1], pathlib.Path(sys.argv[2])
    shutil.rmtree(scratch, ignore_errors=True)
    best = hashes(generate(silva, scratch / "best", {}))
    assert any(name.endswith(".bin") for name in best) and any(name.endswith(".png") for name in best), best
    avx2 = hashes(generate(silva, scratch / "avx2", {"SILVA_SIMD_LIMIT": "avx2", "GLIBC_TUNABLES": NO_FMA}))
    for run, limit in (("best", None), ("avx2", "avx2")):
        simd = json.loads((scratch / run / "0000000033" / "run.json").read_text())["simd"]
        assert simd["limit"] == limit and simd["targets"], simd
        assert limit is None or not any(t.startswith("AVX3") for t in simd["targets"]), simd
    differ = sorted(name for name in best if avx2.get(name) != best[name])
    assert not differ and avx2.keys() == best.keys(), f"AVX2 without FMA writes other files: {differ[:10]}"

    sse4_run = generate(silva, scratch / "sse4", {"SILVA_SIMD_LIMIT": "sse4", "GLIBC_TUNABLES": NO_FMA})
    sse4 = hashes(sse4_run)
    differ = sorted(name for name in best if sse4.get(name) != best[name] and not lidar_or_card(name))
    assert not differ and sse4.keys() == best.keys(), f"SSE4 writes other files: {differ[:10]}"
    total = moved = 0
    for name in (n for n in best if n.endswith(".bin")):
        mine, theirs = points(scratch / "best" / "0000000033" / name), set(points(sse4_run / name))
        total += len(mine)
        moved += sum(p not in theirs for p in mine)
    assert moved <= 0.005 * total, f"SSE4: {moved} of {total} LiDAR points differ"

    bad = subprocess.run([silva, "version"], capture_output=True, text=True,
                         env={**os.environ, "SILVA_SIMD_LIMIT": "avx9"})
    assert bad.returncode == 2 and "SILVA_SIMD_LIMIT=avx9" in bad.stderr, (bad.returncode, bad.stderr)
    capped = subprocess.run([silva, "version"], capture_output=True, text=True, check=True,
                            env={**os.environ, "SILVA_SIMD_LIMIT": "sse4"}).stdout
    assert "AVX" not in capped.split("SIMD targets:")[1], capped
    print(f"simd_limit_test: {len(best)} files equal on AVX2 without FMA; on SSE4 all but the LiDAR's, where "
          f"{moved} of {total} points differ")
    shutil.rmtree(scratch, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
