#!/usr/bin/python3
"""`silva export` read back by independent readers and compared pixel for pixel / pose for pose with the source.

Usage: export_test.py SILVA WORKDIR TEST   (TEST: generate, coco-panoptic, coco-instances, cityscapes, colmap,
nerfstudio, semantickitti, errors, copy, damaged). `generate` makes the small dataset the others read (a ctest fixture);
semantickitti generates its own small dataset with LiDAR (and checks python/silva_dataset's LiDAR read-back on it).
"""
import json
import os
import shutil
import subprocess
import sys

os.environ.setdefault("OPENCV_IO_ENABLE_OPENEXR", "1")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "python"))
import cv2  # noqa: E402
import numpy as np  # noqa: E402
from silva_cli import damaged_copy, edit_json, runner, small_dataset  # noqa: E402
from silva_dataset import SilvaDataset  # noqa: E402  (the loader's LiDAR read-back, beside the independent reads)

SILVA, WORK, TEST = sys.argv[1], sys.argv[2], sys.argv[3]
SEED = 4242
DATASET = os.path.join(WORK, "dataset", f"{SEED:010d}")
EXPORT = os.path.join(WORK, "export")


silva = runner(SILVA)


def generate():
    small_dataset(silva, WORK, SEED, "[0.0]", 1, '["rgb","semantic","semantic_color","instance","depth","depth_exr","normal"]',
                  "--set", 'output.formats=["nerfstudio"]')


def frames():
    manifest = json.load(open(os.path.join(DATASET, "manifest.json")))
    out = []
    for sequence in manifest["config"]["captures"]["sequences"]:
        for frame in range(manifest["frames"].get(sequence, 0)):
            out.append((sequence, frame))
    return out


def source(sequence, frame, folder, ext):
    return os.path.join(DATASET, sequence, folder, f"{frame:06d}.{ext}")


def read(path):
    image = cv2.imread(path, cv2.IMREAD_UNCHANGED)
    assert image is not None, f"{path}: unreadable"
    return image


def export(fmt):
    target = os.path.join(EXPORT, fmt)
    silva("export", DATASET, "--format", fmt, "--out", EXPORT, "--overwrite", "--quiet")
    return target


def camera(sequence, frame, folder=None):
    path = os.path.join(folder, "camera", f"{frame:06d}.json") if folder else source(sequence, frame, "camera", "json")
    cam = json.load(open(path))
    return np.array(cam["K"]), np.array(cam["camera_to_world"])


def things():
    ontology = json.load(open(os.path.join(DATASET, "ontology.json")))["classes"]
    return {c["id"] for c in ontology if c["role"] in ("tree_trunk", "dead_tree", "stump", "shrub", "obstacle")}


def check_coco_panoptic():
    out = export("coco-panoptic")
    doc = json.load(open(os.path.join(out, "panoptic.json")))
    cats = {c["id"]: c for c in doc["categories"]}
    assert {c for c, v in cats.items() if v["isthing"]} == things()
    assert len(doc["annotations"]) == len(frames())
    segments = crowds = 0
    for (sequence, frame), ann, img in zip(frames(), doc["annotations"], doc["images"]):
        assert ann["image_id"] == img["id"]
        rgb = cv2.cvtColor(read(os.path.join(out, "panoptic", ann["file_name"])), cv2.COLOR_BGR2RGB).astype(np.int64)
        ids = rgb[..., 0] + 256 * rgb[..., 1] + 65536 * rgb[..., 2]
        semantic = read(source(sequence, frame, "semantic", "png")).astype(np.int64)
        instance = read(source(sequence, frame, "instance", "png")).astype(np.int64)
        expected = np.where(semantic == 0, 0, instance * 256 + semantic)
        assert np.array_equal(ids, expected), f"{sequence}/{frame}: panoptic ids differ from the source labels"
        assert sorted(s["id"] for s in ann["segments_info"]) == sorted(set(np.unique(ids)) - {0})
        for s in ann["segments_info"]:
            ys, xs = np.nonzero(ids == s["id"])
            assert s["area"] == len(xs)
            assert s["bbox"] == [xs.min(), ys.min(), xs.max() - xs.min() + 1, ys.max() - ys.min() + 1]
            assert s["category_id"] == s["id"] % 256 and s["category_id"] in cats
            # Crowds: thing pixels without an instance, and thing segments under the default 16-pixel minimum.
            thing = cats[s["category_id"]]["isthing"]
            assert s["iscrowd"] == int(bool(thing) and (s["id"] < 256 or s["area"] < 16)), s
            crowds += s["iscrowd"]
            segments += 1
        assert os.path.samefile(os.path.join(out, "images", img["file_name"]), source(sequence, frame, "rgb", "png"))
    assert 0 < crowds < segments, (crowds, segments)
    print(f"coco-panoptic: {segments} segments in {len(frames())} frames equal the source labels; {crowds} crowds")
    check_panoptic_for_detectron2()


