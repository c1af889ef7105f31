#!/usr/bin/env python3
"""Writes configs/scenes/corner.gltf: a concave corner for multipath studies,
two walls meeting at a right angle plus a floor, as a self-contained glTF 2.0
file (buffer embedded as base64). Metres, glTF frame (+y up).

  wall_x:  the plane x = 0, z in [0, 2], y in [0, 2], facing +x
  wall_z:  the plane z = 0, x in [0, 2], y in [0, 2], facing +z
  floor:   the plane y = 0, x and z in [0, 2], facing +y

All three are Lambertian grey (albedo 0.7 walls, 0.5 floor): a CW-ToF camera
looking into the corner sees each wall lit directly and again by light from
the other wall and the floor, the textbook case of multipath interference.
Camera `corner_camera`: at (1.6, 1.2, 1.6) m looking at (0, 0.6, 0), 50 deg
vertical fov. 6 triangles.

Standard library only. Usage: python3 scripts/make_corner.py [out.gltf]
"""

from gltf_common import sub
from gltf_writer import write_quad_scene

MATERIALS = [("wall_grey", (0.7, 0.7, 0.7)), ("floor_grey", (0.5, 0.5, 0.5))]

# name, material, quad corners counter-clockwise seen from the lit side, normal
QUADS = [
    ("wall_x", 0, [(0, 0, 2), (0, 0, 0), (0, 2, 0), (0, 2, 2)], (1, 0, 0)),
    ("wall_z", 0, [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], (0, 0, 1)),
    ("floor", 1, [(0, 0, 0), (0, 0, 2), (2, 0, 2), (2, 0, 0)], (0, 1, 0)),
]

CAMERA_POS = (1.6, 1.2, 1.6)
CAMERA_TARGET = (0.0, 0.6, 0.0)
# name, vertical fov (deg), position, view direction
CAMERA = ("corner_camera", 50.0, CAMERA_POS, sub(CAMERA_TARGET, CAMERA_POS))

if __name__ == "__main__":
    write_quad_scene("corner.gltf", "make_corner.py", "corner", MATERIALS, QUADS, CAMERA)
