"""Shared by the module's tests: the closed-form plane scene and its config."""

import base64
import json
import math
import os
import struct

import pytest

SOURCE_DIR = os.environ.get(
    "TOFSIM_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
)

PLANE_ALBEDO = (0.5, 0.4, 0.3)


def write_plane_gltf(path, side=6.0, albedo=PLANE_ALBEDO, speed=None):
    """A square plane at z = 0 facing +z, centred on the origin (as
    tests/support/AnalyticScenes makePlane), as a self-contained glTF file.
    speed: the plane moves along -z at this many m/s over [0, 1] s (a LINEAR
    translation channel); None: no animation."""
    h = side / 2
    corners = [(-h, -h, 0.0), (h, -h, 0.0), (h, h, 0.0), (-h, h, 0.0)]
    positions = [corners[i] for i in (0, 1, 2, 0, 2, 3)]
    blob = b"".join(struct.pack("<3f", *p) for p in positions)
    blob += b"".join(struct.pack("<3f", 0.0, 0.0, 1.0) for _ in positions)
    if speed is not None:
        blob += struct.pack("<2f", 0.0, 1.0) + struct.pack("<6f", 0, 0, 0, 0, 0, -speed)
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "material": 0}]}],
        "materials": [
            {"pbrMetallicRoughness": {"baseColorFactor": [*albedo, 1.0], "metallicFactor": 0.0}}
        ],
        "buffers": [
            {
                "byteLength": len(blob),
                "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode(),
            }
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 72},
            {"buffer": 0, "byteOffset": 72, "byteLength": 72},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3",
             "min": [-h, -h, 0.0], "max": [h, h, 0.0]},
            {"bufferView": 1, "componentType": 5126, "count": 6, "type": "VEC3"},
        ],
    }
    if speed is not None:
        gltf["bufferViews"] += [
            {"buffer": 0, "byteOffset": 144, "byteLength": 8},
            {"buffer": 0, "byteOffset": 152, "byteLength": 24},
        ]
        gltf["accessors"] += [
            {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR",
             "min": [0.0], "max": [1.0]},
            {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"},
        ]
        gltf["animations"] = [{
            "samplers": [{"input": 2, "output": 3, "interpolation": "LINEAR"}],
            "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}],
        }]
    with open(path, "w") as f:
        json.dump(gltf, f)
    return str(path)


@pytest.fixture
def plane_config(tmp_path):
    """The plane of tests/render/DirectRenderGLTest.cpp as a config dict: a
    camera 1.5 m above it with a point light at the camera, 1200 bins of 2 mm
    optical path from 2.5 m. Point pixels (pixel_footprint off): the tests
    compare the bins of pixel centres' paths."""
    scene = write_plane_gltf(tmp_path / "plane.gltf")
    return {
        "scene": scene,
        "camera": {"position": [0, 0, 1.5], "look_at": [0.2, 0.1, 0], "fov_y": 60,
                   "resolution": [40, 30]},
        "light": {"type": "point", "position": [0, 0, 1.5], "intensity": [2.0, 1.0, 0.5]},
        "time": {"start": "2.5 m", "bin_width": "2 mm", "bins": 1200},
        "render": {"indirect": {"enabled": False}, "shadow_map_resolution": 256,
                   "pixel_footprint": False},
        "output": {"directory": str(tmp_path / "out")},
    }


def pixel_directions(position, look_at, fov_y_deg, width, height, up=(0.0, 1.0, 0.0)):
    """Unit ray through every pixel centre, (H, W, 3), as capture::Camera."""
    import numpy as np

    o = np.asarray(position, float)
    f = np.asarray(look_at, float) - o
    f /= np.linalg.norm(f)
    r = np.cross(f, up)
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    tan_half = math.tan(math.radians(fov_y_deg) / 2)
    x = (2 * (np.arange(width) + 0.5) / width - 1) * tan_half * width / height
    y = (1 - 2 * (np.arange(height) + 0.5) / height) * tan_half
    d = f + x[None, :, None] * r + y[:, None, None] * u
    return d / np.linalg.norm(d, axis=2, keepdims=True)
