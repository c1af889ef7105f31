"""Shared by the scene generators (make_cornell_box.py, make_corner.py):
embedding the binary buffer and writing the .gltf atomically."""

import base64
import json
import os
import sys


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
