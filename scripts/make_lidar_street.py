#!/usr/bin/env python3
"""Writes configs/scenes/lidar_street.gltf: a small street for the spinning
lidar of configs/lidar_street.yaml, as a self-contained glTF 2.0 file (buffer
embedded as base64). Metres, glTF frame (+y up); the street runs along x.

  ground:     y = 0, x and z in [-30, 30], asphalt (albedo 0.12)
  buildings:  four boxes, two on each side of the street (z beyond +-8),
              6 to 15 m high, concrete 0.45 and brick 0.3
  car:        a 4.5 x 1.5 x 1.8 m box at x in [4, 8.5], z in [1, 2.8], white 0.7
  posts:      six 0.2 x 4 x 0.2 m posts along the kerbs (z = +-6.5), 0.6
  kerb wall:  a 0.5 m high wall along z = -7.5 for x in [-20, 0], 0.45

Boxes have no bottom face: 5 quads each (the renderers' surfaces are
two-sided). About 130 triangles. The glTF writer is scripts/gltf_common.py's.

Standard library only. Usage: python3 scripts/make_lidar_street.py [out.gltf]
"""

from gltf_common import add_quads, finish, new_gltf, write_gltf

MATERIALS = [
    ("asphalt", (0.12, 0.12, 0.12)),
    ("concrete", (0.45, 0.45, 0.45)),
    ("brick", (0.30, 0.18, 0.14)),
    ("car_paint", (0.7, 0.7, 0.7)),
    ("post_paint", (0.6, 0.6, 0.6)),
]
ASPHALT, CONCRETE, BRICK, CAR, POST = range(5)

# name, material, (x0, x1), (y0, y1), (z0, z1)
BOXES = [
    ("building_nw", CONCRETE, (-30, -6), (0, 12), (-20, -9)),
    ("building_ne", BRICK, (-2, 22), (0, 15), (-18, -9)),
    ("building_sw", BRICK, (-25, -3), (0, 6), (9, 16)),
    ("building_se", CONCRETE, (2, 28), (0, 9), (10, 22)),
    ("car", CAR, (4, 8.5), (0, 1.5), (1, 2.8)),
    ("kerb_wall", CONCRETE, (-20, 0), (0, 0.5), (-7.7, -7.5)),
]
POSTS = [(-12, -6.5), (-4, -6.5), (10, -6.5), (-9, 6.5), (3, 6.5), (14, 6.5)]


def box_quads(name, material, xs, ys, zs):
    """The box's four sides and its top, counter-clockwise seen from outside."""
    (x0, x1), (y0, y1), (z0, z1) = xs, ys, zs
    return [
        (name + "_px", material, [(x1, y0, z1), (x1, y0, z0), (x1, y1, z0), (x1, y1, z1)], (1, 0, 0)),
        (name + "_nx", material, [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)], (-1, 0, 0)),
        (name + "_pz", material, [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)], (0, 0, 1)),
        (name + "_nz", material, [(x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0)], (0, 0, -1)),
        (name + "_top", material, [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)], (0, 1, 0)),
    ]


def build_gltf():
    blob = bytearray()
    materials = [(name, rgb, 0.0, 1.0) for name, rgb in MATERIALS]
    gltf = new_gltf("tofsim scripts/make_lidar_street.py", "lidar_street", materials)
    quads = [("ground", ASPHALT, [(-30, 0, -30), (-30, 0, 30), (30, 0, 30), (30, 0, -30)], (0, 1, 0))]
    for name, material, xs, ys, zs in BOXES:
        quads += box_quads(name, material, xs, ys, zs)
    for i, (x, z) in enumerate(POSTS):
        quads += box_quads("post%d" % i, POST, (x - 0.1, x + 0.1), (0, 4), (z - 0.1, z + 0.1))
    add_quads(gltf, blob, quads)
    return finish(gltf, blob)


def main():
    write_gltf(build_gltf(), "lidar_street.gltf")


if __name__ == "__main__":
    main()
