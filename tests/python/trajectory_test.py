#!/usr/bin/python3
"""The `trajectory` sequence from the CLI, read back with numpy and OpenCV: one frame per 1 / camera_hz along the
trail, camera files agreeing with groundtruth.txt (TUM), imu.csv (EuRoC columns) at imu_hz whose readings,
integrated here on their own from the first pose, follow the ground truth, imu.yaml (Kalibr keys), optical flow
(KITTI PNG, Middlebury .flo, masks) that carries each frame's labels onto the next, and the same bytes on one
thread and on two.

Usage: trajectory_test.py SILVA WORKDIR
"""
import filecmp
import json
import os
import shutil
import subprocess
import sys

import cv2
import numpy as np
import yaml
from silva_cli import label_edges, runner

SILVA, WORK = sys.argv[1], sys.argv[2]
SEED = 4242
silva = runner(SILVA)


def generate(name, threads, noise):
    out = os.path.join(WORK, name)
    silva("generate", "--seed", str(SEED), "--out", out, "--quiet", "--threads", str(threads),
          "--set", "output.resolution=320x240", "--set", 'captures.sequences=["trajectory"]',
          "--set", "trajectory.duration_s=2", "--set", f"trajectory.imu_noise={noise}", "--set", "trajectory.flow=true",
          "--set", 'output.types=["rgb","semantic","depth"]')
    return os.path.join(out, f"{SEED:010d}")


def quaternion_matrix(x, y, z, w):
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def skew_exp(w, dt):
    """Rotation matrix of the rotation vector w * dt (Rodrigues)."""
    v = np.asarray(w) * dt
    angle = np.linalg.norm(v)
    if angle == 0:
        return np.eye(3)
    k = v / angle
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


