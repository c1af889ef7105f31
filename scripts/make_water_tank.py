#!/usr/bin/env python3
"""Writes configs/scenes/water_tank.gltf: a small tank of water with a target
inside (issue 42's per-region media, configs/water_tank.yaml), as a
self-contained glTF 2.0 file (buffer embedded as base64). Metres, glTF frame
(+y up).

  water_tank: the water's region, one closed mesh of 12 triangles wound
              outwards, the box x in [-0.4, 0.4], y in [0.002, 0.5],
              z in [-1.4, -0.6] m. The config's `media:` names it; the
              renderers take it out of the surfaces (an interface: no glass).
  target:     a white board (albedo 0.8) 0.3 m square inside the tank at
              z = -1.1, facing +z, its centre 0.25 m high
  floor:      a grey floor (0.5) at y = 0 under everything, 4 m square
  back:       a grey wall (0.5) at z = -2.5 facing +z, 4 m wide, 2 m high

Camera `lidar_camera`: at (0, 0.35, 0.8) m looking at (0, 0.25, -1.1), 30 deg
vertical fov (the light sits at its pinhole in the config: a lidar's view).

Standard library only. Usage: python3 scripts/make_water_tank.py [out.gltf]
"""

import math

from gltf_common import (add_camera, add_mesh, add_quads, cross, finish, look_rotation,
                         new_gltf, normalize, sub, write_gltf)

MATERIALS = [("water", (1.0, 1.0, 1.0), 0.0, 1.0), ("white", (0.8, 0.8, 0.8), 0.0, 1.0),
             ("grey", (0.5, 0.5, 0.5), 0.0, 1.0)]

TANK_LO = (-0.4, 0.002, -1.4)
TANK_HI = (0.4, 0.5, -0.6)

# name, material, quad corners counter-clockwise seen from the lit side, normal
QUADS = [
    ("target", 1, [(-0.15, 0.1, -1.1), (0.15, 0.1, -1.1), (0.15, 0.4, -1.1), (-0.15, 0.4, -1.1)],
     (0, 0, 1)),
    ("floor", 2, [(-2, 0, 1), (2, 0, 1), (2, 0, -2.5), (-2, 0, -2.5)], (0, 1, 0)),
    ("back", 2, [(-2, 0, -2.5), (2, 0, -2.5), (2, 2, -2.5), (-2, 2, -2.5)], (0, 0, 1)),
]

CAMERA_POS = (0.0, 0.35, 0.8)
LOOK_AT = (0.0, 0.25, -1.1)
FOV_Y_DEG = 30.0


def box_triangles(lo, hi):
    """The box's 12 triangles, each wound outwards (normal away from the centre)."""
    corner = [(hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2])
              for i in range(8)]
    centre = tuple((a + b) / 2 for a, b in zip(lo, hi))
    faces = [(0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5)]
    triangles = []
    for f in faces:
        for t in ((f[0], f[1], f[2]), (f[0], f[2], f[3])):
            a, b, c = (corner[i] for i in t)
            mid = tuple((x + y + z) / 3 for x, y, z in zip(a, b, c))
            n = cross(sub(b, a), sub(c, a))
            out = sum(p * q for p, q in zip(n, sub(mid, centre))) > 0
            triangles.append((a, b, c) if out else (a, c, b))
    return triangles


def main():
    blob = bytearray()
    gltf = new_gltf("tofsim scripts/make_water_tank.py", "water_tank", MATERIALS)
    positions, normals = [], []
    for a, b, c in box_triangles(TANK_LO, TANK_HI):
        n = normalize(cross(sub(b, a), sub(c, a)))
        positions += [tuple(float(x) for x in p) for p in (a, b, c)]
        normals += [n] * 3
    add_mesh(gltf, blob, "water_tank", 0, positions, normals)
    add_quads(gltf, blob, QUADS)
    forward = normalize(sub(LOOK_AT, CAMERA_POS))
    add_camera(gltf, "lidar_camera", math.radians(FOV_Y_DEG), CAMERA_POS, look_rotation(forward))
    write_gltf(finish(gltf, blob), "water_tank.gltf")


if __name__ == "__main__":
    main()
