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

import math
import struct

from gltf_common import embed_buffer, write_gltf

MATERIALS = [("wall_grey", (0.7, 0.7, 0.7)), ("floor_grey", (0.5, 0.5, 0.5))]

# name, material, quad corners counter-clockwise seen from the lit side, normal
QUADS = [
    ("wall_x", 0, [(0, 0, 2), (0, 0, 0), (0, 2, 0), (0, 2, 2)], (1, 0, 0)),
    ("wall_z", 0, [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0)], (0, 0, 1)),
    ("floor", 1, [(0, 0, 0), (0, 0, 2), (2, 0, 2), (2, 0, 0)], (0, 1, 0)),
]

CAMERA_POS = (1.6, 1.2, 1.6)
CAMERA_TARGET = (0.0, 0.6, 0.0)
FOV_Y_DEG = 50.0


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(v):
    n = math.sqrt(sum(x * x for x in v))
    return tuple(x / n for x in v)


def look_rotation(forward, up=(0.0, 1.0, 0.0)):
    """Quaternion (x, y, z, w) turning the camera's -Z onto `forward`, +Y up."""
    f = normalize(forward)
    r = normalize(cross(f, up))
    u = cross(r, f)
    # Rotation matrix columns: right, up, -forward.
    m = [[r[0], u[0], -f[0]], [r[1], u[1], -f[1]], [r[2], u[2], -f[2]]]
    w = math.sqrt(max(0.0, 1.0 + m[0][0] + m[1][1] + m[2][2])) / 2
    x = math.copysign(math.sqrt(max(0.0, 1.0 + m[0][0] - m[1][1] - m[2][2])) / 2, m[2][1] - m[1][2])
    y = math.copysign(math.sqrt(max(0.0, 1.0 - m[0][0] + m[1][1] - m[2][2])) / 2, m[0][2] - m[2][0])
    z = math.copysign(math.sqrt(max(0.0, 1.0 - m[0][0] - m[1][1] + m[2][2])) / 2, m[1][0] - m[0][1])
    return [x, y, z, w]


def build_gltf():
    blob = bytearray()
    gltf = {
        "asset": {"version": "2.0", "generator": "tofsim scripts/make_corner.py"},
        "scene": 0, "scenes": [{"name": "corner", "nodes": []}],
        "nodes": [], "meshes": [], "accessors": [], "bufferViews": [],
        "materials": [{"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": [r, g, b, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}}
            for name, (r, g, b) in MATERIALS],
    }

    def add_vec3(values, bounds):
        offset = len(blob)
        for v in values:
            blob.extend(struct.pack("<3f", *v))
        gltf["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": 12 * len(values),
                                    "target": 34962})
        accessor = {"bufferView": len(gltf["bufferViews"]) - 1, "componentType": 5126,
                    "count": len(values), "type": "VEC3"}
        if bounds:
            accessor["min"] = [min(v[i] for v in values) for i in range(3)]
            accessor["max"] = [max(v[i] for v in values) for i in range(3)]
        gltf["accessors"].append(accessor)
        return len(gltf["accessors"]) - 1

    for name, material, q, normal in QUADS:
        n = normalize(cross(sub(q[1], q[0]), sub(q[2], q[0])))
        assert all(abs(a - b) < 1e-9 for a, b in zip(n, normal)), name  # winding matches normal
        positions = [tuple(float(c) for c in p) for p in (q[0], q[1], q[2], q[0], q[2], q[3])]
        pos = add_vec3(positions, True)
        nrm = add_vec3([tuple(float(c) for c in normal)] * 6, False)
        gltf["meshes"].append({"name": name, "primitives": [{
            "attributes": {"POSITION": pos, "NORMAL": nrm}, "material": material, "mode": 4}]})
        gltf["nodes"].append({"name": name, "mesh": len(gltf["meshes"]) - 1})

    gltf["cameras"] = [{"name": "corner_camera", "type": "perspective", "perspective": {
        "yfov": math.radians(FOV_Y_DEG), "aspectRatio": 1.0, "znear": 0.01, "zfar": 100.0}}]
    gltf["nodes"].append({"name": "corner_camera", "camera": 0, "translation": list(CAMERA_POS),
                          "rotation": look_rotation(sub(CAMERA_TARGET, CAMERA_POS))})
    gltf["scenes"][0]["nodes"] = list(range(len(gltf["nodes"])))
    embed_buffer(gltf, blob)
    return gltf


def main():
    write_gltf(build_gltf(), "corner.gltf")


if __name__ == "__main__":
    main()