def main():
    shutil.rmtree(WORK, ignore_errors=True)
    one = generate("one", 1, "none")
    two = generate("two", 2, "none")
    seq = os.path.join(two, "trajectory")
    manifest = json.load(open(os.path.join(two, "manifest.json")))
    assert manifest["frames"] == {"trajectory": 20}, manifest["frames"]

    # Same bytes on one and two threads (run.json holds timings).
    for root, _, files in os.walk(one):
        for f in files:
            if f == "run.json":
                continue
            a = os.path.join(root, f)
            b = os.path.join(two, os.path.relpath(a, one))
            assert filecmp.cmp(a, b, shallow=False), f"{os.path.relpath(a, one)} differs between 1 and 2 threads"

    # Ground truth: one TUM line per frame, equal to the camera files.
    gt = np.loadtxt(os.path.join(seq, "groundtruth.txt"), comments="#")
    assert gt.shape == (20, 8), gt.shape
    assert np.allclose(gt[:, 0], np.arange(20) * 0.1, atol=1e-9)
    for i, row in enumerate(gt):
        cam = json.load(open(os.path.join(seq, "camera", f"{i:06d}.json")))
        c2w = np.array(cam["camera_to_world"])
        assert np.allclose(c2w[:3, 3], row[1:4], atol=1e-8), (i, c2w[:3, 3], row[1:4])
        assert np.allclose(c2w[:3, :3], quaternion_matrix(*row[4:8]), atol=1e-9), i
        assert cam["sequence"] == "trajectory" and cam["frame"] == i
    steps = np.linalg.norm(np.diff(gt[:, 1:3], axis=0), axis=1)
    assert abs(steps.mean() / 0.1 - 1.4) < 0.1, f"walks at {steps.mean() / 0.1} m/s, configured 1.4"

    # IMU: EuRoC header and columns, 200 Hz, and readings that integrate back to the ground truth.
    with open(os.path.join(seq, "imu.csv")) as f:
        assert f.readline().startswith("#timestamp [ns],w_RS_S_x [rad s^-1]")
    imu = np.loadtxt(os.path.join(seq, "imu.csv"), delimiter=",", comments="#")
    assert imu.shape == (400, 7), imu.shape
    assert np.array_equal(imu[:, 0], np.arange(400) * 5_000_000)
    # Integrated from rest at the first pose, the positions differ from the truth by v0 * t (the initial
    # velocity, which an IMU cannot know): fit it by least squares, then what is left is the readings' error.
    dt = 0.005
    R = quaternion_matrix(*gt[0, 4:8])
    p, v = gt[0, 1:4].copy(), np.zeros(3)
    g = np.array([0, 0, -9.81])
    integrated = [p.copy()]
    for k in range(399):
        w0, w1 = imu[k, 1:4], imu[k + 1, 1:4]
        a0 = R @ imu[k, 4:7] + g
        R1 = R @ skew_exp(0.5 * (w0 + w1), dt)
        a1 = R1 @ imu[k + 1, 4:7] + g
        p = p + v * dt + (2 * a0 + a1) / 6 * dt * dt
        v = v + 0.5 * (a0 + a1) * dt
        R = R1
        if (k + 1) % 20 == 0:
            integrated.append(p.copy())
    offsets = gt[:20, 1:4] - np.array(integrated)
    times = gt[:20, 0:1]
    v0 = np.linalg.lstsq(times, offsets, rcond=None)[0][0]
    residual = np.linalg.norm(offsets - times * v0, axis=1)
    assert residual.max() < 0.01, f"IMU integration strays {residual.max():.4f} m from the ground truth"
    errors = residual

    kalibr = yaml.safe_load(open(os.path.join(seq, "imu.yaml")))
    assert kalibr["update_rate"] == 200 and kalibr["rostopic"] == "/imu0", kalibr
    assert kalibr["gyroscope_noise_density"] == 0 and kalibr["accelerometer_random_walk"] == 0, kalibr

    # Optical flow: KITTI's valid bit is the mask's 0, and following the .flo vectors from a valid pixel lands on a
    # pixel of the other frame with the same semantic label: >= 99.5 % of the valid pixels away from label edges
    # (neither the pixel nor where it lands has a differently labelled neighbour; at an edge, a vector landing
    # between pixel centres may round to the other side), and >= 98 % of all of them.
    for direction, step, frames in (("forward", 1, range(19)), ("backward", -1, range(1, 20))):
        agree = total = inner_agree = inner_total = 0
        for t in frames:
            kitti = cv2.imread(os.path.join(seq, f"flow_{direction}", f"{t:06d}.png"), cv2.IMREAD_UNCHANGED)
            mask = cv2.imread(os.path.join(seq, f"flow_{direction}_mask", f"{t:06d}.png"), cv2.IMREAD_UNCHANGED)
            raw = open(os.path.join(seq, f"flow_{direction}_flo", f"{t:06d}.flo"), "rb").read()
            assert raw[:4] == b"PIEH" and tuple(np.frombuffer(raw[4:12], np.int32)) == (320, 240)
            flo = np.frombuffer(raw[12:], np.float32).reshape(240, 320, 2)
            valid = mask == 0
            assert np.array_equal(kitti[:, :, 0] == 1, valid), f"{direction} {t}: KITTI valid bit differs from the mask"
            u = (kitti[:, :, 2].astype(np.float64) - 32768) / 64
            assert np.all(np.abs(u[valid] - flo[:, :, 0][valid]) <= 1 / 128 + 1e-6), f"{direction} {t}: KITTI u"
            here = cv2.imread(os.path.join(seq, "semantic", f"{t:06d}.png"), cv2.IMREAD_UNCHANGED)
            there = cv2.imread(os.path.join(seq, "semantic", f"{t + step:06d}.png"), cv2.IMREAD_UNCHANGED)
            ys, xs = np.nonzero(valid)
            x1 = np.floor(xs + 0.5 + flo[ys, xs, 0]).astype(int)
            y1 = np.floor(ys + 0.5 + flo[ys, xs, 1]).astype(int)
            same = here[ys, xs] == there[y1, x1]
            inner = ~label_edges(here)[ys, xs] & ~label_edges(there)[y1, x1]
            agree += int(np.sum(same))
            total += len(ys)
            inner_agree += int(np.sum(same & inner))
            inner_total += int(np.sum(inner))
        assert total > 0.4 * 19 * 320 * 240, f"{direction}: only {total} valid flow pixels"
        assert inner_agree / inner_total >= 0.995, \
            f"{direction} flow carries {inner_agree / inner_total:.4f} of the labels away from label edges, needs 0.995"
        assert agree / total >= 0.98, f"{direction} flow carries {agree / total:.4f} of the labels, needs 0.98"
        print(f"{direction} flow carries {agree / total:.4f} of the labels of {total} valid pixels, "
              f"{inner_agree / inner_total:.4f} of the {inner_total} away from label edges")
    assert not os.path.exists(os.path.join(seq, "flow_forward", "000019.png"))
    assert not os.path.exists(os.path.join(seq, "flow_backward", "000000.png"))

    # EuRoC export: what a VIO system reads, consistent with the dataset's own files.
    silva("export", two, "--format", "euroc", "--out", os.path.join(WORK, "export"), "--quiet")
    mav = os.path.join(WORK, "export", "euroc", "mav0")
    listed = np.loadtxt(os.path.join(mav, "cam0", "data.csv"), delimiter=",", comments="#", dtype=str)
    assert len(listed) == 20 and all(f"{int(t)}.png" == name for t, name in listed), listed[:3]
    assert np.array_equal(listed[:, 0].astype(np.int64), np.arange(20) * 100_000_000)
    for i, (t, name) in enumerate(listed):
        assert filecmp.cmp(os.path.join(mav, "cam0", "data", name), os.path.join(seq, "rgb", f"{i:06d}.png"),
                           shallow=False), name
    cam0 = yaml.safe_load(open(os.path.join(mav, "cam0", "sensor.yaml")))
    K = np.array(json.load(open(os.path.join(seq, "camera", "000000.json")))["K"])
    assert cam0["resolution"] == [320, 240] and cam0["rate_hz"] == 10, cam0
    assert np.allclose(cam0["intrinsics"], [K[0][0], K[1][1], K[0][2] - 0.5, K[1][2] - 0.5]), cam0["intrinsics"]
    assert np.array_equal(np.array(cam0["T_BS"]["data"]).reshape(4, 4), np.eye(4))
    assert filecmp.cmp(os.path.join(mav, "imu0", "data.csv"), os.path.join(seq, "imu.csv"), shallow=False)
    imu0 = yaml.safe_load(open(os.path.join(mav, "imu0", "sensor.yaml")))
    assert imu0["rate_hz"] == 200 and imu0["gyroscope_noise_density"] == 0, imu0
    state = np.loadtxt(os.path.join(mav, "state_groundtruth_estimate0", "data.csv"), delimiter=",", comments="#")
    assert state.shape == (400, 17), state.shape
    assert np.array_equal(state[:, 0], imu[:, 0])
    # At the camera frames (every 20th reading) the state is the TUM ground truth (w first in EuRoC).
    assert np.allclose(state[::20, 1:4], gt[:, 1:4], atol=1e-8)
    assert np.allclose(state[::20, 4:8], gt[:, [7, 4, 5, 6]], atol=1e-9)
    # Its velocity is the derivative of its positions, and noise "none" has no biases.
    centre = (state[2:, 1:4] - state[:-2, 1:4]) / 0.01
    assert np.max(np.abs(centre - state[1:-1, 8:11])) < 0.01, np.max(np.abs(centre - state[1:-1, 8:11]))
    assert np.all(state[:, 11:17] == 0)
    silva("export", one, "--format", "euroc", "--out", os.path.join(WORK, "export-one"), "--quiet")
    assert filecmp.cmp(os.path.join(WORK, "export-one", "euroc", "mav0", "cam0", "sensor.yaml"),
                       os.path.join(mav, "cam0", "sensor.yaml"), shallow=False)

    # The ROS 2 bag carries the IMU too, read back by npm's MCAP and CDR readers (skipped without node).
    node_dir = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "node")
    if shutil.which("node") and os.path.isdir(os.path.join(node_dir, "node_modules", "@mcap")):
        silva("export", two, "--format", "rosbag2", "--out", os.path.join(WORK, "bag"), "--quiet")
        bag = os.path.join(WORK, "bag", "rosbag2", "trajectory", "trajectory_0.mcap")
        result = subprocess.run(["node", os.path.join(node_dir, "read_bag.mjs"), bag], capture_output=True, text=True)
        assert result.returncode == 0, result.stderr
        messages = json.loads(result.stdout)["messages"]
        readings = [m for m in messages if m["topic"] == "/imu"]
        assert len(readings) == 400, len(readings)
        assert [int(m["stamp"]) for m in readings] == list(imu[:, 0].astype(np.int64))
        assert np.array_equal(np.array([m["gyro"] + m["accel"] for m in readings]), imu[:, 1:7])
        assert readings[0]["frame_id"] == "camera_optical_frame" and readings[0]["orientation_covariance"][0] == -1
        images = [int(m["stamp"]) for m in messages if m["topic"] == "/camera/image_raw"]
        assert images == [i * 100_000_000 for i in range(20)], images
        times = [int(m["log_time"]) for m in messages]
        assert times == sorted(times), "bag messages out of time order"
    else:
        print("node or tests/node/node_modules missing: the bag's IMU is not read back")

    # The ADIS16448 model adds noise of its documented size to the same walk.
    noisy_dir = generate("noisy", 2, "adis16448")
    noisy = np.loadtxt(os.path.join(noisy_dir, "trajectory", "imu.csv"), delimiter=",", comments="#")
    spread = np.std(np.diff(noisy[:, 1:4] - imu[:, 1:4], axis=0))
    expected = np.sqrt(2 * 200) * 1.6968e-4
    assert abs(spread / expected - 1) < 0.15, f"gyro noise spread {spread}, expected {expected}"
    # A dataset without the sequence has nothing to export as EuRoC: exit 2 naming what is missing.
    plain = os.path.join(WORK, "plain")
    silva("generate", "--seed", "3", "--out", plain, "--quiet", "--set", "output.resolution=32x24",
          "--set", "captures.autopilot_points=1", "--set", "captures.random_count=0")
    refused = silva("export", os.path.join(plain, f"{3:010d}"), "--format", "euroc", "--out", os.path.join(WORK, "x"),
                    expect=2)
    assert "needs the trajectory sequence" in refused.stderr, refused.stderr
    check_file_walk(two)
    print("trajectory: 20 frames, 400 IMU readings; integration error", f"{max(errors):.4f} m")