def check_panoptic_for_detectron2():
    """--image-format jpg: the files detectron2's load_coco_panoptic_json opens (image = image_dir /
    <annotation file_name's stem>.jpg, label = gt_dir / file_name; re-implemented from its documented behaviour)."""
    target = os.path.join(WORK, "panoptic-jpg")
    shutil.rmtree(target, ignore_errors=True)
    silva("export", DATASET, "--format", "coco-panoptic", "--out", target, "--image-format", "jpg", "--quiet")
    out = os.path.join(target, "coco-panoptic")
    doc = json.load(open(os.path.join(out, "panoptic.json")))
    cats = {c["id"] for c in doc["categories"]}
    for (sequence, frame), ann, img in zip(frames(), doc["annotations"], doc["images"]):
        image_file = os.path.join(out, "images", os.path.splitext(ann["file_name"])[0] + ".jpg")
        assert img["file_name"] == os.path.basename(image_file)
        jpeg = cv2.imread(image_file)
        png = read(source(sequence, frame, "rgb", "png"))
        assert jpeg is not None and jpeg.shape == png.shape, image_file
        mse = np.mean((jpeg.astype(np.float64) - png.astype(np.float64)) ** 2)
        # Quality 95 of a noisy forest frame: 29-31 dB here; another frame would be near 12 dB.
        assert 10 * np.log10(255 ** 2 / max(mse, 1e-12)) > 27, f"{image_file}: JPEG too far from the PNG"
        assert os.path.isfile(os.path.join(out, "panoptic", ann["file_name"]))
        assert all(s["category_id"] in cats for s in ann["segments_info"])


def rle_decode(counts, h, w):
    """COCO compressed RLE string -> mask, written from the format's description (independent of Silva)."""
    runs, p = [], 0
    while p < len(counts):
        x, k, more = 0, 0, True
        while more:
            c = ord(counts[p]) - 48
            x |= (c & 0x1F) << (5 * k)
            more = bool(c & 0x20)
            p += 1
            k += 1
            if not more and c & 0x10:
                x |= -1 << (5 * k)
        if len(runs) > 2:
            x += runs[-2]
        runs.append(x)
    flat = np.zeros(h * w, dtype=np.uint8)
    pos = 0
    for i, n in enumerate(runs):
        if i % 2:
            flat[pos:pos + n] = 1
        pos += n
    assert pos == h * w, "RLE counts do not cover the image"
    return flat.reshape(w, h).T


def check_coco_instances():
    out = export("coco-instances")
    path = os.path.join(out, "instances.json")
    doc = json.load(open(path))
    try:
        from pycocotools.coco import COCO
        coco = COCO(path)
        decode = coco.annToMask
        print("coco-instances: masks decoded by pycocotools")
    except ImportError:
        coco = None
        print("coco-instances: SKIP the pycocotools read-back (pycocotools is not importable; Debian bookworm has "
              "no python3-pycocotools); masks decoded by the test's own RLE decoder")

        def decode(a):
            return rle_decode(a["segmentation"]["counts"], *a["segmentation"]["size"])
    by_image = {}
    for a in doc["annotations"]:
        by_image.setdefault(a["image_id"], []).append(a)
    count = small = 0
    for (sequence, frame), img in zip(frames(), doc["images"]):
        instance = read(source(sequence, frame, "instance", "png"))
        table = json.load(open(source(sequence, frame, "instance", "json")))["instances"]
        anns = by_image.get(img["id"], [])
        present = [e for e in table if (instance == e["index"]).any()]
        assert len(anns) == len(present)
        for a, e in zip(anns, present):
            mask = decode(a)
            assert np.array_equal(mask.astype(bool), instance == e["index"]), f"{sequence}/{frame}: mask differs"
            ys, xs = np.nonzero(mask)
            assert a["area"] == len(xs) and a["category_id"] == e["class_id"] and a["instance_id"] == e["instance_id"]
            assert a["bbox"] == [xs.min(), ys.min(), xs.max() - xs.min() + 1, ys.max() - ys.min() + 1]
            assert a["iscrowd"] == int(a["area"] < 16), f"{sequence}/{frame}: iscrowd {a['iscrowd']}, area {a['area']}"
            small += a["iscrowd"]
            count += 1
    assert count > 0, "the test dataset shows no instance"
    assert 0 < small < count, f"{small} of {count} instances under 16 pixels: the threshold is not exercised"
    # --min-area 0 marks none, --min-area 100 more.
    for min_area in (0, 100):
        target = os.path.join(WORK, f"min-area-{min_area}")
        shutil.rmtree(target, ignore_errors=True)
        silva("export", DATASET, "--format", "coco-instances", "--out", target, "--min-area", str(min_area), "--quiet")
        anns = json.load(open(os.path.join(target, "coco-instances", "instances.json")))["annotations"]
        assert [a["iscrowd"] for a in anns] == [int(a["area"] < min_area) for a in anns], min_area
    silva("export", DATASET, "--format", "coco-instances", "--out", target, "--min-area", "-1", expect=2)
    print(f"coco-instances: {count} instance masks equal the source instance images; {small} under 16 pixels are "
          "crowds")


