#!/usr/bin/env python3
"""Writes configs/scenes/nlos_letter.gltf: a non-line-of-sight test scene, a
relay wall with a hidden letter T and a square patch behind it, as a
self-contained glTF 2.0 file (buffer embedded as base64). Metres, glTF frame
(+y up), the relay wall in y-tal's frame (the plane z = 0, facing +z).

  wall:    the plane z = 0, x and y in [-0.5, 0.5], facing +z, albedo 0.8
  letter:  a T at z = 0.5 facing the wall (-z): bar x in [-0.2, 0.2],
           y in [0.1, 0.18]; stem x in [-0.04, 0.04], y in [-0.2, 0.1]; albedo 0.9
  patch:   a 0.2 m square at z = 0.8 centred on (0.15, -0.1), facing -z,
           albedo 0.9, partly hidden from the wall by the letter's stem

Nothing of it is seen from the sensor and laser at (-0.5, 0, 0.25)
(configs/nlos_confocal.yaml) except the wall. 8 triangles.

Standard library only. Usage: python3 scripts/make_nlos_letter.py [out.gltf]
"""

from gltf_common import add_quads, finish, new_gltf, write_gltf

MATERIALS = [("wall_white", (0.8, 0.8, 0.8)), ("hidden_white", (0.9, 0.9, 0.9))]


def facing_wall(name, x0, x1, y0, y1, z):
    """A rectangle in the plane z, counter-clockwise seen from -z (the wall)."""
    return (name, 1, [(x1, y0, z), (x0, y0, z), (x0, y1, z), (x1, y1, z)], (0, 0, -1))


QUADS = [
    ("wall", 0, [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)], (0, 0, 1)),
    facing_wall("letter_bar", -0.2, 0.2, 0.1, 0.18, 0.5),
    facing_wall("letter_stem", -0.04, 0.04, -0.2, 0.1, 0.5),
    facing_wall("patch", 0.05, 0.25, -0.2, 0.0, 0.8),
]


def build_gltf():
    blob = bytearray()
    materials = [(name, rgb, 0.0, 1.0) for name, rgb in MATERIALS]
    gltf = new_gltf("tofsim scripts/make_nlos_letter.py", "nlos_letter", materials)
    add_quads(gltf, blob, QUADS)
    return finish(gltf, blob)


def main():
    write_gltf(build_gltf(), "nlos_letter.gltf")


if __name__ == "__main__":
    main()