def check_file_walk(walked):
    """A walk through the poses of trajectory.file (here the first walk's groundtruth.txt, in a world without a
    trail) follows them within the smoothing of its 0.25 s control points; a file whose times go back is refused."""
    truth = os.path.join(walked, "trajectory", "groundtruth.txt")
    out = os.path.join(WORK, "file-walk")
    silva("generate", "--seed", str(SEED), "--out", out, "--quiet", "--set", "output.resolution=32x24",
          "--set", 'captures.sequences=["trajectory"]', "--set", "trail.enabled=false",
          "--set", f"trajectory.file={truth}", "--set", 'output.types=["depth"]')
    a = np.loadtxt(truth)
    b = np.loadtxt(os.path.join(out, f"{SEED:010d}", "trajectory", "groundtruth.txt"))
    assert len(b) == 19, len(b)  # frames every 0.1 s while t < the file's span of 1.9 s
    assert np.allclose(b[:, 0], a[:19, 0])
    error = np.linalg.norm(a[:19, 1:4] - b[:, 1:4], axis=1).max()
    assert error < 0.03, f"the file walk strays {error} m from its poses"  # the 1.8 Hz bob, smoothed
    bad = os.path.join(WORK, "backwards.txt")
    with open(bad, "w") as f:
        f.write("0 0 0 1 0 0 0 1\n1 0 0 1 0 0 0 1\n0.5 0 0 1 0 0 0 1\n")
    refused = silva("generate", "--seed", "1", "--out", os.path.join(WORK, "never"), "--quiet",
                    "--set", 'captures.sequences=["trajectory"]', "--set", f"trajectory.file={bad}", expect=2)
    assert "line 3" in refused.stderr and "strictly increase" in refused.stderr, refused.stderr
    assert not os.path.exists(os.path.join(WORK, "never")), "a refused run wrote its folder"


main()
