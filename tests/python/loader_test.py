#!/usr/bin/python3
"""python/silva_dataset read against independent reads of the same files; `silva card` against a numpy recount.

Usage: loader_test.py SILVA WORKDIR TEST (TEST: loader, card, damaged); WORKDIR holds the dataset export_test.py generated.
"""
import json
import math
import os
import subprocess
import sys

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(SOURCE, "python"))
from silva_dataset import DatasetError, SilvaDataset  # noqa: E402  (sets OPENCV_IO_ENABLE_OPENEXR before cv2 loads)
import cv2  # noqa: E402
import numpy as np  # noqa: E402
from silva_cli import damaged_copy, edit_json  # noqa: E402

SILVA, WORK, TEST = sys.argv[1], sys.argv[2], sys.argv[3]
DATASET = os.path.join(WORK, "dataset", "0000004242")


def check_loader():
    ds = SilvaDataset(DATASET)
    manifest = json.load(open(os.path.join(DATASET, "manifest.json")))
    assert len(ds) == sum(manifest["frames"].values()) > 0
    for i in range(len(ds)):
        s = ds[i]
        path = ds.path(i, "rgb", "png")
        assert np.array_equal(s["rgb"], cv2.imread(path)[..., ::-1]), "rgb is not R, G, B"
        h, w = s["semantic"].shape
        fx = w / (2 * math.tan(math.radians(manifest["config"]["camera"]["fov_deg"]) / 2))
        assert np.allclose(s["K"], [[fx, 0, w / 2], [0, fx, h / 2], [0, 0, 1]])
        assert np.allclose(s["camera"]["world_to_camera"] @ s["camera_to_world"], np.eye(4))
        mm = cv2.imread(ds.path(i, "depth", "png"), cv2.IMREAD_UNCHANGED).astype(np.float64)
        exact = (mm > 0) & (mm < 65535)
        assert s["depth"].dtype == np.float32 and np.all(np.abs(s["depth"][exact] * 1000 - mm[exact]) <= 0.5 + 1e-3)
        assert np.all(s["depth"][mm == 0] == 0)
        hit = np.any(s["normal"] != 0, axis=2)
        assert np.allclose(np.linalg.norm(s["normal"][hit], axis=1), 1.0, atol=0.02)
        table = json.load(open(ds.path(i, "instance", "json")))["instances"]
        assert [tuple(r) for r in s["instances"].tolist()] == [(e["index"], e["instance_id"], e["class_id"])
                                                               for e in table]
        assert s["instance"].dtype == np.uint16 and s["instance"].max() <= len(table)
    try:
        import torch  # noqa: F401
        from silva_dataset import SilvaTorchDataset
        t = SilvaTorchDataset(DATASET)[0]
        assert tuple(t["rgb"].shape) == (3, h, w)
        print("loader: torch Dataset checked")
    except ImportError:
        print("loader: SKIP the torch Dataset (torch is not importable)")
    print(f"loader: {len(ds)} frames read; rgb, K, pose, EXR depth, normals and instance tables agree")


def check_damaged():
    """The loader refuses, naming file and field, what the contract rules out: a manifest count the files do not
    back, a camera no one can project with, a label image of another size or with a class the ontology lacks."""
    work = os.path.join(WORK, "loader-damaged")

    camera = lambda d: os.path.join(d, "random", "camera", "000000.json")  # noqa: E731
    semantic = lambda d: os.path.join(d, "random", "semantic", "000000.png")  # noqa: E731
    random_index = [i for i, f in enumerate(SilvaDataset(DATASET).frames) if f == ("random", 0)][0]
    opening = [(lambda d: edit_json(os.path.join(d, "manifest.json"), lambda j: j["frames"].__setitem__("random", 9)),
                "is missing"),
               (lambda d: edit_json(os.path.join(d, "manifest.json"), lambda j: j["frames"].__setitem__("random", -1)),
                "whole number")]
    reading = [(lambda d: edit_json(camera(d), lambda j: j["K"][0].__setitem__(0, 0.0)), "'K'"),
               (lambda d: edit_json(camera(d), lambda j: j["camera_to_world"][0].__setitem__(0, 3.0)), "camera_to_world"),
               (lambda d: cv2.imwrite(semantic(d), np.full((64, 96), 250, np.uint8)), "class id"),
               (lambda d: cv2.imwrite(semantic(d), np.zeros((10, 10), np.uint8)), "not the run's")]
    for edit, expected in opening + reading:
        d = damaged_copy(DATASET, work, edit)
        try:
            SilvaDataset(d)[random_index]
            raise AssertionError(f"damaged dataset accepted: expected {expected!r}")
        except DatasetError as e:
            assert expected in str(e), str(e)
    print(f"damaged: {len(opening) + len(reading)} damaged datasets refused by the loader, naming file and field")


