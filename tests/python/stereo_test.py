#!/usr/bin/python3
"""The stereo rig from the CLI, read back with numpy and OpenCV: the left camera's files equal a mono run's byte for
byte, the right camera sits rig.baseline_m along the left's x, disparity/ holds fx · B / depth (KITTI: × 256,
0 = invalid) for every valid pixel, the right image seen through the disparity gives the left's labels, the EuRoC
export carries cam1 with the baseline in T_BS, KITTI-odometry ground truth matches the camera files, and --resume
writes a deleted right-camera file back with the same bytes.

Usage: stereo_test.py SILVA WORKDIR
"""
import filecmp
import hashlib
import json
import os
import shutil
import sys

import cv2
import numpy as np
import yaml
from silva_cli import label_edges, node_reader_missing, read_bag, runner

SILVA, WORK = sys.argv[1], sys.argv[2]
SEED = 5150
BASELINE = 0.12
VERIFY_FAILED = 4  # silva verify's exit code for labels that disagree with the ray caster (CONTRACT.md "Errors")
TYPES = '["rgb","semantic","depth_exr"]'
silva = runner(SILVA)


def generate(name, *extra):
    out = os.path.join(WORK, name)
    silva("generate", "--seed", str(SEED), "--out", out, "--quiet", "--set", "output.resolution=320x240",
          "--set", 'captures.sequences=["trajectory"]', "--set", "trajectory.duration_s=0.4",
          "--set", f"output.types={TYPES}", *extra)
    return os.path.join(out, f"{SEED:010d}")


def check_left_equals_mono(mono, stereo):
    for folder in ("rgb", "semantic", "depth_exr", "camera"):
        names = sorted(os.listdir(os.path.join(mono, "trajectory", folder)))
        assert names and names == sorted(os.listdir(os.path.join(stereo, "trajectory", folder))), folder
        for n in names:
            a, b = (os.path.join(d, "trajectory", folder, n) for d in (mono, stereo))
            if folder == "camera":  # the stereo camera file adds its "stereo" record, nothing else
                ja, jb = json.load(open(a)), json.load(open(b))
                assert jb.pop("stereo") == {"camera": "left", "baseline_m": BASELINE}, b
                assert ja == jb, (a, b)
            else:
                assert filecmp.cmp(a, b, shallow=False), f"{b} differs from the mono camera's {a}"


def check_frame(seq, name):
    left = json.load(open(os.path.join(seq, "camera", name + ".json")))
    right = json.load(open(os.path.join(seq, "camera_right", name + ".json")))
    assert right["stereo"] == {"camera": "right", "baseline_m": BASELINE}, right["stereo"]
    assert right["K"] == left["K"] and right["frame"] == left["frame"]
    lp, rp = np.array(left["camera_to_world"]), np.array(right["camera_to_world"])
    assert np.allclose(rp[:3, :3], lp[:3, :3], atol=1e-12)
    assert np.allclose(rp[:3, 3], lp[:3, 3] + BASELINE * lp[:3, 0], atol=1e-9), (rp[:3, 3], lp[:3, 3])
    fx = left["K"][0][0]

    depth = cv2.imread(os.path.join(seq, "depth_exr", name + ".exr"), cv2.IMREAD_UNCHANGED).astype(np.float64)
    right_depth = cv2.imread(os.path.join(seq, "depth_exr_right", name + ".exr"), cv2.IMREAD_UNCHANGED)
    disp = cv2.imread(os.path.join(seq, "disparity", name + ".png"), cv2.IMREAD_UNCHANGED)
    assert disp.dtype == np.uint16 and disp.shape == depth.shape, (disp.dtype, disp.shape)
    truth = np.where(depth > 0, fx * BASELINE / np.maximum(depth, 1e-9), 0)
    valid = disp > 0
    assert valid.mean() > 0.5, valid.mean()
    err = np.abs(disp[valid] / 256.0 - truth[valid])
    assert err.max() <= 0.5 / 256 + 1e-4, err.max()
    representable = (depth > 0) & (truth * 256 >= 1) & (truth * 256 <= 65535)
    assert np.array_equal(valid, representable), "disparity invalid where it fits, or valid where it cannot"

    left_sem = cv2.imread(os.path.join(seq, "semantic", name + ".png"), cv2.IMREAD_UNCHANGED)
    right_sem = cv2.imread(os.path.join(seq, "semantic_right", name + ".png"), cv2.IMREAD_UNCHANGED)
    h, w = left_sem.shape
    v, u = np.nonzero(valid)
    ur = np.floor(u + 0.5 - disp[v, u] / 256.0).astype(int)  # the right camera sees pixel centre u + 0.5 - d
    inside = (ur >= 0) & (ur < w)
    v, u, ur = v[inside], u[inside], ur[inside]
    seen = np.abs(right_depth[v, ur] - depth[v, u]) <= 0.02 * depth[v, u]  # not occluded in the right camera
    same = right_sem[v[seen], ur[seen]] == left_sem[v[seen], u[seen]]
    # Away from label edges (neither pixel has a differently labelled neighbour) the label must carry over; at an
    # edge a disparity landing between pixel centres may round to the other side, and a grass blade stands within
    # the 2 % depth tolerance of the ground behind it.
    inner = ~label_edges(left_sem)[v[seen], u[seen]] & ~label_edges(right_sem)[v[seen], ur[seen]]
    agree = same.mean()
    assert seen.mean() > 0.6 and same[inner].mean() >= 0.995 and agree >= 0.98, \
        (seen.mean(), same[inner].mean(), agree)
    # The trail is smooth and never occluded by a 12 cm shift: there the right camera sees the same surface point.
    ontology = json.load(open(os.path.join(seq, "..", "ontology.json")))["classes"]
    trail = left_sem[v, u] == next(c["id"] for c in ontology if c["role"] == "trail")
    assert trail.sum() > 500 and seen[trail].mean() >= 0.98, (trail.sum(), seen[trail].mean())
    return agree, same[inner].mean()


