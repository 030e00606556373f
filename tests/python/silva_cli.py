"""What the Python checks share: running the silva CLI, making a small dataset, damaging copies of one, and
finding label edges."""
import json
import os
import shutil
import subprocess
import sys

import numpy as np


def runner(binary):
    """A function silva(*args, expect=0) that runs `binary` and exits the test with its stderr on another code."""
    def silva(*args, expect=0):
        result = subprocess.run([binary, *args], capture_output=True, text=True)
        if result.returncode != expect:
            sys.exit(f"silva {' '.join(args)}: exit {result.returncode}, expected {expect}\n{result.stderr}")
        return result
    return silva


def small_dataset(silva, work, seed, yaws, random_count, types, *extra):
    """Empties `work` and generates <work>/dataset/<seed>/ at 96 x 64: two autopilot points at `yaws`, `random_count`
    random poses, output types `types` (a JSON list), then the further arguments `extra`."""
    shutil.rmtree(work, ignore_errors=True)
    silva("generate", "--seed", str(seed), "--out", os.path.join(work, "dataset"), "--quiet",
          "--set", "output.resolution=96x64", "--set", "captures.autopilot_points=2",
          "--set", f"captures.autopilot_yaws={yaws}", "--set", f"captures.random_count={random_count}",
          "--set", f"output.types={types}", *extra)


def damaged_copy(dataset, work, edit):
    """A fresh copy of `dataset` under `work` (same folder name; exports and card charts left out) after `edit(copy)`
    damaged it; returns the copy's path."""
    copy = os.path.join(work, os.path.basename(dataset))
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(dataset, copy, ignore=shutil.ignore_patterns("export", "card_*"))
    edit(copy)
    return copy


def edit_json(path, change):
    """Rewrites the JSON file `path` after `change(document)`."""
    with open(path) as f:
        document = json.load(f)
    change(document)
    with open(path, "w") as f:
        json.dump(document, f)


NODE_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "node")


def node_reader_missing():
    """True when node or the npm packages of tests/node are missing (scripts/install-deps.sh --test installs them)."""
    return shutil.which("node") is None or not os.path.isdir(os.path.join(NODE_DIR, "node_modules", "@mcap"))


def read_bag(path):
    """The MCAP file `path` as tests/node/read_bag.mjs reads it (an independent reader), parsed from its JSON."""
    result = subprocess.run(["node", os.path.join(NODE_DIR, "read_bag.mjs"), path], capture_output=True, text=True)
    assert result.returncode == 0, f"{path}: the independent reader failed\n{result.stderr}"
    return json.loads(result.stdout)


def label_edges(labels):
    """Pixels of a label image with a differently labelled pixel among their 8 neighbours."""
    padded = np.pad(labels, 1, mode="edge")
    h, w = labels.shape
    edges = np.zeros(labels.shape, bool)
    for dy in (0, 1, 2):
        for dx in (0, 1, 2):
            edges |= padded[dy:dy + h, dx:dx + w] != labels
    return edges
