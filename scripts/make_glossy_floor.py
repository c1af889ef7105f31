#!/usr/bin/env python3
"""Writes configs/scenes/glossy_floor.gltf: a polished floor in front of a
wall, the textbook case of ToF multipath from a glossy reflection
(configs/glossy_floor.yaml), as a self-contained glTF 2.0 file (buffer
embedded as base64). Metres, glTF frame (+y up). No third-party data.

  floor:  the plane y = 0, x in [-1.5, 1.5], z in [-3, 0.5], facing +y: a
          glossy dielectric (base colour 0.35 grey, metallic 0, roughness 0.2)
  wall:   the plane z = -3, x in [-1.5, 1.5], y in [0, 2], facing +z: diffuse
          (base colour 0.7 grey, metallic 0, roughness 1; render it with
          render.materials: gltf, as the config does, or as Lambertian)

The camera sees the floor at grazing angles, where the floor's Fresnel lobe
mirrors the lit wall: light -> wall -> floor -> camera is longer than the
direct return from the floor, so the CW-ToF depth of the floor comes out too
far, and the wall's bottom is lit again through the floor.
Camera `floor_camera`: at (0, 0.6, 0) m looking at (0, 0.5, -3), 50 deg
vertical fov. 4 triangles.

Standard library only. Usage: python3 scripts/make_glossy_floor.py [out.gltf]
"""

import math

from gltf_common import add_camera, add_quads, finish, look_rotation, new_gltf, sub, write_gltf

# name, rgb, metallic, roughness
MATERIALS = [("floor_polished", (0.35, 0.35, 0.35), 0.0, 0.2),
             ("wall_matte", (0.7, 0.7, 0.7), 0.0, 1.0)]

# name, material, quad corners counter-clockwise seen from the lit side, normal
QUADS = [
    ("floor", 0, [(-1.5, 0, -3), (-1.5, 0, 0.5), (1.5, 0, 0.5), (1.5, 0, -3)], (0, 1, 0)),
    ("wall", 1, [(-1.5, 0, -3), (1.5, 0, -3), (1.5, 2, -3), (-1.5, 2, -3)], (0, 0, 1)),
]

CAMERA_POS = (0.0, 0.6, 0.0)
CAMERA_TARGET = (0.0, 0.5, -3.0)
FOV_Y_DEG = 50.0


def build_gltf():
    blob = bytearray()
    gltf = new_gltf("tofsim scripts/make_glossy_floor.py", "glossy_floor", MATERIALS)
    add_quads(gltf, blob, QUADS)
    add_camera(gltf, "floor_camera", math.radians(FOV_Y_DEG), CAMERA_POS,
               look_rotation(sub(CAMERA_TARGET, CAMERA_POS)))
    return finish(gltf, blob)


def main():
    write_gltf(build_gltf(), "glossy_floor.gltf")


if __name__ == "__main__":
    main()
