"""Shared by the scene generators (make_cornell_box.py, make_glossy_floor.py,
make_nlos_letter.py, and the quad scenes through gltf_writer.py): vector
helpers, the document with its materials, vec3 accessors, quads as meshes, a
look-at camera, a node's translation animation, embedding the binary buffer
and writing the .gltf atomically."""

import base64
import json
import math
import os
import struct
import sys


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


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


def new_gltf(generator, scene_name, materials, copyright=None):
    """An empty glTF 2.0 document with one scene and `materials`, each
    (name, (r, g, b), metallic, roughness)."""
    asset = {"version": "2.0", "generator": generator}
    if copyright:
        asset["copyright"] = copyright
    return {
        "asset": asset,
        "scene": 0,
        "scenes": [{"name": scene_name, "nodes": []}],
        "nodes": [], "meshes": [], "accessors": [], "bufferViews": [],
        "materials": [{"name": name, "pbrMetallicRoughness": {
            "baseColorFactor": [r, g, b, 1.0], "metallicFactor": metallic, "roughnessFactor": roughness}}
            for name, (r, g, b), metallic, roughness in materials],
    }


def add_vec3(gltf, blob, values, bounds=False):
    """Appends `values` as float32 vec3s to blob, with their buffer view and
    accessor; bounds: the accessor's min/max, of the float32 values stored (as
    the spec requires). Returns the accessor's index."""
    offset = len(blob)
    for v in values:
        blob.extend(struct.pack("<3f", *v))
    gltf["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": 12 * len(values),
                                "target": 34962})
    accessor = {"bufferView": len(gltf["bufferViews"]) - 1, "componentType": 5126,
                "count": len(values), "type": "VEC3"}
    if bounds:
        stored = [struct.unpack("<3f", struct.pack("<3f", *p)) for p in values]
        accessor["min"] = [min(p[i] for p in stored) for i in range(3)]
        accessor["max"] = [max(p[i] for p in stored) for i in range(3)]
    gltf["accessors"].append(accessor)
    return len(gltf["accessors"]) - 1


def add_mesh(gltf, blob, name, material, positions, normals):
    """One triangle-list mesh (and its node) of `positions` and `normals`."""
    pos = add_vec3(gltf, blob, positions, True)
    nrm = add_vec3(gltf, blob, normals)
    gltf["meshes"].append({"name": name, "primitives": [{
        "attributes": {"POSITION": pos, "NORMAL": nrm}, "material": material, "mode": 4}]})
    gltf["nodes"].append({"name": name, "mesh": len(gltf["meshes"]) - 1})


def add_quads(gltf, blob, quads):
    """Each (name, material index, 4 corners counter-clockwise seen from the
    lit side, normal) as a mesh of two triangles; the winding is checked
    against the normal."""
    for name, material, q, normal in quads:
        n = normalize(cross(sub(q[1], q[0]), sub(q[2], q[0])))
        assert all(abs(a - b) < 1e-9 for a, b in zip(n, normal)), name  # winding matches normal
        positions = [tuple(float(c) for c in p) for p in (q[0], q[1], q[2], q[0], q[2], q[3])]
        add_mesh(gltf, blob, name, material, positions, [tuple(float(c) for c in normal)] * 6)


def add_camera(gltf, name, yfov_rad, translation, rotation):
    """A perspective camera (square aspect) on its own node."""
    gltf["cameras"] = [{"name": name, "type": "perspective", "perspective": {
        "yfov": yfov_rad, "aspectRatio": 1.0, "znear": 0.01, "zfar": 100.0}}]
    gltf["nodes"].append({"name": name, "camera": 0, "translation": list(translation),
                          "rotation": rotation})


def add_translation_animation(gltf, blob, name, node, times, translations):
    """A LINEAR translation channel on `node`: keyframe times (s, increasing)
    and the node's translation at each, as float32 accessors (input with its
    min/max, as the spec requires)."""
    offset = len(blob)
    for t in times:
        blob.extend(struct.pack("<f", t))
    gltf["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": 4 * len(times)})
    stored = [struct.unpack("<f", struct.pack("<f", t))[0] for t in times]
    gltf["accessors"].append({"bufferView": len(gltf["bufferViews"]) - 1, "componentType": 5126,
                              "count": len(times), "type": "SCALAR",
                              "min": [min(stored)], "max": [max(stored)]})
    times_accessor = len(gltf["accessors"]) - 1
    values = add_vec3(gltf, blob, translations)
    del gltf["bufferViews"][-1]["target"]  # animation data is no vertex buffer
    gltf.setdefault("animations", []).append({
        "name": name,
        "samplers": [{"input": times_accessor, "output": values, "interpolation": "LINEAR"}],
        "channels": [{"sampler": 0, "target": {"node": node, "path": "translation"}}]})


def finish(gltf, blob):
    """Every node in the scene, the buffer embedded."""
    gltf["scenes"][0]["nodes"] = list(range(len(gltf["nodes"])))
    embed_buffer(gltf, blob)
    return gltf


def embed_buffer(gltf, blob):
    """Stores `blob` as the file's only buffer, base64 in a data URI."""
    gltf["buffers"] = [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," +
                        base64.b64encode(bytes(blob)).decode("ascii")}]


def write_gltf(gltf, default_name):
    """Writes to argv[1] or configs/scenes/<default_name>, via a temporary file
    renamed into place so a failed run leaves no half-written scene."""
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "configs", "scenes", default_name)
    text = json.dumps(gltf, indent=1) + "\n"
    tmp = out + ".tmp"
    with open(tmp, "w", encoding="ascii") as f:
        f.write(text)
    os.replace(tmp, out)
    print("wrote", os.path.normpath(out))
