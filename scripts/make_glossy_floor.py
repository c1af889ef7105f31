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
import struct

from gltf_common import embed_buffer, write_gltf
from make_corner import cross, look_rotation, normalize, sub

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
    gltf = {
        "asset": {"version": "2.0", "generator": "tofsim scripts/make_glossy_floor.py"},
        "scene": 0, "scenes": [{"name": "glossy_floor", "nodes": []}],
        "nodes": [], "meshes": [], "accessors": [], "bufferViews": [],
        "materials": [{"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": [r, g, b, 1.0], "metallicFactor": metallic,
            "roughnessFactor": roughness}}
            for name, (r, g, b), metallic, roughness in MATERIALS],
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

    gltf["cameras"] = [{"name": "floor_camera", "type": "perspective", "perspective": {
        "yfov": math.radians(FOV_Y_DEG), "aspectRatio": 1.0, "znear": 0.01, "zfar": 100.0}}]
    gltf["nodes"].append({"name": "floor_camera", "camera": 0, "translation": list(CAMERA_POS),
                          "rotation": look_rotation(sub(CAMERA_TARGET, CAMERA_POS))})
    gltf["scenes"][0]["nodes"] = list(range(len(gltf["nodes"])))
    embed_buffer(gltf, blob)
    return gltf


def main():
    write_gltf(build_gltf(), "glossy_floor.gltf")


if __name__ == "__main__":
    main()
