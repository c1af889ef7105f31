"""Reconstructs a tofsim NLOS capture with y-tal and draws it beside H and the
hidden scene: the picture in README.md, "Non-line-of-sight captures".

Not part of tofsim: the reconstruction needs y-tal (`pip install y-tal` in a
virtual environment of your own; it brings NumPy, SciPy and Matplotlib). The
reconstruction is y-tal's filtered back-projection with a phasor-field
wavelength of 4x the wall sampling (shared/research/nlos-capture-format.md,
section 6), over a volume in front of the wall's grid as deep as the
capture's light reaches, both read from the capture (its grid, time axis and
H: `reconstruction_setup`); the wall at z = 0 facing +z, as y-tal assumes.
The hidden scene is read from any glTF (indexed or not, any node transforms:
gltf_triangles.py). python/tests/test_nlos_ytal_script.py tests the mesh
reading and the setup without y-tal.

Usage: python nlos_reconstruct_ytal.py CAPTURE.hdf5 SCENE.gltf OUT.png [--wall NAME] [--step M]

The volume's step is the wall grid's spacing, coarsened to at most
MAX_VOXELS voxels: y-tal's back-projection holds ~85 kB a voxel, and the
64 x 64 wall of configs/nlos_confocal.yaml at its own spacing ran out of
24 GB.
"""

import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_triangles  # noqa: E402

# The light that counts as arriving: bins whose summed H is at least this
# fraction of the fullest bin's.
SIGNAL_FRACTION = 1e-3

# y-tal's back-projection holds some 85 kB a voxel (nlos_confocal's 64 x 64
# wall at its own spacing, 287,000 voxels, ran out of 24 GB): the default
# volume is coarsened to at most this many voxels (about 3 GB; 146 s on two
# shared cores). --step sets the step yourself.
MAX_VOXELS = 40_000


def hidden_triangles(gltf_path, wall):
    """World-space triangles of every node but the wall."""
    return gltf_triangles.triangles(gltf_path, skip=(wall,))


def signal_range_m(H, t_start, delta_t):
    """Optical path (m) of the first and the end of the last bin holding light."""
    per_bin = np.abs(np.asarray(H, float)).reshape(H.shape[0], -1).sum(axis=1)
    lit = np.nonzero(per_bin >= SIGNAL_FRACTION * per_bin.max())[0]
    return t_start + delta_t * lit[0], t_start + delta_t * (lit[-1] + 1)


def reconstruction_setup(H, sensor_grid_xyz, t_start, delta_t, legs_m=0.0):
    """(lo, hi, step, wavelength) in metres from a capture: x and y over the
    wall's sensor grid, z from the wall to half the longest lit path (a point
    at depth z is at least 2 z of path away: l -> x -> s), less the laser and
    sensor legs when the capture counts them (legs_m); step the grid's
    spacing; the phasor wavelength 4x the spacing (and at least 4 bins)."""
    grid = np.asarray(sensor_grid_xyz, float).reshape(-1, 3)
    lo_xy, hi_xy = grid[:, :2].min(axis=0), grid[:, :2].max(axis=0)
    g = np.asarray(sensor_grid_xyz, float)
    steps = [np.linalg.norm(np.diff(g, axis=a), axis=-1).mean()
             for a in (0, 1) if g.ndim == 3 and g.shape[a] > 1]
    spacing = min(steps) if steps else float(np.max(hi_xy - lo_xy)) or delta_t
    first, last = signal_range_m(H, t_start, delta_t)
    z_max = max((last - legs_m) / 2.0, 2 * spacing)
    lo = np.array([lo_xy[0], lo_xy[1], spacing])
    hi = np.array([hi_xy[0], hi_xy[1], z_max])
    wavelength = max(4.0 * spacing, 4.0 * delta_t)
    return lo, hi, spacing, wavelength


