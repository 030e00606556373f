"""Readers for each Silva output type and the SilvaDataset that joins them per frame."""
import json
import os

import cv2
import numpy as np


class DatasetError(ValueError):
    """A dataset file that does not hold what the contract says (docs/CONTRACT.md): the message names file and field."""


def _imread(path, flags=cv2.IMREAD_UNCHANGED):
    image = cv2.imread(str(path), flags)
    if image is None:
        raise FileNotFoundError(f"{path}: missing or not a readable image")
    return image


def read_rgb(path):
    """8-bit sRGB image as an H x W x 3 uint8 array in R, G, B order."""
    return cv2.cvtColor(_imread(path), cv2.COLOR_BGR2RGB)


def read_label(path):
    """Semantic (uint8 class ids) or instance (uint16 per-frame indices, 0 = none) image, H x W."""
    return _imread(path)


def read_depth(path):
    """Depth in metres along the optical axis as H x W float32, 0 = no hit.

    Reads depth_exr/*.exr (float metres) or depth/*.png (uint16 millimetres; 65535 means 65.535 m or farther).
    """
    image = _imread(path)
    if str(path).endswith(".exr"):
        return image.astype(np.float32)
    return image.astype(np.float32) / 1000.0


def read_normal(path):
    """World-space unit normals (Z up) as H x W x 3 float32 in [-1, 1]; (0, 0, 0) where nothing was hit."""
    rgb = read_rgb(path).astype(np.float32)
    normal = rgb / 127.5 - 1.0
    normal[np.all(rgb == 0, axis=2)] = 0.0
    return normal


def read_camera(path):
    """Camera file as a dict; "K" (3 x 3) and "camera_to_world" (4 x 4, OpenCV camera axes) as float64 arrays,
    plus "world_to_camera" (its inverse)."""
    with open(path) as f:
        cam = json.load(f)
    try:
        K = np.array(cam["K"], dtype=np.float64)
        c2w = np.array(cam["camera_to_world"], dtype=np.float64)
    except (KeyError, TypeError, ValueError) as e:
        raise DatasetError(f"{path}: K or camera_to_world missing or not numbers ({e})") from None
    if K.shape != (3, 3) or not np.all(np.isfinite(K)) or not (K[0, 0] > 0 and K[1, 1] > 0):
        raise DatasetError(f"{path}: 'K' must be a finite 3 x 3 matrix with positive focal lengths")
    R = c2w[:3, :3] if c2w.shape == (4, 4) else None
    if (R is None or not np.all(np.isfinite(c2w)) or np.abs(R.T @ R - np.eye(3)).max() > 1e-5
            or np.linalg.det(R) <= 0 or not np.array_equal(c2w[3], [0, 0, 0, 1])):
        raise DatasetError(f"{path}: 'camera_to_world' must be a finite rigid transform (rotation, last row 0 0 0 1)")
    cam["K"], cam["camera_to_world"] = K, c2w
    cam["world_to_camera"] = np.linalg.inv(c2w)
    return cam


def read_instance_table(path):
    """instance/NNNNNN.json as a structured array with fields index, instance_id, class_id."""
    with open(path) as f:
        rows = json.load(f)["instances"]
    table = np.zeros(len(rows), dtype=[("index", np.uint16), ("instance_id", np.uint32), ("class_id", np.uint8)])
    for k, row in enumerate(rows):
        table[k] = (row["index"], row["instance_id"], row["class_id"])
    return table


def read_lidar(bin_path, label_path=None):
    """A LiDAR scan in SemanticKITTI form: N x 4 float32 (x, y, z, intensity) and, when a .label file is given,
    N uint32 labels (class in the lower 16 bits, instance in the upper 16)."""
    raw = np.fromfile(bin_path, dtype=np.float32)
    if raw.size % 4:
        raise DatasetError(f"{bin_path}: not a KITTI scan (4 float32 per point)")
    points = raw.reshape(-1, 4)
    if label_path is None:
        return points, None
    labels = np.fromfile(label_path, dtype=np.uint32)
    if len(labels) != len(points):
        raise DatasetError(f"{label_path}: {len(labels)} labels for the {len(points)} points of {bin_path}")
    return points, labels


