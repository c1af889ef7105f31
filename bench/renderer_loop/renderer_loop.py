#!/usr/bin/env python3
"""A loop of N renders with the light moving (issue 45, item 4), three ways,
the whole loop's wall time: tofsim.Renderer (the scene prepared once),
tofsim.render per position (loads the glTF and makes the renderer each
time), and one `tofsim render` process per position (as a shell loop
would). The Cornell box protocol of bench/equal_error at SIDE x SIDE (CPU
backend, 20 ps bins from 1.5 m, 371 bins, ISM RSM 32^2), the spot moved
along x. Arrays stay in memory for the first two; the CLI writes its files.

    PYTHONPATH=build/python python3 bench/renderer_loop/renderer_loop.py [N=20] [SIDE=64]
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import tofsim

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
CONFIG = os.path.join(ROOT, "configs", "cornell_box.yaml")
TOFSIM = os.path.join(ROOT, "build", "apps", "cli", "tofsim")


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    side = int(sys.argv[2]) if len(sys.argv) > 2 else 64
    common = {"output.video": False, "sensors": [], "output.components": [],
              "light.cone_angle": "30 deg", "light.cone_falloff": "0 deg",
              "light.attach_to_camera": False, "light.direction": [0, 0, 1],
              "time.start": "1.5 m", "time.bin_width": "20 ps", "time.bins": 371,
              "camera.resolution": [side, side], "render.backend": "cpu"}
    xs = np.linspace(0.2, 0.36, n)
    moved = [{"light.position": [float(x), 0.273, -0.8]} for x in xs]

    start = time.perf_counter()
    renderer = tofsim.Renderer(CONFIG, overrides=common)
    kept = [renderer.render(m).transient.sum() for m in moved]
    t_kept = time.perf_counter() - start

    start = time.perf_counter()
    fresh = [tofsim.render(tofsim.load_config(CONFIG, {**common, **m})).transient.sum() for m in moved]
    t_fresh = time.perf_counter() - start
    assert kept == fresh, "Renderer and render disagree"

    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as out:
        for m in moved:
            args = [TOFSIM, "render", CONFIG, "-q", "-o", out]
            for k, v in {**common, **m}.items():
                value = v if isinstance(v, str) else str(v).replace("True", "true").replace("False", "false")
                args += ["--set", f"{k}={value}"]
            subprocess.run(args, check=True)
    t_cli = time.perf_counter() - start
    print(f"{n} renders at {side}^2: tofsim.Renderer {t_kept:.2f} s ({t_kept / n * 1000:.0f} ms each, "
          f"{renderer.scene_preparations} scene preparation), tofsim.render {t_fresh:.2f} s "
          f"({t_fresh / t_kept:.2f}x), a process each {t_cli:.2f} s ({t_cli / t_kept:.2f}x)")


if __name__ == "__main__":
    main()
