#!/usr/bin/env python3
"""Issue 27's equal-error table on the Cornell box at SIDE x SIDE: tofsim IR
(CPU backend) against mitransient, by hand, never in CI. mitransient renders
the truth (max_depth 3: direct + one bounce, TRUTH_SPP) and a ladder of spp
(64 .. 16384); each tofsim variant's relative L1 error (R + G + B, the
transient rebinned to 100 ps) over all pixels and over interior pixels
(the 3 x 3 neighbourhood on one plane: every neighbour's tofsim depth
within 1 mm of the plane through its row and column neighbours), and
mitransient's seconds to the same error, interpolated log-log between its
runs. tofsim's time is its process wall (the whole run) and stats.seconds.

    python3 -m venv ~/mt && ~/mt/bin/pip install mitransient numpy
    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
      ~/mt/bin/python bench/equal_error/compare_mitransient.py [SIDE=64] [TRUTH_SPP=65536] [OUT]
"""

import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
TOFSIM = os.path.join(ROOT, "build", "apps", "cli", "tofsim")
MT = os.path.join(ROOT, "bench", "equal_error", "mitransient_cornell.py")
BINS, REBIN = 371, 5  # 20 ps bins, error on 100 ps

# (name, --set overrides): the table rows.
VARIANTS = [
    ("ISM, RSM 32^2, 1 sample", ["render.indirect.rsm_resolution=32", "render.indirect.visibility=ism"]),
    ("ISM, RSM 64^2, 3x3 at edges", ["render.indirect.rsm_resolution=64", "render.indirect.visibility=ism",
                                     "render.pixel_samples=3", "render.adaptive_pixel_samples=true"]),
    ("exact, RSM 64^2, 1 sample", ["render.indirect.rsm_resolution=64", "render.indirect.visibility=exact"]),
    ("exact, RSM 128^2, 2x2 at edges", ["render.indirect.rsm_resolution=128", "render.indirect.visibility=exact",
                                        "render.pixel_samples=2", "render.adaptive_pixel_samples=true"]),
    ("exact, RSM 128^2, 3x3 at edges", ["render.indirect.rsm_resolution=128", "render.indirect.visibility=exact",
                                        "render.pixel_samples=3", "render.adaptive_pixel_samples=true"]),
]
COMMON = ["output.video=false", "sensors=[]", "output.components=[]", "light.cone_angle=30 deg",
          "light.cone_falloff=0 deg", "time.start=1.5 m", "time.bin_width=20 ps", f"time.bins={BINS}",
          "render.indirect.geometry_clamp=0"]


