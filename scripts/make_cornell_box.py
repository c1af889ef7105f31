#!/usr/bin/env python3
"""Writes configs/scenes/cornell_box.gltf: the Cornell box from the published
measurements, as a self-contained glTF 2.0 file (buffer embedded as base64).

Source: Cornell University Program of Computer Graphics, "Cornell Box Data"
(https://www.graphics.cornell.edu/online/box/data.html). Vertices there are in
millimetres; here they are converted to metres.

Handedness: the published frame has +y up and the camera at z = -800 looking
along +z, and the red wall (x ~ 556) appears on the LEFT of the image. That is
what a right-handed frame gives (right = forward x up = -x), so the vertices
are used unchanged; the glTF camera node is turned 180 deg about +y so that
its -Z looks along world +z, which puts +x on the image's left: red left,
green right, as in the published photographs. No mirroring, so no winding
change is needed for that; winding is still set per face below so that the
counter-clockwise side is the side the explicit normal points to.

Faces: walls, floor and ceiling face into the room (the ceiling is closed: no
light opening; tofsim uses point/spot lights). The blocks face outward; each
block also gets a bottom face on the floor so it is a closed solid (invisible,
but it keeps the blocks watertight). 5 x 2 + 2 x 6 x 2 = 34 triangles.

Glossy variant (--glossy, configs/scenes/cornell_box_glossy.gltf): the same
box with two surfaces for render.materials: gltf, keeping the published white
reflectance as their base colour: the floor a glossy dielectric (metallic 0,
roughness 0.25: a polished floor that mirrors the blocks and walls) and the
tall block a rough metal (metallic 1, roughness 0.35: its base colour is its
reflectance at normal incidence). Everything else is as in the diffuse box.

Standard library only. Usage: python3 scripts/make_cornell_box.py [--glossy] [out.gltf]
"""

import math
import sys

from gltf_common import add_camera, add_mesh, cross, dot, finish, new_gltf, normalize, sub, write_gltf

MM = 0.001  # metres per millimetre

# Diffuse reflectances (linear RGB), the commonly used values derived from the
# published spectral measurements.
MATERIALS = [
    ("white", (0.725, 0.71, 0.68)),
    ("red", (0.63, 0.065, 0.05)),
    ("green", (0.14, 0.45, 0.091)),
]

# The glossy variant's extra materials (name, rgb, metallic, roughness) and
# the groups that use them.
GLOSSY_MATERIALS = [
    ("white_glossy", (0.725, 0.71, 0.68), 0.0, 0.25),
    ("white_metal", (0.725, 0.71, 0.68), 1.0, 0.35),
]
GLOSSY_GROUPS = {"floor": "white_glossy", "tall_block": "white_metal"}

ROOM = [  # name, material, quad (mm), normal direction: "in" the room
    ("floor", "white", [(552.8, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 559.2), (549.6, 0.0, 559.2)]),
    ("ceiling", "white", [(556.0, 548.8, 0.0), (556.0, 548.8, 559.2), (0.0, 548.8, 559.2), (0.0, 548.8, 0.0)]),
    ("back_wall", "white", [(549.6, 0.0, 559.2), (0.0, 0.0, 559.2), (0.0, 548.8, 559.2), (556.0, 548.8, 559.2)]),
    ("right_wall_green", "green", [(0.0, 0.0, 559.2), (0.0, 0.0, 0.0), (0.0, 548.8, 0.0), (0.0, 548.8, 559.2)]),
    ("left_wall_red", "red", [(552.8, 0.0, 0.0), (549.6, 0.0, 559.2), (556.0, 548.8, 559.2), (556.0, 548.8, 0.0)]),
]

SHORT_TOP = [(130.0, 165.0, 65.0), (82.0, 165.0, 225.0), (240.0, 165.0, 272.0), (290.0, 165.0, 114.0)]
TALL_TOP = [(423.0, 330.0, 247.0), (265.0, 330.0, 296.0), (314.0, 330.0, 456.0), (472.0, 330.0, 406.0)]

# Camera: position (278, 273, -800) mm, looking along +z, up +y; 35 mm focal
# length, 25 mm x 25 mm film: vertical fov = 2 atan(12.5 / 35) = 39.3 deg.
CAMERA_POS_MM = (278.0, 273.0, -800.0)
FOCAL_MM, FILM_MM = 35.0, 25.0


def centroid(points):
    return tuple(sum(p[i] for p in points) / len(points) for i in range(3))


def block_faces(top):
    """Top, four sides and bottom of a block whose top quad is given (mm)."""
    bottom = [(x, 0.0, z) for (x, _, z) in top]
    faces = [top, list(reversed(bottom))]
    for i in range(4):
        j = (i + 1) % 4
        faces.append([bottom[i], top[i], top[j], bottom[j]])
    return faces


def triangles(quad, toward):
    """Two triangles (mm) of a quad, each wound counter-clockwise seen from the
    side `toward(centroid)` points to, with its own unit face normal (the
    published quads are not all exactly planar)."""
    out = []
    for tri in ((quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])):
        n = cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]))
        if dot(n, toward(centroid(quad))) < 0:
            tri = (tri[0], tri[2], tri[1])
            n = tuple(-x for x in n)
        out.append((tri, normalize(n)))
    return out


def build_groups():
    room_center = (278.0, 274.4, 279.6)
    groups = []  # (name, material, [(tri, normal)])
    for name, material, quad in ROOM:
        groups.append((name, material, triangles(quad, lambda c: sub(room_center, c))))
    for name, top in (("short_block", SHORT_TOP), ("tall_block", TALL_TOP)):
        center = centroid(top)
        center = (center[0], center[1] / 2, center[2])
        tris = []
        for face in block_faces(top):
            tris += triangles(face, lambda c, center=center: sub(c, center))
        groups.append((name, "white", tris))
    return groups


def build_gltf(glossy=False):
    groups = build_groups()
    materials = [(name, rgb, 0.0, 1.0) for name, rgb in MATERIALS]
    if glossy:
        materials += GLOSSY_MATERIALS
        groups = [(name, GLOSSY_GROUPS.get(name, material), tris) for name, material, tris in groups]
    material_index = {m[0]: i for i, m in enumerate(materials)}
    blob = bytearray()
    gltf = new_gltf("tofsim scripts/make_cornell_box.py", "cornell_box", materials,
                    "Geometry and camera: Cornell University Program of Computer Graphics, Cornell Box data")
    for name, material, tris in groups:
        positions = [tuple(round(c * MM, 6) for c in p) for tri, _ in tris for p in tri]
        normals = [tuple(round(c, 6) for c in n) for _, n in tris for _ in range(3)]
        add_mesh(gltf, blob, name, material_index[material], positions, normals)

    half_film = FILM_MM / 2
    # 180 deg about +y: the camera's -Z looks along world +z.
    add_camera(gltf, "cornell_camera", 2 * math.atan(half_film / FOCAL_MM),
               [c * MM for c in CAMERA_POS_MM], [0.0, 1.0, 0.0, 0.0])
    return finish(gltf, blob)


def main():
    glossy = "--glossy" in sys.argv[1:]
    if glossy:
        sys.argv.remove("--glossy")
    write_gltf(build_gltf(glossy), "cornell_box_glossy.gltf" if glossy else "cornell_box.gltf")


if __name__ == "__main__":
    main()
