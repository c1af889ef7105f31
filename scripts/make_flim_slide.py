#!/usr/bin/env python3
"""Writes configs/scenes/flim_slide.gltf: a flat sample for fluorescence-
lifetime imaging (configs/flim_spad.yaml), two fluorophore patches on a
prompt background card, as a self-contained glTF 2.0 file (buffer embedded
as base64). Metres, glTF frame (+y up).

  card:    the plane z = 0, x and y in [-0.05, 0.05], facing +z, material
           `background` (grey 0.5: prompt scatter)
  dye_a:   a 30 mm x 30 mm patch at x in [-0.04, -0.01], y in [-0.015, 0.015],
           1 mm in front of the card, material `dye_short`
  dye_b:   the same at x in [0.01, 0.04], material `dye_long`

The dyes' base colour is (0.1, 0.6, 0.1): they take up the green laser's
light. Their lifetimes (1.2 ns and 3.5 ns) and their green-to-red
re-emission are set by the config's `materials:` (configs/README.md,
"materials"); the glTF itself carries `dye_long`'s in its extras, the form a
scene uses to carry its own (the config's entry replaces it).
Camera `flim_camera`: at (0, 0, 0.2) m looking down -z at the card, 30 deg
vertical fov. 6 triangles.

Standard library only. Usage: python3 scripts/make_flim_slide.py [out.gltf]
"""

import math

from gltf_common import add_camera, add_quads, finish, look_rotation, new_gltf, write_gltf

MATERIALS = [("background", (0.5, 0.5, 0.5)), ("dye_short", (0.1, 0.6, 0.1)),
             ("dye_long", (0.1, 0.6, 0.1))]

# A scene's own delay in its extras: what the config's entry replaces.
EXTRAS = {"dye_long": {"scattering_delay": {"model": "exponential", "lifetime": "3.5 ns",
                                            "fraction": 0.9}}}


def patch(x0, x1, y0, y1, z):
    return [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]


# name, material, quad corners counter-clockwise seen from the lit side, normal
QUADS = [
    ("card", 0, patch(-0.05, 0.05, -0.05, 0.05, 0.0), (0, 0, 1)),
    ("dye_a", 1, patch(-0.04, -0.01, -0.015, 0.015, 0.001), (0, 0, 1)),
    ("dye_b", 2, patch(0.01, 0.04, -0.015, 0.015, 0.001), (0, 0, 1)),
]

CAMERA_POS = (0.0, 0.0, 0.2)
FOV_Y_DEG = 30.0


def build_gltf():
    blob = bytearray()
    materials = [(name, rgb, 0.0, 1.0) for name, rgb in MATERIALS]
    gltf = new_gltf("tofsim scripts/make_flim_slide.py", "flim_slide", materials)
    for m in gltf["materials"]:
        if m["name"] in EXTRAS:
            m["extras"] = EXTRAS[m["name"]]
    add_quads(gltf, blob, QUADS)
    add_camera(gltf, "flim_camera", math.radians(FOV_Y_DEG), CAMERA_POS,
               look_rotation((0.0, 0.0, -1.0)))
    return finish(gltf, blob)


def main():
    write_gltf(build_gltf(), "flim_slide.gltf")


if __name__ == "__main__":
    main()
