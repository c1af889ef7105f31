#!/usr/bin/env python3
"""Writes configs/scenes/fog_range.gltf: a lidar test range for fog
(configs/fog_lidar.yaml), two boards down a lane over a floor, as a
self-contained glTF 2.0 file (buffer embedded as base64). Metres, glTF frame
(+y up); the sensor looks down -z.

  floor:      the plane y = 0, x in [-3, 3], z in [-16, 0], facing +y,
              material `asphalt` (grey 0.2)
  near_board: 1.2 m x 1.2 m facing +z at z = -6, x in [-1.3, -0.1],
              y in [0.4, 1.6], material `board` (white 0.8)
  far_board:  1.4 m x 1.6 m facing +z at z = -12, x in [0.1, 1.5],
              y in [0.2, 1.8], material `board`; the near board does not
              hide it from the camera
Camera `fog_camera`: at (0, 1, 0) m looking down -z, 24 deg vertical fov
(the far board fills its right half-width at 12 m). Every material
Lambertian (metallic 0, roughness 1); the fog itself is the config's
`medium:`, not the scene's. 6 triangles.

Standard library only. Usage: python3 scripts/make_fog_range.py [out.gltf]
"""

from gltf_writer import rect_facing_z, write_quad_scene

MATERIALS = [("asphalt", (0.2, 0.2, 0.2)), ("board", (0.8, 0.8, 0.8))]

# name, material, quad corners counter-clockwise seen from the lit side, normal
QUADS = [
    ("floor", 0, [(-3.0, 0.0, 0.0), (3.0, 0.0, 0.0), (3.0, 0.0, -16.0), (-3.0, 0.0, -16.0)],
     (0, 1, 0)),
    ("near_board", 1, rect_facing_z(-1.3, -0.1, 0.4, 1.6, -6.0), (0, 0, 1)),
    ("far_board", 1, rect_facing_z(0.1, 1.5, 0.2, 1.8, -12.0), (0, 0, 1)),
]

# name, vertical fov (deg), position, view direction
CAMERA = ("fog_camera", 24.0, (0.0, 1.0, 0.0), (0.0, 0.0, -1.0))

if __name__ == "__main__":
    write_quad_scene("fog_range.gltf", "make_fog_range.py", "fog_range", MATERIALS, QUADS, CAMERA)
