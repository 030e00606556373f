"""SilvaDataset as a torch.utils.data.Dataset: images as CHW float tensors, labels as int64 tensors."""
import numpy as np
import torch
from torch.utils.data import Dataset

from .reader import SilvaDataset


class SilvaTorchDataset(Dataset):
    """Frames of a Silva dataset as dicts of tensors: rgb (3 x H x W float in [0, 1]), semantic and instance
    (H x W int64), depth (H x W float metres), normal (3 x H x W), K (3 x 3), camera_to_world (4 x 4)."""

    def __init__(self, root, transform=None):
        self.data = SilvaDataset(root)
        self.transform = transform

    def __len__(self):
        return len(self.data)

    def __getitem__(self, index):
        s = self.data[index]
        out = {"K": torch.from_numpy(s["K"]), "camera_to_world": torch.from_numpy(s["camera_to_world"])}
        if "rgb" in s:
            out["rgb"] = torch.from_numpy(s["rgb"]).permute(2, 0, 1).float() / 255.0
        for key in ("semantic", "instance"):
            if key in s:
                out[key] = torch.from_numpy(s[key].astype(np.int64))
        if "depth" in s:
            out["depth"] = torch.from_numpy(s["depth"])
        if "normal" in s:
            out["normal"] = torch.from_numpy(s["normal"]).permute(2, 0, 1)
        return self.transform(out) if self.transform else out