def check_cityscapes():
    out = export("cityscapes")
    city = f"{SEED:010d}"
    for sequence, frame in frames():
        stem = os.path.join(out, "gtFine", "train", city, f"{city}_{sequence}_{frame:06d}_gtFine_")
        semantic = read(source(sequence, frame, "semantic", "png")).astype(np.int64)
        instance = read(source(sequence, frame, "instance", "png")).astype(np.int64)
        labels = read(stem + "labelIds.png").astype(np.int64)
        ids = read(stem + "instanceIds.png").astype(np.int64)
        assert ids.dtype == np.int64 and np.array_equal(labels, semantic)
        cls = np.where(ids >= 1000, ids // 1000, ids)
        assert np.array_equal(cls, semantic), "instanceIds // 1000 is not the class"
        assert np.array_equal(ids >= 1000, instance > 0), "instance pixels and Cityscapes instance pixels differ"
        # The same partition into instances: a one-to-one map between source indices and Cityscapes ids.
        pairs = set(zip(instance[instance > 0].tolist(), ids[instance > 0].tolist()))
        assert len({a for a, _ in pairs}) == len(pairs) == len({b for _, b in pairs})
        color = cv2.cvtColor(read(stem + "color.png"), cv2.COLOR_BGR2RGB)
        assert np.array_equal(color, cv2.cvtColor(read(source(sequence, frame, "semantic_color", "png")),
                                                  cv2.COLOR_BGR2RGB))
        assert os.path.isfile(os.path.join(out, "leftImg8bit", "train", city,
                                           f"{city}_{sequence}_{frame:06d}_leftImg8bit.png"))
    check_cityscapes_loaders(out, city)
    print(f"cityscapes: {len(frames())} frames, labelIds and instanceIds (class*1000+k) equal the source labels; "
          "labelTrainIds and polygons.json as detectron2's semantic loader reads them")


def check_cityscapes_loaders(out, city):
    """labelTrainIds (label_train_ids.json's mapping), polygons.json, and the files detectron2's
    load_cityscapes_semantic derives from each leftImg8bit name (re-implemented from its documented behaviour)."""
    ontology = json.load(open(os.path.join(DATASET, "ontology.json")))["classes"]
    background = next(c["id"] for c in ontology if c["role"] == "background")
    ids = sorted({c["id"] for c in ontology} - {background})
    want = {i: t for t, i in enumerate(ids)}
    mapping = json.load(open(os.path.join(out, "label_train_ids.json")))
    assert mapping["ignore_train_id"] == 255
    assert {c["id"]: c["train_id"] for c in mapping["classes"]} == {**want, background: 255}
    lut = np.full(256, 255, dtype=np.int64)
    for i, t in want.items():
        lut[i] = t
    names = {c["id"]: c["name"] for c in ontology}
    left_dir = os.path.join(out, "leftImg8bit", "train", city)
    images = sorted(os.listdir(left_dir))
    assert len(images) == len(frames())
    for basename in images:  # detectron2: cityscapes.py load_cityscapes_semantic
        gt = os.path.join(out, "gtFine", "train", city, basename.replace("leftImg8bit.png", "gtFine_labelTrainIds.png"))
        polygons = json.load(open(gt.replace("labelTrainIds.png", "polygons.json")))
        train = read(gt).astype(np.int64)
        labels = read(gt.replace("labelTrainIds", "labelIds")).astype(np.int64)
        assert np.array_equal(train, lut[labels]), f"{basename}: labelTrainIds is not the mapping"
        assert (polygons["imgHeight"], polygons["imgWidth"]) == train.shape
        # The outlines drawn in order (larger first) cover what the labels say, up to the outline pixels.
        drawn = np.full(train.shape, 254, dtype=np.uint8)  # a value no class has: undrawn pixels disagree
        for obj in polygons["objects"]:
            assert obj["label"] in names.values() and len(obj["polygon"]) >= 1
            cls = next(i for i, n in names.items() if n == obj["label"])
            cv2.fillPoly(drawn, [np.array(obj["polygon"], dtype=np.int32)], int(lut[cls]))
        agree = np.mean(drawn == train)
        assert agree > 0.95, f"{basename}: polygons agree with labelTrainIds on {agree:.3f} of the pixels"
    # --split val: the same files under val/.
    target = os.path.join(WORK, "cityscapes-val")
    shutil.rmtree(target, ignore_errors=True)
    silva("export", DATASET, "--format", "cityscapes", "--out", target, "--split", "val", "--quiet")
    assert sorted(os.listdir(os.path.join(target, "cityscapes", "leftImg8bit", "val", city))) == images
    assert not os.path.exists(os.path.join(target, "cityscapes", "leftImg8bit", "train"))


def quaternion_to_matrix(w, x, y, z):
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def check_colmap():
    out = export("colmap")
    model = os.path.join(out, "sparse", "0")
    if shutil.which("colmap"):
        binary, text = os.path.join(WORK, "colmap-bin"), os.path.join(WORK, "colmap-txt")
        for folder in (binary, text):
            shutil.rmtree(folder, ignore_errors=True)
            os.makedirs(folder)
        for src, dst, kind in ((model, binary, "BIN"), (binary, text, "TXT")):
            r = subprocess.run(["colmap", "model_converter", "--input_path", src, "--output_path", dst,
                                "--output_type", kind], capture_output=True, text=True)
            assert r.returncode == 0, f"colmap model_converter failed: {r.stderr[-2000:]}"
        model = text
        print("colmap: read back through colmap model_converter (TXT -> BIN -> TXT)")
    else:
        print("colmap: SKIP the colmap read-back (no colmap binary; apt-get install colmap); parsing Silva's text")
    cams = {}
    for line in open(os.path.join(model, "cameras.txt")):
        if line.startswith("#") or not line.strip():
            continue
        f = line.split()
        assert f[1] == "PINHOLE"
        cams[int(f[0])] = np.array([[float(f[4]), 0, float(f[6])], [0, float(f[5]), float(f[7])], [0, 0, 1]])
    lines = [l for l in open(os.path.join(model, "images.txt")) if not l.startswith("#")]
    images = {}
    for head, pts in zip(lines[0::2], lines[1::2]):
        f = head.split()
        images[f[9]] = (int(f[0]), quaternion_to_matrix(*map(float, f[1:5])), np.array(list(map(float, f[5:8]))),
                        cams[int(f[8])], pts.split())
    assert len(images) == len(frames())
    points = {}
    for line in open(os.path.join(model, "points3D.txt")):
        if not line.startswith("#") and line.strip():
            f = line.split()
            points[int(f[0])] = np.array(list(map(float, f[1:4])))
    checked = 0
    for sequence, frame in frames():
        image_id, r, t, k, pts = images[f"{sequence}_{frame:06d}.png"]
        k_src, c2w = camera(sequence, frame)
        assert np.allclose(k, k_src, atol=1e-9)
        assert np.allclose(r, c2w[:3, :3].T, atol=1e-9) and np.allclose(t, -c2w[:3, :3].T @ c2w[:3, 3], atol=1e-6)
        depth = read(source(sequence, frame, "depth", "png"))
        for u, v, pid in zip(pts[0::3], pts[1::3], pts[2::3]):
            x_cam = r @ points[int(pid)] + t
            uv = k @ (x_cam / x_cam[2])
            assert abs(uv[0] - float(u)) < 1e-3 and abs(uv[1] - float(v)) < 1e-3
            assert abs(x_cam[2] - depth[int(float(v))][int(float(u))] / 1000.0) < 1e-5
            checked += 1
    assert checked > 0
    print(f"colmap: {len(images)} poses equal the camera files; {checked} points project to their pixel and depth")


def check_nerfstudio():
    during_run = open(os.path.join(DATASET, "export", "nerfstudio", "transforms.json")).read()
    out = export("nerfstudio")
    assert open(os.path.join(out, "transforms.json")).read() == during_run, "output.formats differs from export"
    doc = json.load(open(os.path.join(out, "transforms.json")))
    assert doc["camera_model"] == "OPENCV" and len(doc["frames"]) == len(frames())
    checked = clamped = 0
    for (sequence, frame), f in zip(frames(), doc["frames"]):
        k, c2w = camera(sequence, frame)
        gl = np.array(f["transform_matrix"])
        exported_mm = read(os.path.join(out, f["depth_file_path"]))
        source_mm = read(source(sequence, frame, "depth", "png"))
        # The clamp (65535 mm: at or beyond 65.535 m) is no depth for nerfstudio; every other pixel is the dataset's.
        assert np.array_equal(exported_mm, np.where(source_mm == 65535, 0, source_mm)), f"{sequence}/{frame}: depth"
        clamped += int((source_mm == 65535).sum())
        depth = exported_mm.astype(np.float64) / 1000.0
        mask = read(os.path.join(out, f["mask_path"]))
        semantic = read(source(sequence, frame, "semantic", "png"))
        assert np.array_equal(mask == 0, semantic == 0)
        for v, u in zip(*np.nonzero((depth > 0) & (depth < 65.0))):
            z = depth[v, u]
            # nerfstudio: ray direction ((u + 0.5 - cx) / fx, -(v + 0.5 - cy) / fy, -1) in OpenGL camera axes.
            d_gl = np.array([(u + 0.5 - f["cx"]) / f["fl_x"], -(v + 0.5 - f["cy"]) / f["fl_y"], -1.0])
            p_gl = gl[:3, :3] @ (z * d_gl) + gl[:3, 3]
            p_cv = c2w[:3, :3] @ (z * np.linalg.inv(k) @ np.array([u + 0.5, v + 0.5, 1.0])) + c2w[:3, 3]
            assert np.allclose(p_gl, p_cv, atol=1e-9), f"{sequence}/{frame} pixel {u},{v}: {p_gl} != {p_cv}"
            checked += 1
    assert checked > 0
    print(f"nerfstudio: {checked} depth pixels reproject through the OpenGL poses onto the contract's poses; "
          f"{clamped} clamped pixels are no depth")


def read_kitti_matrices(path, key=None):
    """3x4 matrices of a KITTI text file as 4x4 arrays: every line, or the line starting with `key:`."""
    rows = []
    for line in open(path):
        if key is None:
            values = line.split()
        elif line.startswith(key + ":"):
            values = line.split()[1:]
        else:
            continue
        m = np.eye(4)
        m[:3, :] = np.array(list(map(float, values))).reshape(3, 4)
        rows.append(m)
    return rows


def check_semantickitti():
    work = os.path.join(WORK, "kitti")
    shutil.rmtree(work, ignore_errors=True)
    seed = 31
    silva("generate", "--seed", str(seed), "--out", work, "--quiet",
          "--set", "output.resolution=64x48", "--set", "captures.autopilot_points=2",
          "--set", "captures.autopilot_yaws=[0.0]", "--set", "captures.random_count=2",
          "--set", "world.extent=128", "--set", "world.render_distance=48", "--set", "trail.control_points=6",
          "--set", "camera.far=40", "--set", 'output.types=["rgb","semantic","lidar"]',
          "--set", 'output.formats=["semantickitti"]')
    dataset = os.path.join(work, f"{seed:010d}")
    during_run = os.path.join(dataset, "export", "semantickitti")
    out = os.path.join(work, "export", "semantickitti")
    silva("export", dataset, "--format", "semantickitti", "--out", os.path.join(work, "export"), "--quiet")
    manifest = json.load(open(os.path.join(dataset, "manifest.json")))
    sensor = manifest["sensors"]["lidar"]
    ontology = json.load(open(os.path.join(dataset, "ontology.json")))["classes"]
    to_kitti = {c["id"]: c["semantic_kitti_id"] for c in ontology}
    lut = np.full(1 << 16, -1, dtype=np.int64)
    for silva_id, kitti_id in to_kitti.items():
        lut[silva_id] = kitti_id
    numbers = {"autopilot": "00", "random": "01", "custom": "02"}
    loader = SilvaDataset(dataset)
    sequence_index, index_owner, seen_in = {}, {}, {}  # (sequence, object) -> exported index and back; scans
    counts, scans = {}, 0
    for sequence, frames in manifest["frames"].items():
        seq = os.path.join(out, "sequences", numbers[sequence])
        src = os.path.join(dataset, sequence)
        # Poses round-trip: camera 0's pose times poses.txt's line i is camera i's pose; Tr is the LiDAR mount.
        poses = read_kitti_matrices(os.path.join(seq, "poses.txt"))
        tr = read_kitti_matrices(os.path.join(seq, "calib.txt"), "Tr")[0]
        assert np.allclose(tr, np.array(sensor["lidar_to_camera"]), atol=1e-9), "Tr is not the LiDAR mount"
        assert len(poses) == frames
        first = camera(sequence, 0, src)[1]
        # calib.txt's P2 puts pixel centres on integers (KITTI's convention): Silva's K moved by half a pixel.
        k0 = camera(sequence, 0, src)[0]
        p2 = read_kitti_matrices(os.path.join(seq, "calib.txt"), "P2")[0][:3, :3]
        assert np.allclose(p2, k0 - np.array([[0, 0, 0.5], [0, 0, 0.5], [0, 0, 0]]), atol=1e-9), (p2, k0)
        times = [float(t) for t in open(os.path.join(seq, "times.txt"))]
        assert np.allclose(times, np.arange(frames) / sensor["rotation_hz"], atol=1e-6), times
        for f in range(frames):
            k, c2w = camera(sequence, f, src)
            assert np.allclose(first @ poses[f], c2w, atol=1e-6), f"{sequence}/{f}: poses.txt does not give the camera"
            scan = np.fromfile(os.path.join(seq, "velodyne", f"{f:06d}.bin"), dtype="<f4").reshape(-1, 4)
            source_scan = np.fromfile(os.path.join(src, "lidar", f"{f:06d}.bin"), dtype="<f4").reshape(-1, 4)
            assert np.array_equal(scan, source_scan) and len(scan) > 0
            label = np.fromfile(os.path.join(seq, "labels", f"{f:06d}.label"), dtype="<u4")
            source = np.fromfile(os.path.join(src, "lidar_labels", f"{f:06d}.label"), dtype="<u4")
            assert label.shape[0] == scan.shape[0] == source.shape[0]
            assert np.array_equal(label & 0xFFFF, lut[source & 0xFFFF]), f"{sequence}/{f}: classes are not the mapping"
            # One object, one instance index in every scan of its sequence (the dataset numbers them per scan).
            table = json.load(open(os.path.join(src, "lidar_labels", f"{f:06d}.json")))["instances"]
            object_of = {e["index"]: e["instance_id"] for e in table}
            for scan_index, kitti_index in set(zip((source >> 16).tolist(), (label >> 16).tolist())):
                assert (scan_index == 0) == (kitti_index == 0), f"{sequence}/{f}: instance {scan_index} -> {kitti_index}"
                if scan_index:
                    obj = object_of[scan_index]
                    seen_in[(sequence, obj)] = seen_in.get((sequence, obj), 0) + 1
                    assert sequence_index.setdefault((sequence, obj), kitti_index) == kitti_index, \
                        f"{sequence}/{f}: object {obj} changed its instance index"
                    assert index_owner.setdefault((sequence, kitti_index), obj) == obj, \
                        f"{sequence}/{f}: instance index {kitti_index} names two objects"
            sample = loader[loader.frames.index((sequence, f))]
            assert np.array_equal(sample["lidar"], source_scan), f"{sequence}/{f}: the loader's points differ"
            assert sample["lidar_labels"] is not None and np.array_equal(sample["lidar_labels"], source), \
                f"{sequence}/{f}: the loader's LiDAR labels are not lidar_labels/{f:06d}.label"
            for kid, n in zip(*np.unique(label & 0xFFFF, return_counts=True)):
                counts[int(kid)] = counts.get(int(kid), 0) + int(n)
            assert os.path.samefile(os.path.join(seq, "image_2", f"{f:06d}.png"), os.path.join(src, "rgb", f"{f:06d}.png"))
            with open(os.path.join(seq, "labels", f"{f:06d}.label"), "rb") as a, \
                    open(os.path.join(during_run, "sequences", numbers[sequence], "labels", f"{f:06d}.label"), "rb") as b:
                assert a.read() == b.read(), "output.formats differs from silva export"
            scans += 1
    assert max(seen_in.values()) > 1, "no object is seen by two scans: the instance check compared nothing"
    try:
        import yaml
    except ImportError:
        print("semantickitti: SKIP the semantic-kitti.yaml read-back (python3-yaml is not importable)")
    else:
        doc = yaml.safe_load(open(os.path.join(out, "semantic-kitti.yaml")))
        assert set(doc["labels"]) == set(to_kitti.values()) | {0}
        total = sum(counts.values())
        for kid in doc["labels"]:
            assert abs(doc["content"][kid] - counts.get(kid, 0) / total) < 1e-8, (kid, doc["content"][kid])
        assert doc["learning_map"][0] == 0 and doc["learning_ignore"][0] is True
        assert sorted(doc["learning_map"].values()) == list(range(len(doc["labels"])))
        assert all(doc["learning_map_inv"][t] == k for k, t in doc["learning_map"].items())
        assert doc["split"]["train"] == sorted(int(numbers[s]) for s in manifest["frames"])
    r = silva("export", DATASET, "--format", "all", "--out", os.path.join(work, "all"), "--json")
    assert [e["format"] for e in json.loads(r.stdout)["exports"]] == \
        ["coco-panoptic", "coco-instances", "cityscapes", "colmap", "nerfstudio", "rosbag2", "tartanair"], \
        "all: every camera format, rosbag2 and tartanair, semantickitti only with lidar, euroc only with a trajectory"
    r = silva("export", DATASET, "--format", "semantickitti", "--out", os.path.join(work, "none"), expect=2)
    assert "needs output type 'lidar'" in r.stderr and r.stderr.count("\n") == 1, r.stderr
    r = silva("generate", "--seed", "1", "--out", os.path.join(work, "none"), "--set", 'output.formats=["semantickitti"]',
              expect=2)
    assert "needs \"lidar\" in output.types" in r.stderr and r.stderr.count("\n") == 1, r.stderr
    print(f"semantickitti: {scans} scans and labels equal the source through the ontology's mapping; poses round-trip")


def check_errors():
    r = silva("export", WORK, "--format", "colmap", expect=2)
    assert "not a Silva dataset" in r.stderr and r.stderr.count("\n") == 1, r.stderr
    r = silva("export", DATASET, "--format", "kitti", expect=2)
    assert "unknown format 'kitti'" in r.stderr and "coco-panoptic" in r.stderr, r.stderr
    r = silva("export", DATASET, "--format", ",,", "--overwrite", expect=2)
    assert "--format ',,': unknown format ''" in r.stderr and "--overwrite" not in r.stderr, r.stderr
    target = os.path.join(WORK, "taken")
    os.makedirs(os.path.join(target, "colmap"), exist_ok=True)
    open(os.path.join(target, "colmap", "keep.txt"), "w").write("mine")
    r = silva("export", DATASET, "--format", "colmap", "--out", target, expect=2)
    assert "already exists; pass --overwrite" in r.stderr, r.stderr
    assert open(os.path.join(target, "colmap", "keep.txt")).read() == "mine"
    broken = os.path.join(WORK, "broken", f"{SEED:010d}")
    shutil.rmtree(os.path.dirname(broken), ignore_errors=True)
    shutil.copytree(DATASET, broken, ignore=shutil.ignore_patterns("export", "card_*"))
    open(os.path.join(broken, "random", "instance", "000000.png"), "w").write("not a png")
    r = silva("export", broken, "--format", "cityscapes", expect=2)
    assert "instance/000000.png: not a PNG file" in r.stderr and r.stderr.count("\n") == 1, r.stderr
    assert not os.path.exists(os.path.join(broken, "export", "cityscapes"))
    print("errors: not a dataset, unknown format, an existing target and a corrupt label image each stop with one "
          "line, exit 2")


def check_copy():
    """--copy: the export's images have the dataset's bytes in files of their own; editing one leaves the dataset."""
    out = os.path.join(WORK, "copied")
    shutil.rmtree(out, ignore_errors=True)
    silva("export", DATASET, "--format", "colmap,nerfstudio", "--out", out, "--copy", "--quiet")
    copied = 0
    for fmt in ("colmap", "nerfstudio"):
        for name in sorted(os.listdir(os.path.join(out, fmt, "images"))):
            sequence, frame = name[:-len(".png")].rsplit("_", 1)
            exported, original = os.path.join(out, fmt, "images", name), source(sequence, int(frame), "rgb", "png")
            assert not os.path.samefile(exported, original), f"{fmt}/{name} is the dataset's file"
            assert open(exported, "rb").read() == open(original, "rb").read(), f"{fmt}/{name}: bytes differ"
            copied += 1
    before = open(original, "rb").read()
    open(exported, "ab").write(b"edit")
    assert open(original, "rb").read() == before, "editing the export edited the dataset"
    print(f"copy: {copied} images copied, none shared with the dataset")


def check_damaged():
    """A damaged dataset (camera files no reader can project with, manifest counts the files do not back) stops
    export, card and verify with exit 2 and one line naming the file, where they crashed, hung or wrote nan."""
    work = os.path.join(WORK, "damaged")

    camera = lambda d: os.path.join(d, "random", "camera", "000000.json")  # noqa: E731
    manifest = lambda d: os.path.join(d, "manifest.json")  # noqa: E731
    cases = [
        (lambda d: edit_json(camera(d), lambda j: j["K"][0].__setitem__(0, 0.0)), "000000.json: 'K'"),
        (lambda d: edit_json(camera(d), lambda j: j["K"][0].__setitem__(2, 1e308)), "000000.json: 'K'"),
        (lambda d: edit_json(camera(d), lambda j: j["camera_to_world"][0].__setitem__(3, 1e19)), "'camera_to_world'"),
        (lambda d: edit_json(camera(d), lambda j: j["camera_to_world"][0].__setitem__(0, 3.0)), "rotation"),
        (lambda d: edit_json(manifest(d), lambda j: j["frames"].__setitem__("random", 1000000000)), "frames"),
        (lambda d: edit_json(manifest(d), lambda j: j["frames"].__setitem__("random", -1)), "frames"),
        (lambda d: edit_json(manifest(d), lambda j: j["frames"].__setitem__("random", "x")), "frames"),
        (lambda d: edit_json(manifest(d), lambda j: j["frames"].__setitem__("random", 50)), "is missing"),
        (lambda d: edit_json(manifest(d), lambda j: j["config"]["output"].__setitem__("types", "rgb")),
         "config.output.types must be a list of names"),
        (lambda d: edit_json(manifest(d), lambda j: j.pop("seed")), "manifest.json: seed is missing"),
    ]
    readers = ("export", "card", "verify")
    cases = [(edit, expected, readers) for edit, expected in cases]
    rgb = lambda d: os.path.join(d, "random", "rgb", "000000.png")  # noqa: E731
    semantic = lambda d: os.path.join(d, "random", "semantic", "000000.png")  # noqa: E731

    def replace_with(path, make):
        os.remove(path)
        make(path)

    def truncate(path):
        data = open(path, "rb").read()
        open(path, "wb").write(data[:len(data) // 2])

    def relabel(path, value):
        image = cv2.imread(path, cv2.IMREAD_UNCHANGED)
        image[0, 0] = value
        cv2.imwrite(path, image)

    cases += [
        (lambda d: truncate(rgb(d)), "rgb/000000.png", ("export",)),
        (lambda d: replace_with(rgb(d), lambda p: os.symlink("/etc/passwd", p)), "symbolic link", ("export",)),
        (lambda d: replace_with(rgb(d), lambda p: os.symlink(p + ".gone", p)), "symbolic link", ("export",)),
        (lambda d: replace_with(rgb(d), os.mkdir), "not a regular file", ("export",)),
        (lambda d: relabel(semantic(d), 250), "class 250", ("export-coco", "card", "verify")),
        (lambda d: cv2.imwrite(semantic(d), np.zeros((96, 128), np.uint8)), "128x96", ("export-coco", "card", "verify")),
    ]
    commands = {"export": ["export", None, "--format", "colmap"], "export-coco": ["export", None, "--format",
                "coco-panoptic"], "card": ["card", None], "verify": ["verify", None, "--sample", "0.01"]}
    for edit, expected, which in cases:
        d = damaged_copy(DATASET, work, edit)
        for command in ([d if a is None else a for a in commands[w]] for w in which):
            r = silva(*command, "--quiet", expect=2)
            assert expected in r.stderr and r.stderr.count("\n") == 1, (command, r.stderr)
        assert not os.path.exists(os.path.join(d, "export", "colmap")), "a refused export left files"
        assert not os.path.exists(os.path.join(d, "export", "coco-panoptic")), "a refused export left files"
    r = silva("verify", DATASET, "--sample", "nan", expect=2)
    assert "not a finite number" in r.stderr, r.stderr
    print(f"damaged: {len(cases)} damaged datasets through export, card and verify: exit 2, one line naming the file")


CHECKS = {"generate": generate, "coco-panoptic": check_coco_panoptic, "coco-instances": check_coco_instances,
          "cityscapes": check_cityscapes, "colmap": check_colmap, "nerfstudio": check_nerfstudio,
          "semantickitti": check_semantickitti, "errors": check_errors, "copy": check_copy,
          "damaged": check_damaged}
CHECKS[TEST]()
