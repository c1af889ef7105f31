#!/usr/bin/env python3
"""Draws lidar beams' waveforms on a logarithmic axis as a PNG: the
multipath's tail after an echo is ~1e-3 of its peak, flat on a linear plot
(waveforms.png). Reads a `lidar:` render's waveforms.npy (channels, azimuths,
T) float32 and its lidar.json (the time axis, the azimuths); with --direct,
the same beams of a render without `lidar.multipath` are drawn thin and
grey under them, so what lies above the grey is the multipath.

Each beam's waveform is drawn against range (depth_start_m + (t + 1/2)
depth_bin_width_m) in decades below the highest bin of all the beams drawn;
the y ticks are decades (1, 1e-1, ...), the x ticks every 5, 1 or 0.5 m.

Standard library only (struct, zlib, json).
Usage: python3 scripts/plot_lidar_multipath.py OUT/waveforms.npy picture.png
         --beam RING AZIMUTH_DEG [--beam ...] [--direct DIRECT/waveforms.npy]
         [--range 0 30] [--decades 6] [--size 800 480]
scripts/lidar_multipath_picture.sh renders the README's picture with it.
"""

import argparse
import ast
import json
import math
import os
import struct
import zlib

COLOURS = [(220, 60, 40), (40, 110, 220), (30, 160, 70), (200, 140, 20)]

# A 3 x 5 font for the tick labels.
GLYPHS = {
    "0": ["111", "101", "101", "101", "111"], "1": ["010", "110", "010", "010", "111"],
    "2": ["111", "001", "111", "100", "111"], "3": ["111", "001", "111", "001", "111"],
    "4": ["101", "101", "111", "001", "001"], "5": ["111", "100", "111", "001", "111"],
    "6": ["111", "100", "111", "101", "111"], "7": ["111", "001", "010", "010", "010"],
    "8": ["111", "101", "111", "101", "111"], "9": ["111", "101", "111", "001", "111"],
    "e": ["000", "111", "111", "100", "111"], "-": ["000", "000", "111", "000", "000"],
    "m": ["000", "110", "111", "101", "101"], " ": ["000", "000", "000", "000", "000"],
    ".": ["000", "000", "000", "000", "010"],
}