def rebinned(v):
    """(H, W, T, 3) -> (H, W, T / REBIN), R + G + B."""
    s = v.sum(axis=3)
    t = (s.shape[2] // REBIN) * REBIN
    return s[:, :, :t].reshape(s.shape[0], s.shape[1], -1, REBIN).sum(axis=3)


def rel_l1(v, truth, mask):
    return float(np.abs(v - truth)[mask].sum() / np.abs(truth)[mask].sum())


def interior(depth):
    """Pixels whose 3 x 3 neighbourhood is one plane of tofsim's depth."""
    d = depth
    ok = np.zeros_like(d, dtype=bool)
    c = d[1:-1, 1:-1]
    flat_x = np.abs(d[1:-1, :-2] + d[1:-1, 2:] - 2 * c) < 1e-3
    flat_y = np.abs(d[:-2, 1:-1] + d[2:, 1:-1] - 2 * c) < 1e-3
    flat_d = np.abs(d[:-2, :-2] + d[2:, 2:] - 2 * c) < 1e-3
    flat_a = np.abs(d[:-2, 2:] + d[2:, :-2] - 2 * c) < 1e-3
    ok[1:-1, 1:-1] = flat_x & flat_y & flat_d & flat_a & (c > 0)
    return ok


def mitransient(spp, side, out):
    env = dict(os.environ)
    r = subprocess.run([sys.executable, MT, str(spp), "3", out, str(side), str(BINS)], env=env,
                       check=True, capture_output=True, text=True)
    return json.loads(r.stdout.strip().splitlines()[-1])["seconds"]


def tofsim(side, sets, out):
    args = [TOFSIM, "render", os.path.join(ROOT, "configs", "cornell_box.yaml"), "--backend", "cpu",
            "-q", "-o", out, "--set", f"camera.resolution=[{side}, {side}]"]
    for s in COMMON + sets:
        args += ["--set", s]
    start = time.time()
    subprocess.run(args, check=True)
    wall = time.time() - start
    stats = json.load(open(os.path.join(out, "transient.json")))["stats"]
    return np.load(os.path.join(out, "transient.npy")), np.load(os.path.join(out, "depth.npy")), \
        wall, stats["seconds"]


def seconds_to(error, ladder):
    """mitransient's seconds to `error`, log-log between its runs (None off the ladder)."""
    pts = sorted(ladder, key=lambda p: -p[1])  # (seconds, error), error decreasing
    for (s0, e0), (s1, e1) in zip(pts, pts[1:]):
        if e1 <= error <= e0:
            f = (math.log(error) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(s0) + f * (math.log(s1) - math.log(s0)))
    return None


def main():
    side = int(sys.argv[1]) if len(sys.argv) > 1 else 64
    truth_spp = int(sys.argv[2]) if len(sys.argv) > 2 else 65536
    folder = sys.argv[3] if len(sys.argv) > 3 else tempfile.mkdtemp(prefix="tofsim-mt-")
    os.makedirs(folder, exist_ok=True)
    truth_file = os.path.join(folder, f"truth_{side}_{truth_spp}.npy")
    if not os.path.exists(truth_file):
        mitransient(truth_spp, side, truth_file)
    truth = rebinned(np.load(truth_file))
    # The first tofsim variant's depth decides the interior pixels.
    runs = [(name, *tofsim(side, sets, os.path.join(folder, f"tofsim{i}")))
            for i, (name, sets) in enumerate(VARIANTS)]
    inside = np.broadcast_to(interior(runs[0][2])[:, :, None], truth.shape)
    everywhere = np.ones_like(truth, dtype=bool)
    ladder_in, ladder_all = [], []
    spp = 64
    while spp <= min(16384, truth_spp // 4):
        f = os.path.join(folder, f"mt_{side}_{spp}.npy")
        s = mitransient(spp, side, f)
        v = rebinned(np.load(f))
        ladder_in.append((s, rel_l1(v, truth, inside)))
        ladder_all.append((s, rel_l1(v, truth, everywhere)))
        print(f"mitransient {spp} spp: {s:.2f} s, L1 interior {ladder_in[-1][1]:.2%} / all {ladder_all[-1][1]:.2%}")
        spp *= 4
    print(f"\n{side}x{side}, truth mitransient {truth_spp} spp, {inside[:, :, 0].sum()} interior pixels of {side * side}")
    print("| tofsim IR (CPU backend, clamp 0) | process s / render s | transient L1 interior / all | "
          "mitransient s to the same error, interior / all | speed-up (process) interior / all |")
    print("|---|---|---|---|---|")
    for name, v, depth, wall, render in runs:
        ei, ea = rel_l1(rebinned(v), truth, inside), rel_l1(rebinned(v), truth, everywhere)
        ti, ta = seconds_to(ei, ladder_in), seconds_to(ea, ladder_all)
        fmt = lambda t: "off the ladder" if t is None else f"{t:.2f}"
        sp = lambda t: "-" if t is None else f"{t / wall:.1f}x"
        print(f"| {name} | {wall:.2f} / {render:.2f} | {ei:.1%} / {ea:.1%} | {fmt(ti)} / {fmt(ta)} | {sp(ti)} / {sp(ta)} |")


if __name__ == "__main__":
    main()
