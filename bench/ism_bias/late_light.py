#!/usr/bin/env python3
"""IR's light by time window with imperfect shadow maps against exact
visibility (the same VPLs), on the Cornell box protocol of
bench/equal_error/compare_mitransient.py at 64 x 64 pixels (CPU backend,
30-degree spot, 20 ps bins from 1.5 m): all light, each pixel's direct peak
(up to 400 ps after it), the light more than 400 ps and more than 1 ns after
the pixel's peak, and the late light's ratio by 8 x 8 region. Exact
visibility's late light is within 0.6 % of mitransient's truth (issue 45), so
ISM / exact is the ISM's own bias. bench/README.md, "The ISM's bias".

    python3 bench/ism_bias/late_light.py build/apps/cli/tofsim /tmp/ism_bias \\
        [--set render.indirect.points_per_vpl=8000 ...]
"""
import json
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
COMMON = ["output.video=false", "sensors=[]", "output.components=[]", "light.cone_angle=30 deg",
          "light.cone_falloff=0 deg", "time.start=1.5 m", "time.bin_width=20 ps", "time.bins=371",
          "camera.resolution=[64, 64]"]


def render(tofsim, out, sets):
    args = [tofsim, "render", os.path.join(ROOT, "configs", "cornell_box.yaml"), "--backend", "cpu",
            "-q", "-o", out]
    for s in COMMON + sets:
        args += ["--set", s]
    subprocess.run(args, check=True)
    volume = np.load(os.path.join(out, "transient.npy")).sum(axis=3)  # (H, W, T), R + G + B
    return volume, json.load(open(os.path.join(out, "transient.json")))["stats"]["seconds"]


def main():
    tofsim, out = sys.argv[1], sys.argv[2]
    extra = [a for a in sys.argv[3:] if a != "--set"]
    for rsm in (32, 64):
        base = [f"render.indirect.rsm_resolution={rsm}"]
        exact, _ = render(tofsim, os.path.join(out, f"exact{rsm}"), base + ["render.indirect.visibility=exact"])
        ism, seconds = render(tofsim, os.path.join(out, f"ism{rsm}"),
                              base + ["render.indirect.visibility=ism"] + extra)
        t = np.arange(exact.shape[2])[None, None, :]
        peak = exact.argmax(axis=2)[..., None]
        windows = {"all": t >= 0, "peak": t <= peak + 20, ">400ps": t > peak + 20, ">1ns": t > peak + 50}
        ratios = {k: float(ism[m].sum() / exact[m].sum()) for k, m in
                  ((k, np.broadcast_to(m, exact.shape)) for k, m in windows.items())}
        late = np.broadcast_to(windows[">400ps"], exact.shape)
        region = lambda v: np.where(late, v, 0).sum(axis=2).reshape(8, 8, 8, 8).sum(axis=(1, 3))
        r_ism, r_exact = region(ism), region(exact)
        by_region = r_ism / r_exact
        print(f"RSM {rsm}^2 {' '.join(extra)}: ISM / exact " +
              " ".join(f"{k} {v:.3f}" for k, v in ratios.items()) +
              f"; late by 8x8 region {by_region.min():.2f}..{by_region.max():.2f}, "
              f"L1 {np.abs(r_ism - r_exact).sum() / r_exact.sum():.3f}; ISM render {seconds:.2f} s",
              flush=True)


if __name__ == "__main__":
    main()
