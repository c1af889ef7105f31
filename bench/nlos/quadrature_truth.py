#!/usr/bin/env python3
"""The exact third bounce of bench/nlos's single scan, by quadrature: every
hidden quad of configs/scenes/nlos_letter.gltf cut into 1 mm elements, each
element's term of the closed form (shared/research/nlos-capture-format.md,
section 5: rho_l rho_x rho_s / pi^3 x pi E0 cos(theta_L) / d_L^2 x cos cos / r1^2
x cos cos / r2^2 x dA, summed over R, G, B) in the bin of its path r1 + r2, with
the letter occluding the patch on either leg. Neither renderer's code: the
truth both are measured against. NumPy only.

Usage: python3 quadrature_truth.py OUT.npy [element_m]
"""

import sys

import numpy as np

WALL_ALBEDO, HIDDEN_ALBEDO = 0.8, 0.9
LASER_ORIGIN = np.array([-0.5, 0.0, 0.25])
SENSOR_GRID, BINS, BIN_M = 32, 512, 0.01
# Hidden quads facing the wall (-z): (x0, x1, y0, y1, z), as make_nlos_letter.py.
QUADS = [(-0.2, 0.2, 0.1, 0.18, 0.5), (-0.04, 0.04, -0.2, 0.1, 0.5), (0.05, 0.25, -0.2, 0.0, 0.8)]
OCCLUDERS = QUADS[:2]  # the letter, between the wall and the patch


def elements(q, h):
    x0, x1, y0, y1, z = q
    nx, ny = max(1, round((x1 - x0) / h)), max(1, round((y1 - y0) / h))
    xs = x0 + (np.arange(nx) + 0.5) * (x1 - x0) / nx
    ys = y0 + (np.arange(ny) + 0.5) * (y1 - y0) / ny
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    p = np.stack([X.ravel(), Y.ravel(), np.full(X.size, z)], axis=1)
    return p, (x1 - x0) * (y1 - y0) / (nx * ny)


def unoccluded(a, b, z_of_b):
    """Segments a -> b (b: (N, 3), a: (3,) or (N, 3)) not crossing the letter."""
    ok = np.ones(len(b), bool)
    for x0, x1, y0, y1, z in OCCLUDERS:
        if z_of_b <= z:
            continue
        t = (z - (a[..., 2] if a.ndim > 1 else a[2])) / (b[:, 2] - (a[..., 2] if a.ndim > 1 else a[2]))
        p = a + t[:, None] * (b - a)
        ok &= ~((p[:, 0] >= x0) & (p[:, 0] <= x1) & (p[:, 1] >= y0) & (p[:, 1] <= y1))
    return ok


def main():
    out = sys.argv[1]
    h = float(sys.argv[2]) if len(sys.argv) > 2 else 0.001
    g = -0.5 + (np.arange(SENSOR_GRID) + 0.5) / SENSOR_GRID
    sensors = np.array([[x, y, 0.0] for x in g for y in g])  # x index major, as tal
    l = np.zeros(3)  # the laser spot: the wall's centre
    d_l = np.linalg.norm(LASER_ORIGIN - l)
    cos_L = LASER_ORIGIN[2] / d_l
    laser = np.pi * 1.0 * cos_L / d_l ** 2  # tal's projector, irradiance 1 per channel
    H = np.zeros((BINS, len(sensors)))
    rho = 3 * WALL_ALBEDO * HIDDEN_ALBEDO * WALL_ALBEDO / np.pi ** 3  # R + G + B
    for q in QUADS:
        x, dA = elements(q, h)
        r1v = x - l
        r1 = np.linalg.norm(r1v, axis=1)
        c1 = r1v[:, 2] / r1  # cos at l and at x (normals +z and -z)
        first = laser * c1 * c1 / r1 ** 2 * unoccluded(l, x, q[4])
        for i, s in enumerate(sensors):
            r2v = x - s
            r2 = np.linalg.norm(r2v, axis=1)
            c2 = r2v[:, 2] / r2
            w = rho * first * c2 * c2 / r2 ** 2 * dA * unoccluded(np.broadcast_to(s, x.shape), x, q[4])
            b = np.floor((r1 + r2) / BIN_M).astype(int)
            keep = (b >= 0) & (b < BINS)
            np.add.at(H[:, i], b[keep], w[keep])
    np.save(out, H.reshape(BINS, SENSOR_GRID, SENSOR_GRID).astype(np.float32))
    print("wrote", out, "energy", H.sum())


if __name__ == "__main__":
    main()