def read_npy(path):
    """A little-endian float32 C-order .npy: (shape, values)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:6] != b"\x93NUMPY":
        raise SystemExit("%s: not an .npy file" % path)
    major = data[6]
    length = struct.unpack_from("<H" if major == 1 else "<I", data, 8)[0]
    start = 10 if major == 1 else 12
    header = ast.literal_eval(data[start:start + length].decode("latin1"))
    if header["descr"] != "<f4" or header["fortran_order"]:
        raise SystemExit("%s: expected little-endian float32 in C order" % path)
    shape = tuple(header["shape"])
    count = 1
    for n in shape:
        count *= n
    values = struct.unpack_from("<%df" % count, data, start + length)
    return shape, values


def beam_waveform(shape, values, ring, azimuth):
    _, azimuths, bins = shape
    first = (ring * azimuths + azimuth) * bins
    return values[first:first + bins]


class Canvas:
    def __init__(self, width, height):
        self.w, self.h = width, height
        self.rgb = bytearray(b"\xff" * (width * height * 3))

    def dot(self, x, y, c):
        if 0 <= x < self.w and 0 <= y < self.h:
            i = (y * self.w + x) * 3
            self.rgb[i:i + 3] = bytes(c)

    def line(self, x0, y0, x1, y1, c, thick=1):
        steps = max(abs(x1 - x0), abs(y1 - y0), 1)
        for s in range(steps + 1):
            x = round(x0 + (x1 - x0) * s / steps)
            y = round(y0 + (y1 - y0) * s / steps)
            for d in range(thick):
                self.dot(x, y + d, c)

    def text(self, x, y, s, c=(0, 0, 0), scale=2):
        for k, ch in enumerate(s):
            for row, bits in enumerate(GLYPHS.get(ch, GLYPHS[" "])):
                for col, bit in enumerate(bits):
                    if bit == "1":
                        for dy in range(scale):
                            for dx in range(scale):
                                self.dot(x + (4 * k + col) * scale + dx, y + row * scale + dy, c)

    def write_png(self, path):
        raw = b"".join(b"\x00" + bytes(self.rgb[y * self.w * 3:(y + 1) * self.w * 3])
                       for y in range(self.h))

        def chunk(kind, body):
            return struct.pack(">I", len(body)) + kind + body + struct.pack(
                ">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

        with open(path, "wb") as f:
            f.write(b"\x89PNG\r\n\x1a\n" +
                    chunk(b"IHDR", struct.pack(">IIBBBBB", self.w, self.h, 8, 2, 0, 0, 0)) +
                    chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("waveforms")
    p.add_argument("png")
    p.add_argument("--beam", type=float, nargs=2, action="append", required=True,
                   metavar=("RING", "AZIMUTH_DEG"), help="a beam (the nearest azimuth)")
    p.add_argument("--direct", help="waveforms.npy of the same lidar without multipath")
    p.add_argument("--range", type=float, nargs=2, default=(0.0, 30.0), help="m")
    p.add_argument("--decades", type=int, default=6)
    p.add_argument("--size", type=int, nargs=2, default=(800, 480))
    a = p.parse_args()

    folder = os.path.dirname(os.path.abspath(a.waveforms))
    with open(os.path.join(folder, "lidar.json")) as f:
        meta = json.load(f)
    time = meta["time"]
    shape, values = read_npy(a.waveforms)
    direct = read_npy(a.direct) if a.direct else None
    if direct and direct[0] != shape:
        raise SystemExit("--direct: shape %s, not %s" % (direct[0], shape))
    beams = []
    for ring, azimuth_deg in a.beam:
        index = round((azimuth_deg - meta["lidar"]["azimuth_start_deg"]) / meta["lidar"]["azimuth_step_deg"])
        if not (0 <= ring < shape[0] and 0 <= index < shape[1]):
            raise SystemExit("beam (%g, %g deg) is not in the scan" % (ring, azimuth_deg))
        beams.append((int(ring), int(index)))

    def depth(t):
        return time["depth_start_m"] + (t + 0.5) * time["depth_bin_width_m"]

    peak = max(max(beam_waveform(shape, values, r, i)) for r, i in beams)
    if not peak > 0.0:
        raise SystemExit("the beams hold no light")
    c = Canvas(*a.size)
    left, right, top, bottom = 70, c.w - 20, 20, c.h - 40
    lo_r, hi_r = a.range
    floor = -a.decades

    def px(r):
        return round(left + (r - lo_r) / (hi_r - lo_r) * (right - left))

    def py(v):  # v relative to the peak, > 0
        d = max(math.log10(v), floor) if v > 0.0 else floor
        return round(top + (0.3 - d) / (0.3 - floor) * (bottom - top))

    for d in range(floor, 1):  # decades
        y = py(10.0 ** d)
        c.line(left, y, right, y, (225, 225, 225))
        c.text(8, y - 5, "1" if d == 0 else "1e%d" % d)
    step = 5.0 if hi_r - lo_r > 10.0 else 1.0 if hi_r - lo_r > 3.0 else 0.5
    k = math.ceil(lo_r / step)
    while k * step <= hi_r:
        r = k * step
        c.line(px(r), top, px(r), bottom, (225, 225, 225))
        c.text(px(r) - 8, bottom + 8, "%gm" % r)
        k += 1
    c.line(left, bottom, right, bottom, (0, 0, 0))
    c.line(left, top, left, bottom, (0, 0, 0))

    def draw(wave, colour, thick):
        last = None
        for t, v in enumerate(wave):
            r = depth(t)
            if r < lo_r or r > hi_r:
                continue
            point = (px(r), py(v / peak))
            if last:
                c.line(last[0], last[1], point[0], point[1], colour, thick)
            last = point

    for k, (ring, index) in enumerate(beams):
        if direct:
            draw(beam_waveform(direct[0], direct[1], ring, index), (150, 150, 150), 1)
        draw(beam_waveform(shape, values, ring, index), COLOURS[k % len(COLOURS)], 2)
    c.write_png(a.png)
    print("wrote %s: %d beams, %g .. %g m, %d decades below the peak %.4g"
          % (a.png, len(beams), lo_r, hi_r, a.decades, peak))


if __name__ == "__main__":
    main()