def check_card():
    during_run = open(os.path.join(DATASET, "card.json")).read()
    poses_during_run = open(os.path.join(DATASET, "card_poses.png"), "rb").read()
    r = subprocess.run([SILVA, "card", DATASET, "--quiet"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    # generate counts its frames in memory and maps its own world; card reads the PNGs and rebuilds the world.
    assert open(os.path.join(DATASET, "card.json")).read() == during_run, "generate's card differs from silva card's"
    assert open(os.path.join(DATASET, "card_poses.png"), "rb").read() == poses_during_run, "class maps differ"
    card = json.load(open(os.path.join(DATASET, "card.json")))
    ds = SilvaDataset(DATASET)
    pixels = np.zeros(256, dtype=np.int64)
    instances = np.zeros(256, dtype=np.int64)
    depth = np.zeros(33, dtype=np.int64)
    for i in range(len(ds)):
        semantic = cv2.imread(ds.path(i, "semantic", "png"), cv2.IMREAD_UNCHANGED)
        pixels += np.bincount(semantic.ravel(), minlength=256)
        instance = cv2.imread(ds.path(i, "instance", "png"), cv2.IMREAD_UNCHANGED)
        for e in json.load(open(ds.path(i, "instance", "json")))["instances"]:
            instances[e["class_id"]] += int((instance == e["index"]).any())
        mm = cv2.imread(ds.path(i, "depth", "png"), cv2.IMREAD_UNCHANGED).astype(np.int64)
        depth += np.bincount(np.minimum(mm[mm > 0] // 2000, 32), minlength=33)
    assert card["pixels"] == pixels.sum()
    for row in card["classes"]:
        assert row["pixels"] == pixels[row["id"]], row
        assert abs(row["fraction"] - pixels[row["id"]] / pixels.sum()) < 1e-12
        assert row["instances"] == instances[row["id"]], row
    assert [b["pixels"] for b in card["depth_histogram"]] == depth.tolist()
    bins = card["depth_histogram"]
    assert all(b["to_m"] == b["from_m"] + 2 for b in bins[:-1]), "depth bins are not 2 m wide"
    assert bins[-1]["to_m"] is None, f"the last depth bin holds everything beyond {bins[-1]['from_m']} m: {bins[-1]}"
    assert card["class_map"] is not None and card["class_map"]["width"] > 0
    rellis = card["published"]["rellis3d"]["classes"]
    assert abs(sum(r["published_share"] for r in rellis) - 1) < 1e-9
    ontology = json.load(open(os.path.join(DATASET, "ontology.json")))["classes"]
    for row in rellis:
        ids = {c["id"] for c in ontology if c["rellis"] == row["name"]}
        assert abs(row["silva_pixel_share"] - sum(pixels[i] for i in ids) / pixels.sum()) < 1e-12, row
    for chart in ("classes", "depth", "instance_sizes", "poses"):
        assert cv2.imread(os.path.join(DATASET, "card_" + chart + ".png")) is not None
    assert os.path.isfile(os.path.join(DATASET, "CARD.md"))
    print(f"card: class pixels, instance counts and the depth histogram equal a numpy recount of {len(ds)} frames")


{"loader": check_loader, "card": check_card, "damaged": check_damaged}[TEST]()
