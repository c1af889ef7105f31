#!/usr/bin/env python3
"""Writes configs/scenes/fog_box.gltf: a closed box for fog (issue 42's
fog box, configs/fog_box.yaml, bench/fog_box/), as a self-contained glTF 2.0
file (buffer embedded as base64). Metres, glTF frame (+y up).

  walls: the six faces of the cube [-1, 1]^3, each facing inward (no ray
         from inside leaves the box), material `wall` (Lambertian grey 0.6)

The box of bench/reference_fog's tofsim_reference_fog_box (tests/support
makeClosedBox(2, 0.6)). Camera `box_camera`: at (0, 0, 0.9) m looking down
-z at the far wall, 60 deg vertical fov. The fog is the config's `medium:`.
12 triangles.

Standard library only. Usage: python3 scripts/make_fog_box.py [out.gltf]
"""

from gltf_writer import write_quad_scene

MATERIALS = [("wall", (0.6, 0.6, 0.6))]

# name, material, quad corners counter-clockwise seen from inside, inward normal
QUADS = [
    ("back", 0, [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1)], (0, 0, 1)),
    ("front", 0, [(1, -1, 1), (-1, -1, 1), (-1, 1, 1), (1, 1, 1)], (0, 0, -1)),
    ("left", 0, [(-1, -1, 1), (-1, -1, -1), (-1, 1, -1), (-1, 1, 1)], (1, 0, 0)),
    ("right", 0, [(1, -1, -1), (1, -1, 1), (1, 1, 1), (1, 1, -1)], (-1, 0, 0)),
    ("floor", 0, [(-1, -1, 1), (1, -1, 1), (1, -1, -1), (-1, -1, -1)], (0, 1, 0)),
    ("ceiling", 0, [(-1, 1, -1), (1, 1, -1), (1, 1, 1), (-1, 1, 1)], (0, -1, 0)),
]

# name, vertical fov (deg), position, view direction
CAMERA = ("box_camera", 60.0, (0.0, 0.0, 0.9), (0.0, 0.0, -1.0))

if __name__ == "__main__":
    write_quad_scene("fog_box.gltf", "make_fog_box.py", "fog_box", MATERIALS, QUADS, CAMERA)
