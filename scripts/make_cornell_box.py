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

Retro-reflector variant (--retro, configs/scenes/cornell_box_retro.gltf): the
diffuse box with a small bright plate at its opening, facing the camera, on a
thin post standing on the floor's front edge, for configs/spad_lidar.yaml's
crosstalk halo. The plate (`retro_reflector`, RETRO_* below) is white of
albedo 1 (every photon reflected, diffusely: tofsim has no retro-reflective
BRDF, so this is the brightest plate its materials give), nearer than the
walls and lit by the spot's centre: about twice the counts of the back wall
behind it in spad_lidar. Everything else is the diffuse box, byte for byte in
its meshes.

Moving-block variant (--moving, configs/scenes/cornell_box_moving.gltf): the
diffuse box, byte for byte in its meshes, whose short block slides MOVING_SHIFT
towards the red wall over MOVING_SECONDS (one LINEAR translation channel on its
node, animation `short_block_slide`), for configs/moving_block.yaml's capture
sequence: 0.2 m/s, a few pixels between the first and last raw of a CW-ToF
frame. Its path stays clear of the tall block (which lies further back in z).

Standard library only. Usage: python3 scripts/make_cornell_box.py [--glossy | --retro | --moving] [out.gltf]
"""

import math
import sys

from gltf_common import (add_camera, add_mesh, add_translation_animation, cross, dot, finish, new_gltf,
                         normalize, sub, write_gltf)

MM = 0.001  # metres per millimetre

# Diffuse reflectances (linear RGB), the commonly used values derived from the
# published spectral measurements.
MATERIALS = [
    ("white", (0.725, 0.71, 0.68)),
    ("red", (0.63, 0.065, 0.05)),
    ("green", (0.14, 0.45, 0.091)),
]

# The moving-block variant: the short block's slide, metres along +x (towards
# the red wall) over this many seconds.
MOVING_SHIFT = (0.2, 0.0, 0.0)
MOVING_SECONDS = 1.0

# The glossy variant's extra materials (name, rgb, metallic, roughness) and
# the groups that use them.
GLOSSY_MATERIALS = [
    ("white_glossy", (0.725, 0.71, 0.68), 0.0, 0.25),
    ("white_metal", (0.725, 0.71, 0.68), 1.0, 0.35),
]
GLOSSY_GROUPS = {"floor": "white_glossy", "tall_block": "white_metal"}

# The retro-reflector variant's plate (mm): 40 x 40, 3 thick, its front face
# at the box's opening (z = 0, 0.8 m from the camera: optical path ~1.6 m, in
# spad_lidar's time window), above the short block, right of the image centre
# (+x is image left), so the back wall is behind it; and a 6 mm post from
# the floor's front edge up to it.
RETRO_MATERIAL = ("retro_white", (1.0, 1.0, 1.0), 0.0, 1.0)
RETRO_CENTER_MM = (200.0, 330.0, 0.0)
RETRO_HALF_MM, RETRO_THICK_MM, POST_HALF_MM = 20.0, 3.0, 3.0

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


def box_triangles(lo, hi):
    """The six outward faces of the axis-aligned box lo..hi (mm)."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    c = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
    center = centroid(c)
    faces = [[c[0], c[1], c[3], c[2]], [c[4], c[6], c[7], c[5]],  # x0, x1
             [c[0], c[4], c[5], c[1]], [c[2], c[3], c[7], c[6]],  # y0, y1
             [c[0], c[2], c[6], c[4]], [c[1], c[5], c[7], c[3]]]  # z0, z1
    tris = []
    for face in faces:
        tris += triangles(face, lambda p, center=center: sub(p, center))
    return tris


def retro_groups():
    x, y, z = RETRO_CENTER_MM
    h, t, w = RETRO_HALF_MM, RETRO_THICK_MM, POST_HALF_MM
    plate = box_triangles((x - h, y - h, z), (x + h, y + h, z + t))
    post = box_triangles((x - w, 0.0, z + t), (x + w, y - h, z + t + 2 * w))
    return [("retro_reflector", "retro_white", plate), ("retro_post", "white", post)]


def build_gltf(glossy=False, retro=False, moving=False):
    groups = build_groups()
    materials = [(name, rgb, 0.0, 1.0) for name, rgb in MATERIALS]
    if glossy:
        materials += GLOSSY_MATERIALS
        groups = [(name, GLOSSY_GROUPS.get(name, material), tris) for name, material, tris in groups]
    if retro:
        materials.append(RETRO_MATERIAL)
        groups += retro_groups()
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
    if moving:
        node = [n["name"] for n in gltf["nodes"]].index("short_block")
        add_translation_animation(gltf, blob, "short_block_slide", node, [0.0, MOVING_SECONDS],
                                  [(0.0, 0.0, 0.0), MOVING_SHIFT])
    return finish(gltf, blob)


def main():
    glossy, retro, moving = ("--" + f in sys.argv[1:] for f in ("glossy", "retro", "moving"))
    for flag in ("--glossy", "--retro", "--moving"):
        if flag in sys.argv:
            sys.argv.remove(flag)
    name = ("cornell_box_glossy.gltf" if glossy else "cornell_box_retro.gltf" if retro
            else "cornell_box_moving.gltf" if moving else "cornell_box.gltf")
    write_gltf(build_gltf(glossy, retro, moving), name)


if __name__ == "__main__":
    main()