def check_euroc(stereo):
    out = os.path.join(WORK, "export")
    silva("export", stereo, "--format", "euroc", "--out", out)
    mav = os.path.join(out, "euroc", "mav0")
    cam0 = open(os.path.join(mav, "cam0", "data.csv")).read()
    assert cam0 == open(os.path.join(mav, "cam1", "data.csv")).read(), "cam0 and cam1 stamps differ"
    t_bs = np.array(yaml.safe_load(open(os.path.join(mav, "cam1", "sensor.yaml")))["T_BS"]["data"]).reshape(4, 4)
    assert np.allclose(t_bs, [[1, 0, 0, BASELINE], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]), t_bs
    first = cam0.splitlines()[1].split(",")[1]
    a = cv2.imread(os.path.join(mav, "cam1", "data", first))
    assert a is not None and a.shape == (240, 320, 3)
    assert filecmp.cmp(os.path.join(mav, "cam1", "data", first), os.path.join(stereo, "trajectory", "rgb_right",
                                                                              "000000.png"), shallow=False)


def quaternion_matrix(x, y, z, w):
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def check_tartanair(stereo):
    """The tartanair export read back as TartanAir's tools read it: np.load, cv2.imread, NED poses."""
    out = os.path.join(WORK, "tartanair-export")
    silva("export", stereo, "--format", "tartanair", "--out", out)
    seq, src = os.path.join(out, "tartanair", "trajectory"), os.path.join(stereo, "trajectory")
    for side, suffix in (("left", ""), ("right", "_right")):
        poses = np.loadtxt(os.path.join(seq, f"pose_{side}.txt"))
        assert poses.shape == (4, 7), poses.shape
        for i in range(4):
            n = f"{i:06d}"
            assert filecmp.cmp(os.path.join(seq, f"image_{side}", f"{n}_{side}.png"),
                               os.path.join(src, "rgb" + suffix, n + ".png"), shallow=False)
            depth = np.load(os.path.join(seq, f"depth_{side}", f"{n}_{side}_depth.npy"))
            exr = cv2.imread(os.path.join(src, "depth_exr" + suffix, n + ".exr"), cv2.IMREAD_UNCHANGED)
            assert depth.dtype == np.float32 and np.array_equal(depth, np.where(exr > 0, exr, 10000)), side
            seg = np.load(os.path.join(seq, f"seg_{side}", f"{n}_{side}_seg.npy"))
            sem = cv2.imread(os.path.join(src, "semantic" + suffix, n + ".png"), cv2.IMREAD_UNCHANGED)
            assert seg.dtype == np.uint8 and np.array_equal(seg, sem), side
            pose = np.array(json.load(open(os.path.join(src, "camera" + suffix, n + ".json")))["camera_to_world"])
            ned = np.diag([1.0, -1.0, -1.0])
            assert np.allclose(poses[i, :3], ned @ pose[:3, 3], atol=1e-6)
            body = quaternion_matrix(*poses[i, 3:])  # TartanAir's body: x forward, y right, z down
            assert np.allclose(body[:, 0], ned @ pose[:3, 2], atol=1e-6) and np.allclose(body[:, 1], ned @ pose[:3, 0],
                                                                                         atol=1e-6)
    flow = np.load(os.path.join(seq, "flow", "000000_000001_flow.npy"))
    mask = np.load(os.path.join(seq, "flow", "000000_000001_mask.npy"))
    flo = np.fromfile(os.path.join(src, "flow_forward_flo", "000000.flo"), dtype="<f4")[3:].reshape(240, 320, 2)
    assert flow.shape == (240, 320, 2) and np.array_equal(flow, flo) and mask.shape == (240, 320)
    assert not os.path.exists(os.path.join(seq, "flow", "000003_000004_flow.npy")), "flow past the last frame"


