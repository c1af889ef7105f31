#!/usr/bin/env python3
"""Reconstructs a tofsim NLOS capture with y-tal and draws it beside H and the
hidden scene: the picture in README.md, "Non-line-of-sight captures".

Not part of tofsim and not run by its tests: it needs y-tal (`pip install
y-tal` in a virtual environment of your own; it brings NumPy, SciPy and
Matplotlib). The reconstruction is y-tal's filtered back-projection with
phasor-field wavelengths about 4x the wall sampling
(shared/research/nlos-capture-format.md, section 6), on a wall at z = 0
facing +z, as y-tal assumes.

Usage: python nlos_reconstruct_ytal.py CAPTURE.hdf5 SCENE.gltf OUT.png [--wall NAME]
"""

import argparse
import base64
import json
import struct
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import scipy.ndimage  # noqa: E402
import tal  # noqa: E402


def hidden_triangles(gltf_path, wall):
    """World-space triangles of every node but the wall (translation-only nodes,
    as scripts/make_nlos_letter.py writes them)."""
    with open(gltf_path) as f:
        g = json.load(f)
    blob = base64.b64decode(g["buffers"][0]["uri"].split(",", 1)[1])
    tris = []
    for node in g["nodes"]:
        if "mesh" not in node or node.get("name") == wall:
            continue
        offset = np.array(node.get("translation", [0, 0, 0]), float)
        for prim in g["meshes"][node["mesh"]]["primitives"]:
            acc = g["accessors"][prim["attributes"]["POSITION"]]
            view = g["bufferViews"][acc["bufferView"]]
            start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
            p = np.array(struct.unpack_from("<%df" % (3 * acc["count"]), blob, start)).reshape(-1, 3)
            tris.extend((p + offset).reshape(-1, 3, 3))
    return tris


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("capture")
    ap.add_argument("scene")
    ap.add_argument("out")
    ap.add_argument("--wall", default="wall")
    a = ap.parse_args()

    d = tal.io.read_capture(a.capture)
    print("H", d.H.shape, d.H_format, "confocal", d.is_confocal(), "delta_t", d.delta_t)
    H = np.array(d.H)
    tal.reconstruct.compensate_laser_cos_dsqr(d)
    lo, hi, step = np.array([-0.45, -0.45, 0.3]), np.array([0.45, 0.45, 1.0]), 0.025
    vol = tal.reconstruct.get_volume_min_max_resolution(lo, hi, step)
    t0 = time.time()
    R = tal.reconstruct.fbp.solve(d, wl_mean=0.12, wl_sigma=0.12 / np.sqrt(2), volume_xyz=vol,
                                  camera_system=tal.enums.CameraSystem.DIRECT_LIGHT,
                                  compensate_invsq=True, progress=False)
    S = scipy.ndimage.gaussian_filter(np.abs(R), 0.03 / step)
    print("fbp: %.1f s" % (time.time() - t0))

    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    sy = H.shape[2] // 2
    t_end = d.t_start + d.delta_t * H.shape[0]
    ax[0].imshow(H[:, :, sy], aspect="auto", origin="lower", cmap="magma",
                 extent=[-0.5, 0.5, d.t_start, t_end])
    ax[0].set(title="H: x-t slice at the wall's middle row", xlabel="x [m]", ylabel="optical path [m]",
              ylim=(0.8, 2.4))
    for tri in hidden_triangles(a.scene, a.wall):
        ax[1].add_patch(plt.Polygon(tri[:, :2], color=plt.cm.viridis((tri[:, 2].mean() - 0.3) / 0.7)))
    ax[1].set(title="hidden scene (colour: depth 0.3-1 m)", xlim=(-0.45, 0.45), ylim=(-0.45, 0.45),
              xlabel="x [m]", ylabel="y [m]", aspect="equal")
    ax[2].imshow(S.max(axis=2).T, origin="lower", cmap="inferno", extent=[lo[0], hi[0], lo[1], hi[1]])
    ax[2].set(title="y-tal fbp reconstruction (max over depth)", xlabel="x [m]", ylabel="y [m]")
    plt.tight_layout()
    plt.savefig(a.out, dpi=70)
    print("wrote", a.out)


if __name__ == "__main__":
    main()
