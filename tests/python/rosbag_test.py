#!/usr/bin/python3
"""`silva export --format rosbag2` read back by independent readers: the bag's MCAP container and CDR payloads
through npm's @mcap/core and @foxglove/rosmsg2-serialization (tests/node/read_bag.mjs, run with Debian's node),
compared with the dataset's own files through OpenCV and numpy.

Usage: rosbag_test.py SILVA WORKDIR TEST   (TEST: generate, bag, errors, damaged: damaged LiDAR files). `generate` makes the small dataset with
LiDAR the others read (a ctest fixture). Exits 77 (skipped) when node or the npm packages are missing.
"""
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import time

os.environ.setdefault("OPENCV_IO_ENABLE_OPENEXR", "1")
import cv2  # noqa: E402
import numpy as np  # noqa: E402
from silva_cli import damaged_copy, edit_json, node_reader_missing, runner, small_dataset  # noqa: E402
from silva_cli import read_bag as bag_reader  # noqa: E402
import yaml  # noqa: E402

SILVA, WORK, TEST = sys.argv[1], sys.argv[2], sys.argv[3]
SEED = 5151
DATASET = os.path.join(WORK, "dataset", f"{SEED:010d}")
PERIOD_NS = 100_000_000


silva = runner(SILVA)


def generate():
    small_dataset(silva, WORK, SEED, "[-30.0,30.0]", 2, '["rgb","semantic","instance","depth","depth_exr","lidar"]')


def read_bag(path):
    if node_reader_missing():
        print("node or tests/node/node_modules missing (scripts/install-deps.sh --test installs them)")
        sys.exit(77)
    return bag_reader(path)


def sha(data):
    return hashlib.sha256(np.ascontiguousarray(data).tobytes()).hexdigest()


def source(sequence, frame, folder, ext):
    return os.path.join(DATASET, sequence, folder, f"{frame:06d}.{ext}")


