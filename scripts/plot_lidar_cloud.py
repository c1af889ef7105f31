#!/usr/bin/env python3
"""Draws a lidar's point cloud (points.ply of a `lidar:` render) seen from
above as a PNG: the horizontal plane of the lidar's frame, coloured by
height, the lidar a white cross at the centre. The PLY is the binary
little-endian file tofsim writes (core/lidar/PointCloudFiles.h: x, y, z,
intensity, ring, azimuth, return_index, time_offset); any order of float,
ushort and uchar properties is read from its header.

Standard library only (struct, zlib).
Usage: python3 scripts/plot_lidar_cloud.py out/lidar_street/points.ply cloud.png
         [--up y] [--extent 40] [--size 640] [--height-range -0.2 6]
"""

import argparse
import math
import struct
import zlib

TYPES = {"float": "f", "float32": "f", "double": "d", "uchar": "B", "uint8": "B",
         "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I"}


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    names, fmt, count = [], "<", 0
    for line in data[:end].decode("ascii").splitlines():
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words and words[0] == "property":
            fmt += TYPES[words[1]]
            names.append(words[2])
    size = struct.calcsize(fmt)
    return [dict(zip(names, struct.unpack_from(fmt, data, end + i * size))) for i in range(count)]


def colour(t):
    """A blue -> green -> yellow -> red ramp for t in [0, 1]."""
    t = min(max(t, 0.0), 1.0)
    stops = [(0.0, (40, 60, 200)), (0.35, (30, 180, 170)), (0.6, (120, 210, 60)),
             (0.8, (250, 200, 40)), (1.0, (220, 50, 40))]
    for (t0, c0), (t1, c1) in zip(stops, stops[1:]):
        if t <= t1:
            u = (t - t0) / (t1 - t0)
            return tuple(int(a + (b - a) * u) for a, b in zip(c0, c1))
    return stops[-1][1]


def write_png(path, width, height, rgb):
    raw = b"".join(b"\x00" + bytes(rgb[y * width * 3:(y + 1) * width * 3]) for y in range(height))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(
            ">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("ply")
    p.add_argument("png")
    p.add_argument("--up", default="y", choices="xyz", help="the world's up axis (glTF: y)")
    p.add_argument("--extent", type=float, default=40.0, help="half width of the view, m")
    p.add_argument("--size", type=int, default=640, help="picture side, px")
    p.add_argument("--height-range", type=float, nargs=2, default=(-0.2, 6.0))
    a = p.parse_args()
    points = read_ply(a.ply)
    across = {"x": ("y", "z"), "y": ("x", "z"), "z": ("x", "y")}[a.up]
    n = a.size
    rgb = bytearray(n * n * 3)  # black
    lo, hi = a.height_range
    # Low points first, so walls and roofs stay on top of the ground.
    for pt in sorted(points, key=lambda q: q[a.up]):
        col = int((pt[across[0]] / a.extent + 1.0) * 0.5 * n)
        row = int((pt[across[1]] / a.extent + 1.0) * 0.5 * n)
        c = colour((pt[a.up] - lo) / (hi - lo))
        for dy in (0, 1):
            for dx in (0, 1):
                x, y = col + dx, row + dy
                if 0 <= x < n and 0 <= y < n:
                    rgb[(y * n + x) * 3:(y * n + x) * 3 + 3] = bytes(c)
    for d in range(-6, 7):  # the lidar
        for x, y in ((n // 2 + d, n // 2), (n // 2, n // 2 + d)):
            rgb[(y * n + x) * 3:(y * n + x) * 3 + 3] = b"\xff\xff\xff"
    write_png(a.png, n, n, rgb)
    print("wrote %s: %d points, %.0f m across, height %g .. %g m coloured blue -> red"
          % (a.png, len(points), 2 * a.extent, lo, hi))


if __name__ == "__main__":
    main()