class SilvaDataset:
    """The frames of one dataset folder <output.dir>/<seed>/, in global order (sequences in config order, then
    frame number). Indexing returns a dict holding every output the run wrote for that frame."""

    def __init__(self, root):
        self.root = str(root)
        manifest_path = os.path.join(self.root, "manifest.json")
        if not os.path.isfile(manifest_path):
            raise FileNotFoundError(f"{self.root}: not a finished Silva dataset (no manifest.json)")
        with open(manifest_path) as f:
            self.manifest = json.load(f)
        with open(os.path.join(self.root, "ontology.json")) as f:
            self.ontology = json.load(f)["classes"]
        self.seed = self.manifest["seed"]
        self.types = self.manifest["config"]["output"]["types"]
        width, height = (int(v) for v in self.manifest["config"]["output"]["resolution"].split("x"))
        self.size = (height, width)
        self.frames = []
        for sequence in self.manifest["config"]["captures"]["sequences"]:
            count = self.manifest["frames"].get(sequence, 0)
            if not isinstance(count, int) or isinstance(count, bool) or not 0 <= count <= 1_000_000:
                raise DatasetError(f"{manifest_path}: frames.{sequence} must be a whole number 0 ... 1000000")
            last = os.path.join(self.root, sequence, "camera", f"{count - 1:06d}.json")
            if count and not os.path.isfile(last):
                raise DatasetError(f"{manifest_path}: frames.{sequence} = {count}, but {last} is missing")
            self.frames.extend((sequence, frame) for frame in range(count))

    def __len__(self):
        return len(self.frames)

    def path(self, index, folder, ext):
        """Path of frame `index`'s file in `folder`, e.g. path(0, "rgb", "png")."""
        sequence, frame = self.frames[index]
        return os.path.join(self.root, sequence, folder, f"{frame:06d}.{ext}")

    def class_names(self):
        """Class id -> name."""
        return {c["id"]: c["name"] for c in self.ontology}

    def __getitem__(self, index):
        if not 0 <= index < len(self):
            raise IndexError(index)
        sequence, frame = self.frames[index]
        sample = {"sequence": sequence, "frame": frame}
        camera = read_camera(self.path(index, "camera", "json"))
        sample.update(camera=camera, K=camera["K"], camera_to_world=camera["camera_to_world"])
        if "rgb" in self.types:
            sample["rgb"] = read_rgb(self.path(index, "rgb", "png"))
        known = np.zeros(256, dtype=bool)
        known[[c["id"] for c in self.ontology]] = True
        if "semantic" in self.types:
            sample["semantic"] = read_label(self.path(index, "semantic", "png"))
            if not known[sample["semantic"]].all():
                raise DatasetError(f"{self.path(index, 'semantic', 'png')}: holds a class id ontology.json lacks")
        if "semantic_color" in self.types:
            sample["semantic_color"] = read_rgb(self.path(index, "semantic_color", "png"))
        if "instance" in self.types:
            sample["instance"] = read_label(self.path(index, "instance", "png"))
            sample["instances"] = read_instance_table(self.path(index, "instance", "json"))
        if "depth_exr" in self.types:
            sample["depth"] = read_depth(self.path(index, "depth_exr", "exr"))
        elif "depth" in self.types:
            sample["depth"] = read_depth(self.path(index, "depth", "png"))
        if "normal" in self.types:
            sample["normal"] = read_normal(self.path(index, "normal", "png"))
        for key in ("rgb", "semantic", "semantic_color", "instance", "depth", "normal"):
            if key in sample and sample[key].shape[:2] != self.size:
                raise DatasetError(f"{self.root}: frame {sequence}/{frame:06d}'s {key} is not the run's "
                                   f"{self.size[1]}x{self.size[0]}")
        lidar = self.path(index, "lidar", "bin")
        if os.path.isfile(lidar):
            label = self.path(index, "lidar_labels", "label")
            sample["lidar"], sample["lidar_labels"] = read_lidar(lidar, label if os.path.isfile(label) else None)
        return sample
