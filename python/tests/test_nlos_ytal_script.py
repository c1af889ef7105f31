"""scripts/nlos_reconstruct_ytal.py (issue 44, item 10): its mesh reading on
glTF files as exporters write them (indexed, interleaved, nested transforms,
external and GLB buffers), which needs no y-tal, and its volume and
wavelength taken from the capture, not the example's; the reconstruction
itself runs only where y-tal is installed."""

import base64
import importlib
import json
import math
import os
import struct
import subprocess
import sys

import numpy as np
import pytest

from conftest import SOURCE_DIR

SCRIPTS = os.path.join(SOURCE_DIR, "scripts")
sys.path.insert(0, SCRIPTS)
gltf_triangles = importlib.import_module("gltf_triangles")
script = importlib.import_module("nlos_reconstruct_ytal")

# A unit quad in the xy plane, 4 vertices and 6 indices (as exporters write a
# quad), and the same quad's 6 vertices without indices.
QUAD = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
QUAD_INDICES = [0, 1, 2, 0, 2, 3]


def _document(blob_uri=None):
    """A glTF of three nodes: `wall` (non-indexed quad), `hidden` under a
    parent translated by (0, 0, 2), itself rotated 90 deg about y and scaled
    by 2 (an indexed quad in an interleaved position + normal buffer with
    unsigned short indices), and the bytes of its one buffer."""
    interleaved = b"".join(struct.pack("<3f3f", *p, 0, 0, 1) for p in QUAD)
    indices = struct.pack("<6H", *QUAD_INDICES)  # 12 bytes: the next view stays aligned
    flat = b"".join(struct.pack("<3f", *QUAD[i]) for i in QUAD_INDICES)
    blob = interleaved + indices + flat
    s = math.sqrt(0.5)
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"name": "wall", "mesh": 1},
            {"name": "parent", "translation": [0, 0, 2], "children": [2]},
            {"name": "hidden", "mesh": 0, "rotation": [0, s, 0, s], "scale": [2, 2, 2]},
        ],
        "meshes": [
            {"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]},
            {"primitives": [{"attributes": {"POSITION": 2}}]},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 6, "type": "VEC3"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 96, "byteStride": 24},
            {"buffer": 0, "byteOffset": 96, "byteLength": 12},
            {"buffer": 0, "byteOffset": 108, "byteLength": 72},
        ],
        "buffers": [{"byteLength": len(blob)}],
    }
    if blob_uri is not None:
        doc["buffers"][0]["uri"] = blob_uri
    return doc, blob


def _expected_hidden():
    # Rotation by 90 deg about y: (x, y, z) -> (z, y, -x); scale 2; then +2 in z.
    world = [(2 * z, 2 * y, -2 * x + 2) for x, y, z in QUAD]
    return np.array([world[i] for i in QUAD_INDICES], float).reshape(2, 3, 3)


def _write_embedded(path):
    doc, blob = _document()
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(
        blob).decode()
    path.write_text(json.dumps(doc))


def test_an_indexed_mesh_reads_in_world_space(tmp_path):
    path = tmp_path / "scene.gltf"
    _write_embedded(path)
    hidden = script.hidden_triangles(str(path), "wall")
    np.testing.assert_allclose(hidden, _expected_hidden(), atol=1e-6)
    everything = gltf_triangles.triangles(str(path))
    assert everything.shape == (4, 3, 3)
    wall = np.array([QUAD[i] for i in QUAD_INDICES], float).reshape(2, 3, 3)
    np.testing.assert_allclose(everything[:2], wall, atol=0)


def test_external_and_glb_buffers_read_the_same(tmp_path):
    doc, blob = _document("scene.bin")
    (tmp_path / "scene.bin").write_bytes(blob)
    (tmp_path / "scene.gltf").write_text(json.dumps(doc))
    np.testing.assert_allclose(gltf_triangles.triangles(str(tmp_path / "scene.gltf"), ("wall",)),
                               _expected_hidden(), atol=1e-6)
    doc, blob = _document()
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    glb = (struct.pack("<II", len(text), 0x4E4F534A) + text +
           struct.pack("<II", len(blob), 0x004E4942) + blob)
    (tmp_path / "scene.glb").write_bytes(struct.pack("<4sII", b"glTF", 2, 12 + len(glb)) + glb)
    np.testing.assert_allclose(gltf_triangles.triangles(str(tmp_path / "scene.glb"), ("wall",)),
                               _expected_hidden(), atol=1e-6)


def test_the_volume_and_wavelength_come_from_the_capture():
    # A 16 x 8 grid over a 0.8 x 0.4 m wall (5 cm apart) and 2 cm bins from
    # 0.1 m; light in bins 40 .. 59 only: path up to 0.1 + 60 x 0.02 = 1.3 m.
    xs = -0.4 + (np.arange(16) + 0.5) * 0.05
    ys = -0.2 + (np.arange(8) + 0.5) * 0.05
    grid = np.stack(np.meshgrid(xs, ys, indexing="ij") + [np.zeros((16, 8))], axis=-1)
    H = np.zeros((128, 16, 8), np.float32)
    H[40:60] = 1.0
    lo, hi, step, wavelength = script.reconstruction_setup(H, grid, 0.1, 0.02)
    np.testing.assert_allclose(lo, [xs[0], ys[0], 0.05])
    np.testing.assert_allclose(hi, [xs[-1], ys[-1], 1.3 / 2])
    assert step == pytest.approx(0.05)
    assert wavelength == pytest.approx(0.2)  # 4 x the grid's spacing
    # Counted laser and sensor legs are not depth.
    assert script.reconstruction_setup(H, grid, 0.1, 0.02, legs_m=0.5)[1][2] == pytest.approx(0.4)


def test_the_volume_is_coarsened_to_what_y_tal_can_hold():
    # A 64 x 64 wall 1 m wide at its own spacing, 1.08 m deep: 287,000 voxels.
    lo, hi, step = np.array([-0.49, -0.49, 0.0156]), np.array([0.49, 0.49, 1.095]), 0.015625
    coarse = script.volume_step(lo, hi, step)
    assert coarse == pytest.approx(2 * step)  # 32 x 32 x 35 voxels
    voxels = np.prod(np.floor((hi - lo) / coarse) + 1)
    assert voxels <= script.MAX_VOXELS
    assert np.prod(np.floor((hi - lo) / step) + 1) > script.MAX_VOXELS
    # A small volume keeps its step.
    assert script.volume_step(lo, lo + 0.1, step) == step


def test_y_tal_reconstructs_a_tofsim_capture(tmp_path):
    pytest.importorskip("tal", reason="y-tal (pip install y-tal) runs the reconstruction")
    tofsim = pytest.importorskip("tofsim")
    config = tofsim.load_config(os.path.join(SOURCE_DIR, "configs", "nlos_confocal.yaml"),
                                {"nlos.sensor_grid": [16, 16], "time.bins": 256,
                                 "time.bin_width": "1 cm", "render.indirect.rsm_resolution": 32})
    tofsim.render(config, output_dir=tmp_path / "out")
    out = tmp_path / "r.png"
    subprocess.run([sys.executable, os.path.join(SCRIPTS, "nlos_reconstruct_ytal.py"),
                    str(tmp_path / "out" / "capture.hdf5"),
                    os.path.join(SOURCE_DIR, "configs", "scenes", "nlos_letter.gltf"), str(out)],
                   check=True)
    assert out.stat().st_size > 0
