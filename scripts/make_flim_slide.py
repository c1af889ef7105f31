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

from gltf_writer import rect_facing_z, write_quad_scene

MATERIALS = [("background", (0.5, 0.5, 0.5)), ("dye_short", (0.1, 0.6, 0.1)),
             ("dye_long", (0.1, 0.6, 0.1))]

# A scene's own delay in its extras: what the config's entry replaces.
EXTRAS = {"dye_long": {"scattering_delay": {"model": "exponential", "lifetime": "3.5 ns",
                                            "fraction": 0.9}}}


# name, material, quad corners counter-clockwise seen from the lit side, normal
QUADS = [
    ("card", 0, rect_facing_z(-0.05, 0.05, -0.05, 0.05, 0.0), (0, 0, 1)),
    ("dye_a", 1, rect_facing_z(-0.04, -0.01, -0.015, 0.015, 0.001), (0, 0, 1)),
    ("dye_b", 2, rect_facing_z(0.01, 0.04, -0.015, 0.015, 0.001), (0, 0, 1)),
]

# name, vertical fov (deg), position, view direction
CAMERA = ("flim_camera", 30.0, (0.0, 0.0, 0.2), (0.0, 0.0, -1.0))

if __name__ == "__main__":
    write_quad_scene("flim_slide.gltf", "make_flim_slide.py", "flim_slide", MATERIALS, QUADS,
                     CAMERA, extras=EXTRAS)
