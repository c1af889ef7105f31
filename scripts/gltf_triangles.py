"""World-space triangles of a glTF 2.0 file, as exporters write them: indexed
or not (unsigned byte, short or int indices), interleaved vertex buffers
(byteStride), buffers embedded as data URIs, beside the file (.bin) or in a
binary .glb, and the node hierarchy's transforms (matrix or translation,
rotation, scale) applied. Only triangle lists (mode 4, the default) are read;
strips, fans, points and lines are skipped, as tofsim's loader skips points
and lines. NumPy only: used by nlos_reconstruct_ytal.py and its test
(python/tests/test_nlos_ytal_script.py)."""

import base64
import json
import os
import struct

import numpy as np

_COMPONENTS = {5121: "<u1", 5123: "<u2", 5125: "<u4", 5126: "<f4"}
_WIDTH = {"SCALAR": 1, "VEC3": 3}


def _load(path):
    """(document, [buffer bytes]) of a .gltf or .glb file."""
    with open(path, "rb") as f:
        data = f.read()
    glb_blob = None
    if data[:4] == b"glTF":  # binary: header, a JSON chunk, then an optional BIN chunk
        length, kind = struct.unpack_from("<II", data, 12)
        doc = json.loads(data[20:20 + length].decode("utf-8"))
        rest = 20 + length
        if rest + 8 <= len(data):
            bin_length, _ = struct.unpack_from("<II", data, rest)
            glb_blob = data[rest + 8:rest + 8 + bin_length]
    else:
        doc = json.loads(data.decode("utf-8"))
    buffers = []
    for b in doc.get("buffers", []):
        uri = b.get("uri")
        if uri is None:
            buffers.append(glb_blob)
        elif uri.startswith("data:"):
            buffers.append(base64.b64decode(uri.split(",", 1)[1]))
        else:
            with open(os.path.join(os.path.dirname(os.path.abspath(path)), uri), "rb") as f:
                buffers.append(f.read())
    return doc, buffers


def _accessor(doc, buffers, index):
    """Accessor `index` as an array (count, width), its byteStride honoured."""
    acc = doc["accessors"][index]
    dtype = np.dtype(_COMPONENTS[acc["componentType"]])
    width = _WIDTH[acc["type"]]
    count = acc["count"]
    view = doc["bufferViews"][acc["bufferView"]]
    blob = buffers[view["buffer"]]
    start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    stride = view.get("byteStride", 0) or dtype.itemsize * width
    rows = np.ndarray((count, width), dtype=dtype, buffer=blob, offset=start,
                      strides=(stride, dtype.itemsize))
    return np.array(rows)


def _quaternion_matrix(q):
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def _local_matrix(node):
    if "matrix" in node:  # column major
        return np.array(node["matrix"], float).reshape(4, 4).T
    m = np.eye(4)
    m[:3, :3] = _quaternion_matrix(node.get("rotation", [0, 0, 0, 1])) @ np.diag(
        node.get("scale", [1, 1, 1]))
    m[:3, 3] = node.get("translation", [0, 0, 0])
    return m


def _mesh_triangles(doc, buffers, mesh, world):
    tris = []
    for prim in doc["meshes"][mesh]["primitives"]:
        if prim.get("mode", 4) != 4:
            continue
        p = _accessor(doc, buffers, prim["attributes"]["POSITION"]).astype(float)
        p = p @ world[:3, :3].T + world[:3, 3]
        if "indices" in prim:
            idx = _accessor(doc, buffers, prim["indices"])[:, 0].astype(np.int64)
        else:
            idx = np.arange(len(p))
        idx = idx[:len(idx) - len(idx) % 3]
        tris.append(p[idx].reshape(-1, 3, 3))
    return tris


def triangles(path, skip=()):
    """World-space triangles (N, 3, 3) of every mesh the file's scene places,
    leaving out nodes (and their children) named in `skip`."""
    doc, buffers = _load(path)
    nodes = doc.get("nodes", [])
    scenes = doc.get("scenes")
    if scenes:
        roots = scenes[doc.get("scene", 0)].get("nodes", [])
    else:  # no scene: every node that is no other node's child
        children = {c for n in nodes for c in n.get("children", [])}
        roots = [i for i in range(len(nodes)) if i not in children]
    tris = []
    stack = [(i, np.eye(4)) for i in reversed(roots)]  # depth first, in file order
    while stack:
        i, parent = stack.pop()
        node = nodes[i]
        if node.get("name") in skip:
            continue
        world = parent @ _local_matrix(node)
        if "mesh" in node:
            tris.extend(_mesh_triangles(doc, buffers, node["mesh"], world))
        stack.extend((c, world) for c in reversed(node.get("children", [])))
    return np.concatenate(tris) if tris else np.zeros((0, 3, 3))
