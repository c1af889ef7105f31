#!/usr/bin/env python3
"""The Cornell box demo scene rendered by mitransient (Mitsuba 3's transient
path tracer), for issue 27's equal-error protocol: 64x64 (or SIDE), the
demo's camera, a point light at the demo's light position (the camera plus
5 cm right), 20 ps bins from 1.5 m of optical path, box pixel filter,
near_clip 1e-5. Writes OUT (H, W, T, 3) float32 .npy and prints the
render's seconds. A measurement tool, run by hand in a venv with
mitransient (never a dependency of tofsim):

    python3 -m venv ~/mt && ~/mt/bin/pip install mitransient numpy
    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
      ~/mt/bin/python bench/equal_error/mitransient_cornell.py SPP MAX_DEPTH OUT.npy [SIDE] [BINS]
"""

import base64
import json
import os
import struct
import sys
import tempfile
import time

import drjit as dr
import mitsuba as mi

mi.set_variant("llvm_ad_rgb")
import mitransient  # noqa: E402,F401  (registers the transient plugins)
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
GLTF = os.path.join(HERE, "..", "..", "configs", "scenes", "cornell_box.gltf")
CAMERA = (0.278, 0.273, -0.8)  # cornell_camera, looking along +z
LIGHT_OFFSET_RIGHT = 0.05      # cornell_box.yaml: light.offset [0.05, 0, 0]
C = 299792458.0


def meshes_as_obj(folder):
    """(obj path, rgb) per glTF mesh: its float32 triangle list as an OBJ."""
    doc = json.load(open(GLTF))
    blob = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    out = []
    for m in doc["meshes"]:
        prim = m["primitives"][0]
        acc = doc["accessors"][prim["attributes"]["POSITION"]]
        view = doc["bufferViews"][acc["bufferView"]]
        n = acc["count"]
        xyz = struct.unpack_from(f"<{3 * n}f", blob, view.get("byteOffset", 0) + acc.get("byteOffset", 0))
        path = os.path.join(folder, m["name"] + ".obj")
        with open(path, "w") as f:
            for i in range(n):
                f.write(f"v {xyz[3 * i]!r} {xyz[3 * i + 1]!r} {xyz[3 * i + 2]!r}\n")
            for t in range(n // 3):
                f.write(f"f {3 * t + 1} {3 * t + 2} {3 * t + 3}\n")
        rgb = doc["materials"][prim["material"]]["pbrMetallicRoughness"]["baseColorFactor"][:3]
        out.append((path, rgb))
    return out


def scene(folder, side, bins, spp, max_depth):
    # The camera's right: looking along +z with +y up, right = forward x up = -x.
    light = (CAMERA[0] - LIGHT_OFFSET_RIGHT, CAMERA[1], CAMERA[2])
    d = {
        "type": "scene",
        "integrator": {"type": "transient_path", "max_depth": max_depth, "camera_unwarp": False,
                       "temporal_filter": "box"},
        "sensor": {
            "type": "perspective",
            "fov": 39.3076481,  # 2 atan(12.5 / 35), vertical = horizontal (square)
            "fov_axis": "y",
            "near_clip": 1e-5,
            "far_clip": 100.0,
            "to_world": mi.ScalarTransform4f().look_at(
                origin=CAMERA, target=(CAMERA[0], CAMERA[1], CAMERA[2] + 1.0), up=(0, 1, 0)),
            "sampler": {"type": "independent", "sample_count": spp},
            "film": {"type": "transient_hdr_film", "width": side, "height": side,
                     "temporal_bins": bins, "bin_width_opl": 20e-12 * C, "start_opl": 1.5,
                     "rfilter": {"type": "box"}},
        },
        "light": {"type": "point", "position": light, "intensity": {"type": "rgb", "value": [1, 1, 1]}},
    }
    for path, rgb in meshes_as_obj(folder):
        d[os.path.basename(path)[:-4]] = {
            "type": "obj", "filename": path, "face_normals": True,
            "bsdf": {"type": "twosided", "bsdf": {"type": "diffuse",
                                                   "reflectance": {"type": "rgb", "value": rgb}}}}
    return d


def main():
    spp, max_depth, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    side = int(sys.argv[4]) if len(sys.argv) > 4 else 64
    bins = int(sys.argv[5]) if len(sys.argv) > 5 else 371
    with tempfile.TemporaryDirectory() as folder:
        s = mi.load_dict(scene(folder, side, bins, spp, max_depth))
        start = time.time()
        _, transient = mi.render(s, spp=spp)  # steady, transient (mitransient's integrator)
        dr.eval(transient)  # Dr.Jit is lazy: the render runs here
        dr.sync_thread()
        seconds = time.time() - start
    v = np.array(transient, dtype=np.float32)  # (H, W, T, C)
    np.save(out, v)
    print(json.dumps({"spp": spp, "max_depth": max_depth, "seconds": seconds, "shape": list(v.shape)}))


if __name__ == "__main__":
    main()