def matrix(t, q):
    """4x4 rigid transform from a translation and a unit quaternion (x, y, z, w)."""
    x, y, z, w = q
    assert abs(x * x + y * y + z * z + w * w - 1) < 1e-12, f"quaternion {q} is not unit"
    m = np.eye(4)
    m[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                 [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                 [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    m[:3, 3] = t
    return m


def check_scan(m, sequence, frame, lidar):
    scan = np.fromfile(source(sequence, frame, "lidar", "bin"), dtype="<f4").reshape(-1, 4)
    labels = np.fromfile(source(sequence, frame, "lidar_labels", "label"), dtype="<u4")
    assert m["points"] == len(scan) and m["point_step"] == 32, m["points"]
    assert m["fields"] == ["x", "y", "z", "intensity", "time", "ring", "label", "instance"], m["fields"]
    assert m["xyzi_sha256"] == sha(scan), f"{sequence} {frame}: points differ from the .bin"
    assert m["labels_sha256"] == sha(labels), f"{sequence} {frame}: labels differ from the .label"
    # Ring: the beam whose elevation is nearest the point's; firing time: never decreasing in firing order (the
    # points are in column order) and within one revolution.
    elevations = np.array(lidar["elevations_deg"])
    point_elevation = np.degrees(np.arctan2(scan[:, 2], np.hypot(scan[:, 0], scan[:, 1])))
    nearest = np.abs(point_elevation[:, None] - elevations[None, :]).argmin(axis=1)
    assert np.array_equal(np.array(m["rings"]), nearest), f"{sequence} {frame}: rings are not the nearest beams"
    times = np.array(m["times"])
    assert times.min() >= 0 and times.max() < 1 / lidar["rotation_hz"], (times.min(), times.max())
    assert np.all(np.diff(times) >= -1e-7), f"{sequence} {frame}: firing times go back"


def bag():
    out = os.path.join(WORK, "bags")
    silva("export", DATASET, "--format", "rosbag2", "--out", out, "--overwrite", "--quiet")
    manifest = json.load(open(os.path.join(DATASET, "manifest.json")))
    lidar = manifest["sensors"]["lidar"]
    lidar_to_camera = np.array(lidar["lidar_to_camera"])
    base_from_optical = np.array([[0, 0, 1, 0], [-1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 0, 1]], dtype=float)
    for sequence, count in manifest["frames"].items():
        folder = os.path.join(out, "rosbag2", sequence)
        meta = yaml.safe_load(open(os.path.join(folder, "metadata.yaml")))["rosbag2_bagfile_information"]
        assert meta["storage_identifier"] == "mcap" and meta["relative_file_paths"] == [f"{sequence}_0.mcap"], meta
        b = read_bag(os.path.join(folder, f"{sequence}_0.mcap"))
        assert b["profile"] == "ros2" and b["chunks"] >= 1, (b["profile"], b["chunks"])
        assert all(s["encoding"] == "ros2msg" for s in b["schemas"].values()), b["schemas"]
        assert all(c["encoding"] == "cdr" for c in b["channels"].values()), b["channels"]
        assert "durability: 1" in b["channels"]["/tf_static"]["qos"], "/tf_static is not transient local"
        expected = {"/tf_static": 1, "/tf": count, "/odom": count, "/camera/camera_info": count,
                    "/camera/image_raw": count, "/camera/depth/image_raw": count,
                    "/camera/semantic/image_raw": count, "/camera/instance/image_raw": count, "/lidar/points": count}
        counts = {}
        for m in b["messages"]:
            counts[m["topic"]] = counts.get(m["topic"], 0) + 1
        assert counts == expected, counts
        assert b["statistics"]["messages"] == meta["message_count"] == len(b["messages"]), (b["statistics"], meta)
        listed = {t["topic_metadata"]["name"]: t["message_count"] for t in meta["topics_with_message_count"]}
        assert listed == expected, listed
        times = [int(m["log_time"]) for m in b["messages"]]
        assert times == sorted(times), "log times go back"
        seen = {}
        for m in b["messages"]:
            topic, t = m["topic"], int(m["log_time"])
            frame = t // PERIOD_NS
            assert t == frame * PERIOD_NS and frame < count, (topic, t)
            if "stamp" in m:
                assert int(m["stamp"]) == t, (topic, m["stamp"], t)
            seen.setdefault(topic, []).append(frame)
            camera = json.load(open(source(sequence, frame, "camera", "json")))
            K = np.array(camera["K"])
            if topic == "/tf_static":
                mounts = {x["child"]: matrix(x["t"], x["q"]) for x in m["transforms"]}
                assert np.allclose(mounts["camera_optical_frame"], base_from_optical, atol=1e-12)
                assert np.allclose(mounts["lidar"], base_from_optical @ lidar_to_camera, atol=1e-12)
            elif topic == "/tf" or topic == "/odom":
                pose = m["transforms"][0] if topic == "/tf" else m
                assert (pose.get("parent", m.get("frame_id")), pose["child"]) == ("map", "base_link"), pose
                c2w = matrix(pose["t"], pose["q"]) @ base_from_optical
                assert np.allclose(c2w, np.array(camera["camera_to_world"]), atol=1e-9), (sequence, frame)
            elif topic == "/camera/camera_info":
                k = np.array(K, dtype=float)
                k[0, 2] -= 0.5
                k[1, 2] -= 0.5
                assert np.allclose(np.array(m["k"]).reshape(3, 3), k, atol=1e-12), m["k"]
                assert np.allclose(np.array(m["p"]).reshape(3, 4), np.hstack([k, np.zeros((3, 1))]), atol=1e-12)
                assert (m["width"], m["height"], m["distortion_model"]) == (camera["width"], camera["height"],
                                                                            "plumb_bob")
            elif topic == "/camera/image_raw":
                rgb = cv2.cvtColor(cv2.imread(source(sequence, frame, "rgb", "png")), cv2.COLOR_BGR2RGB)
                assert (m["encoding"], m["step"]) == ("rgb8", 3 * rgb.shape[1]) and m["sha256"] == sha(rgb), m
            elif topic == "/camera/depth/image_raw":
                depth = cv2.imread(source(sequence, frame, "depth_exr", "exr"), cv2.IMREAD_UNCHANGED)
                depth = np.where(depth == 0, np.float32(np.inf), depth).astype("<f4")
                assert (m["encoding"], m["step"]) == ("32FC1", 4 * depth.shape[1]) and m["sha256"] == sha(depth), m
            elif topic == "/camera/semantic/image_raw":
                semantic = cv2.imread(source(sequence, frame, "semantic", "png"), cv2.IMREAD_UNCHANGED)
                assert m["encoding"] == "mono8" and m["sha256"] == sha(semantic), m
            elif topic == "/camera/instance/image_raw":
                instance = cv2.imread(source(sequence, frame, "instance", "png"), cv2.IMREAD_UNCHANGED)
                assert m["encoding"] == "mono16" and m["sha256"] == sha(instance.astype("<u2")), m
            elif topic == "/lidar/points":
                assert m["frame_id"] == "lidar"
                check_scan(m, sequence, frame, lidar)
        assert all(v == list(range(count)) for k, v in seen.items() if k != "/tf_static"), seen


def errors():
    # A folder without a manifest, the dataset's own folders as the output, the dataset itself as the output.
    empty = os.path.join(WORK, "not-a-dataset")
    os.makedirs(empty, exist_ok=True)
    r = silva("export", empty, "--format", "rosbag2", expect=2)
    assert r.stderr.count("\n") == 1 and "not a Silva dataset" in r.stderr, r.stderr
    unfinished = os.path.join(WORK, "unfinished", f"{SEED:010d}")  # a run folder whose manifest was never written
    shutil.rmtree(os.path.dirname(unfinished), ignore_errors=True)
    shutil.copytree(DATASET, unfinished, ignore=shutil.ignore_patterns("manifest.json"))
    r = silva("export", unfinished, "--format", "rosbag2", expect=2)
    assert r.stderr.count("\n") == 1 and "not a finished Silva dataset" in r.stderr, r.stderr
    assert not os.path.exists(os.path.join(unfinished, "export")), "a refused export left files"
    r = silva("export", DATASET, "--format", "rosbag2", "--out", os.path.join(DATASET, "random"), expect=2)
    assert "inside the dataset" in r.stderr, r.stderr
    alias = os.path.join(WORK, "alias")  # alias/rosbag2 is the dataset, reached through a link
    shutil.rmtree(alias, ignore_errors=True)
    os.makedirs(alias)
    os.symlink(os.path.abspath(DATASET), os.path.join(alias, "rosbag2"))
    r = silva("export", DATASET, "--format", "rosbag2", "--out", alias, "--overwrite", expect=2)
    assert "would replace the dataset" in r.stderr, r.stderr
    assert os.path.isfile(os.path.join(DATASET, "manifest.json")), "the refused export touched the dataset"
    # Interrupted exports: whatever instant the kill lands at, rosbag2/ is absent or a complete bag.
    out = os.path.join(WORK, "killed")
    for delay in (0.02, 0.05, 0.1, 0.2):
        shutil.rmtree(out, ignore_errors=True)
        p = subprocess.Popen([SILVA, "export", DATASET, "--format", "rosbag2", "--out", out, "--quiet"])
        time.sleep(delay)
        p.send_signal(signal.SIGKILL)
        p.wait()
        final = os.path.join(out, "rosbag2")
        if os.path.exists(final):
            for sequence in os.listdir(final):
                mcap = open(os.path.join(final, sequence, f"{sequence}_0.mcap"), "rb").read()
                assert mcap[:8] == mcap[-8:] == b"\x89MCAP0\r\n", f"{sequence}: a half-written bag"
                assert os.path.isfile(os.path.join(final, sequence, "metadata.yaml"))


def damaged():
    """Damaged LiDAR files stop the readers of a LiDAR dataset (semantickitti and rosbag2 exports, the card) with exit
    2 and one line naming the file, where they passed them on or wrote nan."""
    work = os.path.join(WORK, "damaged")
    sequence = "random"
    labels = lambda d: os.path.join(d, sequence, "lidar_labels", "000000.label")  # noqa: E731

    def short_labels(d):
        data = open(labels(d), "rb").read()
        open(labels(d), "wb").write(data[:-4])

    def foreign_class(d):
        data = np.fromfile(labels(d), dtype="<u4")
        data[0] = (data[0] & 0xFFFF0000) | 250
        data.tofile(labels(d))

    def manifest_edit(change):
        return lambda d: edit_json(os.path.join(d, "manifest.json"), change)

    def write(name, text):
        return lambda d: open(os.path.join(d, sequence, name), "w").write(text)

    cases = [
        (short_labels, "labels for the", ("semantickitti", "rosbag2", "card")),
        (foreign_class, "class 250", ("semantickitti", "rosbag2", "card")),
        (write("poses.txt", ""), "0 poses", ("semantickitti",)),
        (write("calib.txt", "P0: 1 2 3\n"), "calib.txt", ("semantickitti",)),
        (manifest_edit(lambda j: j["sensors"]["lidar"].__setitem__("rotation_hz", 0)), "rotation_hz",
         ("semantickitti",)),
    ]
    for edit, expected, readers in cases:
        copy = damaged_copy(DATASET, work, edit)
        for reader in readers:
            args = ["card", copy] if reader == "card" else ["export", copy, "--format", reader]
            r = silva(*args, "--quiet", expect=2)
            assert expected in r.stderr and r.stderr.count("\n") == 1, (reader, r.stderr)
            assert not os.path.exists(os.path.join(copy, "export", reader)), f"{reader}: a refused export left files"


{"generate": generate, "bag": bag, "errors": errors, "damaged": damaged}[TEST]()