def volume_step(lo, hi, step, max_voxels=MAX_VOXELS):
    """The smallest whole multiple of `step` whose volume lo..hi holds at
    most max_voxels voxels (y-tal's memory grows with them)."""
    extent = np.maximum(np.asarray(hi, float) - np.asarray(lo, float), 0.0)
    factor = 1
    while np.prod(np.floor(extent / (step * factor)) + 1) > max_voxels:
        factor += 1
    return step * factor


def main():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import scipy.ndimage
    import tal

    ap = argparse.ArgumentParser()
    ap.add_argument("capture")
    ap.add_argument("scene")
    ap.add_argument("out")
    ap.add_argument("--wall", default="wall")
    ap.add_argument("--step", type=float, default=None,
                    help="voxel size in metres (default: the wall grid's spacing, coarsened "
                         "to at most %d voxels)" % MAX_VOXELS)
    a = ap.parse_args()

    d = tal.io.read_capture(a.capture)
    print("H", d.H.shape, d.H_format, "confocal", d.is_confocal(), "delta_t", d.delta_t)
    H = np.array(d.H)
    legs = 0.0
    if d.t_accounts_first_and_last_bounces:  # the shortest laser and sensor legs
        grid = np.asarray(d.sensor_grid_xyz, float).reshape(-1, 3)
        legs = (np.linalg.norm(np.asarray(d.laser_grid_xyz, float).reshape(-1, 3) - d.laser_xyz,
                               axis=1).min() + np.linalg.norm(grid - d.sensor_xyz, axis=1).min())
    lo, hi, step, wl = reconstruction_setup(H, d.sensor_grid_xyz, d.t_start, d.delta_t, legs)
    step = a.step if a.step else volume_step(lo, hi, step)
    print("volume", lo, "..", hi, "step %.4g m, wavelength %.4g m" % (step, wl))
    tal.reconstruct.compensate_laser_cos_dsqr(d)
    vol = tal.reconstruct.get_volume_min_max_resolution(lo, hi, step)
    t0 = time.time()
    R = tal.reconstruct.fbp.solve(d, wl_mean=wl, wl_sigma=wl / np.sqrt(2), volume_xyz=vol,
                                  camera_system=tal.enums.CameraSystem.DIRECT_LIGHT,
                                  compensate_invsq=True, progress=False)
    S = scipy.ndimage.gaussian_filter(np.abs(R), 0.03 / step)
    print("fbp: %.1f s" % (time.time() - t0))

    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    sy = H.shape[-1] // 2
    t_end = d.t_start + d.delta_t * H.shape[0]
    first, last = signal_range_m(H, d.t_start, d.delta_t)
    xt = H.reshape(H.shape[0], -1, H.shape[-2], H.shape[-1])[:, 0, :, sy]
    ax[0].imshow(xt, aspect="auto", origin="lower", cmap="magma",
                 extent=[lo[0], hi[0], d.t_start, t_end])
    ax[0].set(title="H: x-t slice at the wall's middle row", xlabel="x [m]",
              ylabel="optical path [m]", ylim=(first, last))
    tris = hidden_triangles(a.scene, a.wall)
    for tri in tris:
        depth = (tri[:, 2].mean() - lo[2]) / max(hi[2] - lo[2], 1e-9)
        ax[1].add_patch(plt.Polygon(tri[:, :2], color=plt.cm.viridis(depth)))
    ax[1].set(title="hidden scene (colour: depth %.2g-%.2g m)" % (lo[2], hi[2]),
              xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), xlabel="x [m]", ylabel="y [m]",
              aspect="equal")
    ax[2].imshow(S.max(axis=2).T, origin="lower", cmap="inferno", extent=[lo[0], hi[0], lo[1], hi[1]])
    ax[2].set(title="y-tal fbp reconstruction (max over depth)", xlabel="x [m]", ylabel="y [m]")
    plt.tight_layout()
    plt.savefig(a.out, dpi=70)
    print("wrote", a.out)


if __name__ == "__main__":
    main()