def check_kitti_groundtruth(seq):
    rows = np.loadtxt(os.path.join(seq, "groundtruth_kitti.txt")).reshape(-1, 3, 4)
    first = np.array(json.load(open(os.path.join(seq, "camera", "000000.json")))["camera_to_world"])
    assert np.allclose(rows[0], np.eye(4)[:3], atol=1e-9)
    for i, row in enumerate(rows):
        pose = np.array(json.load(open(os.path.join(seq, "camera", f"{i:06d}.json")))["camera_to_world"])
        assert np.allclose(row, (np.linalg.inv(first) @ pose)[:3], atol=1e-6), i


def check_resume(stereo):
    lost = os.path.join(stereo, "trajectory", "rgb_right", "000002.png")
    kept = lost + ".kept"
    shutil.copy(lost, kept)
    os.remove(lost)
    silva("generate", "--resume", "--out", os.path.dirname(stereo), "--seed", str(SEED), "--quiet")
    assert filecmp.cmp(lost, kept, shallow=False), "the re-captured right image differs"
    os.remove(kept)


def check_verify(stereo):
    """silva verify casts both cameras of each frame; a right semantic image with two classes swapped fails it."""
    silva("verify", stereo, "--quiet")
    cameras = [f["camera"] for f in json.load(open(os.path.join(stereo, "verify.json")))["frames"]]
    assert cameras == ["left", "right"] * 4, cameras
    path = os.path.join(stereo, "trajectory", "semantic_right", "000001.png")
    sem = cv2.imread(path, cv2.IMREAD_UNCHANGED)
    swapped = sem.copy()
    ground, canopy = 1, 4  # the default ontology's ground and canopy classes
    swapped[sem == ground], swapped[sem == canopy] = canopy, ground
    cv2.imwrite(path, swapped)
    silva("verify", stereo, "--quiet", expect=VERIFY_FAILED)


def check_rosbag(stereo):
    """The ROS 2 bag of a stereo run, read by the independent MCAP reader: the right camera's info (P's Tx =
    -fx · B) and images beside the left's, its mount in /tf_static the baseline along the left's x."""
    if node_reader_missing():
        print("stereo: node or tests/node/node_modules missing, the ROS 2 bag check is skipped")
        return
    out = os.path.join(WORK, "bag")
    silva("export", stereo, "--format", "rosbag2", "--out", out, "--quiet")
    b = read_bag(os.path.join(out, "rosbag2", "trajectory", "trajectory_0.mcap"))
    seq = os.path.join(stereo, "trajectory")
    frames = sorted(os.listdir(os.path.join(seq, "rgb_right")))
    right = [m for m in b["messages"] if m["topic"] == "/camera/right/image_raw"]
    info = [m for m in b["messages"] if m["topic"] == "/camera/right/camera_info"]
    assert len(right) == len(info) == len(frames), (len(right), len(info), len(frames))
    for m, name in zip(right, frames):
        rgb = cv2.cvtColor(cv2.imread(os.path.join(seq, "rgb_right", name)), cv2.COLOR_BGR2RGB)
        assert m["frame_id"] == "camera_right_optical_frame" and m["sha256"] == hashlib.sha256(rgb.tobytes()).hexdigest()
    fx = json.load(open(os.path.join(seq, "camera_right", frames[0][:-4] + ".json")))["K"][0][0]
    assert np.isclose(np.array(info[0]["p"]).reshape(3, 4)[0, 3], -fx * BASELINE, atol=1e-9), info[0]["p"]
    static = [m for m in b["messages"] if m["topic"] == "/tf_static"][0]
    mount = {t["child"]: t for t in static["transforms"]}["camera_right_optical_frame"]
    # base_link is x forward, y left: the right camera's centre sits B to the right, at y = -B.
    assert np.allclose(mount["t"], [0, -BASELINE, 0], atol=1e-12), mount


