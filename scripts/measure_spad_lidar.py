#!/usr/bin/env python3
"""The figures configs/README.md quotes for spad_lidar.yaml, from a render.

Usage: measure_spad_lidar.py OUT [OUT_NO_CROSSTALK]
  OUT: `tofsim render configs/spad_lidar.yaml -o OUT`; OUT_NO_CROSSTALK: the
  same with `--set sensors.0.crosstalk_probability=0` (for the halo's size,
  the lift and the two-return count without crosstalk).

Halo: a pixel has a return at the plate's distance when its counts in the 16
TDC bins around the plate's arrival (PLATE_BINS, 5.28 - 5.55 ns) exceed 16
times its median bin by 5 sigma (Poisson). Tail: a plotted pixel's mean count
15 - 75 bins (0.26 - 1.3 ns) after its peak, against 10 - 60 bins before it.
Needs numpy only (the EXRs are read here: one FLOAT channel, ZIP).
"""
import struct
import sys
import zlib

import numpy as np

PLATE_BINS = (16, 32)
BESIDE, ABOVE = (22, 40), (18, 40)  # (y, x): beside the plate, four rows above


def read_exr(path):
    d = open(path, "rb").read()
    i, hdr = 8, {}
    while d[i] != 0:
        j = d.index(b"\0", i)
        k = d.index(b"\0", j + 1)
        size = struct.unpack("<i", d[k + 1:k + 5])[0]
        hdr[d[i:j].decode()] = d[k + 5:k + 5 + size]
        i = k + 5 + size
    i += 1
    x0, y0, x1, y1 = struct.unpack("<4i", hdr["dataWindow"])
    W, H = x1 - x0 + 1, y1 - y0 + 1
    comp = hdr["compression"][0]
    lines = {0: 1, 2: 1, 3: 16}[comp]
    blocks = (H + lines - 1) // lines
    img = np.zeros((H, W), np.float32)
    for off in struct.unpack("<%dQ" % blocks, d[i:i + 8 * blocks]):
        y, n = struct.unpack("<ii", d[off:off + 8])
        raw, rows = d[off + 8:off + 8 + n], min(lines, H - (y - y0))
        if n < rows * W * 4:  # compressed: inflate, undo the predictor, de-interleave
            t = np.frombuffer(zlib.decompress(raw), np.uint8).astype(np.int64)
            t = (np.cumsum(np.concatenate([[t[0]], t[1:] - 128])) & 0xFF).astype(np.uint8)
            half, out = (len(t) + 1) // 2, np.empty(len(t), np.uint8)
            out[0::2], out[1::2] = t[:half], t[half:]
            raw = out.tobytes()
        img[y - y0:y - y0 + rows] = np.frombuffer(raw[:rows * W * 4], "<f4").reshape(rows, W)
    return img


def load(out):
    s = out + "/sensors/spad/"
    r = {k: read_exr(s + "spad_%s.exr" % k) for k in
         ["intensity", "depth_peak", "depth_coates", "depth_matched", "depth_first", "depth_last",
          "returns", "confidence"]}
    r["counts"] = np.load(s + "spad_counts.npy").astype(float)
    r["depth"] = np.load(out + "/depth.npy")
    return r


def halo(r):
    c, (a, b) = r["counts"], PLATE_BINS
    B = np.median(c, axis=2) * (b - a)
    z = (c[:, :, a:b].sum(2) - B) / np.sqrt(np.maximum(B, 1.0))
    return int((z > 5).sum())


def two_returns(r):
    f, l = r["depth_first"], r["depth_last"]
    return int((np.isfinite(f) & np.isfinite(l) & (np.abs(f - l) > 1e-6)).sum())


def main():
    r = load(sys.argv[1])
    c = r["counts"]
    plate = np.unravel_index(np.argmax(c[:, :, PLATE_BINS[0]:PLATE_BINS[1]].max(2)), c.shape[:2])
    h = c[BESIDE]
    early = int(np.argmax(h[:60]))
    print("plate pixel (x, y) = (%d, %d): highest bin %d" % (plate[1], plate[0], c[plate].max()))
    print("(40, 22): early peak %d counts in bin %d, %.1f %% of the plate's; highest bin %d at "
          "bin %d" % (h[early], early, 100 * h[early] / c[plate].max(), h.max(), int(np.argmax(h))))
    print("halo: %d pixels with a 5-sigma return at the plate's distance" % halo(r))
    I = r["intensity"]
    print("spad_intensity: %d beside the plate (40, 22), %d four rows above (40, 18); mean %.0f" %
          (I[BESIDE], I[ABOVE], I.mean()))
    for name in ["matched", "peak", "coates"]:
        d = r["depth_" + name]
        ok = (r["returns"] > 0) & np.isfinite(d)
        print("spad_depth_%s: median |error| %.1f mm over %d pixels" %
              (name, 1e3 * np.median(np.abs(d[ok] - r["depth"][ok])), ok.sum()))
    print("first != last: %d pixels; returns > 0: %d pixels; mean confidence %.3f" %
          (two_returns(r), int((r["returns"] > 0).sum()), r["confidence"].mean()))
    for (x, y) in [(32, 32), (10, 32), (32, 55), (40, 22)]:
        h = c[y, x]
        i = int(np.argmax(h))
        before, tail = h[max(0, i - 60):max(1, i - 10)].mean(), h[i + 15:i + 75].mean()
        print("(%d, %d): peak %d at bin %d; tail (peak + 15 .. 75 bins) %.1f per bin against %.1f "
              "before it: %+.0f counts" % (x, y, h[i], i, tail, before, (tail - before) * 60))
    if len(sys.argv) > 2:
        n = load(sys.argv[2])
        print("without crosstalk: halo %d pixels, first != last %d, mean intensity %.0f (lift %.1f %%)"
              % (halo(n), two_returns(n), n["intensity"].mean(),
                 100 * (I.mean() / n["intensity"].mean() - 1)))


if __name__ == "__main__":
    main()
