"""Read a Silva dataset (docs/CONTRACT.md "Dataset layout") with numpy and OpenCV only.

    from silva_dataset import SilvaDataset
    ds = SilvaDataset("out/1234567890")
    sample = ds[0]            # dict of numpy arrays: rgb, semantic, instance, depth, normal, K, ...

`SilvaTorchDataset` wraps it as a torch.utils.data.Dataset when torch is importable.
"""
import os

# OpenCV reads EXR only when this is set before cv2 is imported.
os.environ.setdefault("OPENCV_IO_ENABLE_OPENEXR", "1")

from .reader import (  # noqa: E402
    DatasetError,
    SilvaDataset,
    read_camera,
    read_depth,
    read_instance_table,
    read_label,
    read_lidar,
    read_normal,
    read_rgb,
)

__all__ = [
    "DatasetError",
    "SilvaDataset",
    "read_camera",
    "read_depth",
    "read_instance_table",
    "read_label",
    "read_lidar",
    "read_normal",
    "read_rgb",
]

try:
    from .torch_dataset import SilvaTorchDataset  # noqa: F401

    __all__.append("SilvaTorchDataset")
except ImportError:  # torch is optional
    pass