def check_ground_robot():
    """The ground_robot preset: a stereo pair 0.55 m above the terrain (the walk's bob off) with a LiDAR sweep per
    frame, the rig named in the manifest and the card."""
    run = generate("robot", "--set", "rig.preset=ground_robot", "--set", "trajectory.bob_m=0")
    seq = os.path.join(run, "trajectory")
    for folder in ("rgb", "rgb_right", "disparity", "lidar", "camera_right"):
        assert len(os.listdir(os.path.join(seq, folder))) >= 4, folder
    manifest = json.load(open(os.path.join(run, "manifest.json")))
    assert "lidar" in manifest["config"]["output"]["types"] and "lidar" in manifest["sensors"]
    assert [c["name"] for c in manifest["sensors"]["cameras"]] == ["left", "right"]
    depth = cv2.imread(os.path.join(seq, "depth_exr", "000000.exr"), cv2.IMREAD_UNCHANGED)
    camera = json.load(open(os.path.join(seq, "camera", "000000.json")))
    # The bottom row's centre ray meets the ground ahead: its depth and the ray's fall give the camera's height.
    k = np.array(camera["K"])
    h, w = depth.shape[:2]
    z = float(depth[h - 1, w // 2] if depth.ndim == 2 else depth[h - 1, w // 2, 0])
    drop = z * ((h - 1 + 0.5) - k[1][2]) / k[1][1]
    assert 0.45 < drop < 0.65, f"ground_robot camera {drop:.3f} m above the ground ahead, expected about 0.55"
    card = open(os.path.join(run, "CARD.md")).read()
    assert "Rig: `ground_robot`, a rectified stereo pair" in card and "0.55 m above the ground, with a LiDAR." in card


def main():
    shutil.rmtree(WORK, ignore_errors=True)
    check_ground_robot()
    mono = generate("mono")
    stereo = generate("stereo", "--set", "rig.preset=stereo", "--set", f"rig.baseline_m={BASELINE}",
                      "--set", "trajectory.flow=true")
    check_left_equals_mono(mono, stereo)
    cameras = json.load(open(os.path.join(stereo, "manifest.json")))["sensors"]["cameras"]
    assert [c["name"] for c in cameras] == ["left", "right"], cameras
    assert np.allclose(cameras[1]["camera_to_rig"], [[1, 0, 0, BASELINE], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    rig = json.load(open(os.path.join(stereo, "card.json")))["rig"]
    assert rig == {"preset": "stereo", "cameras": 2, "height_m": None, "pitch_deg": 0.0, "lidar": False,
                   "baseline_m": BASELINE, "imu_hz": 200.0, "imu_noise": "adis16448"}, rig
    assert "a rectified stereo pair, baseline 0.12 m" in open(os.path.join(stereo, "CARD.md")).read()
    seq = os.path.join(stereo, "trajectory")
    names = [n[:-5] for n in sorted(os.listdir(os.path.join(seq, "camera")))]
    assert len(names) == 4, names
    agreement = [check_frame(seq, n) for n in names]
    check_euroc(stereo)
    check_tartanair(stereo)
    check_kitti_groundtruth(seq)
    check_rosbag(stereo)
    check_resume(stereo)
    check_verify(stereo)
    print(f"stereo ok: {len(names)} frames, label agreement through the disparity {min(a for a, _ in agreement):.4f}, "
          f"{min(i for _, i in agreement):.4f} away from label edges")


if __name__ == "__main__":
    main()
