#!/usr/bin/env python3
"""Issue 45's P2: a loop of N renders of the 64^2 Cornell box protocol with
the light moving, tofsim.Renderer against mitransient's own Python loop, at
equal all-pixel transient error against a converged truth. Never in CI;
run by hand in a venv that has mitransient, with tofsim's module on the path:

    python3 -m venv /work/venv-mi && /work/venv-mi/bin/pip install mitransient
    apt-get install -y libllvm19
    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 PYTHONPATH=build/python \\
      /work/venv-mi/bin/python bench/renderer_loop/mitransient_loop.py \
      [--ladder 64,256,1024,4096] [--renders K] [--rows 0,1,2,3] [N=100] [TRUTH_SPP=32768] [OUT]

The protocol is bench/equal_error's (compare_mitransient.py and
mitransient_cornell.py: 371 bins of 20 ps from 1.5 m, clamp 0, tofsim's
hard 30-degree spot against mitransient's point light at the same place,
box pixel filter, near_clip 1e-5, max_depth 3 = direct + one bounce), the
error its relative L1 of R + G + B rebinned to 100 ps over all pixels. The
light moves along x from 0.20 to 0.36 m (renderer_loop.py's positions).

- The truth: mitransient at TRUTH_SPP at three of the N positions (the
  first, middle and last), cached in OUT; a loop's error is the mean of its
  renders' errors at those three.
- tofsim: for each row, tofsim.Renderer made (glTF loaded, scene prepared)
  and N renders each returned as a NumPy transient, the whole loop timed.
- mitransient: the scene loaded once (mi.load_dict), then per position the
  light moved through mi.traverse and mi.render, the transient turned into a
  NumPy array, the whole loop timed, at a ladder of spp. A rung whose loop
  would be long renders only LADDER_RENDERS positions (the three truth
  positions among them) and its loop time is extrapolated: the load, the
  first render (the kernel's compilation) and N - 1 times the mean of the
  other renders.
mitransient's seconds to a tofsim row's error are interpolated log-log
between its rungs (compare_mitransient.seconds_to). --ladder: the rungs'
spp; --renders K: every rung rendered at K positions and extrapolated (a
quick run); --rows: which of ROWS.
"""
import json
import os
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "bench", "equal_error"))
import compare_mitransient as protocol  # noqa: E402  (rebinned, rel_l1, seconds_to, COMMON)

CONFIG = os.path.join(ROOT, "configs", "cornell_box.yaml")
SIDE = 64
LADDER = (64, 256, 1024, 4096)
LADDER_RENDERS = {1024: 20, 4096: 10}  # rungs rendered at fewer positions, extrapolated to N
ROWS = [("ISM, RSM 32^2, 1 sample", ["render.indirect.rsm_resolution=32"]),
        ("ISM, RSM 32^2, 3x3 at edges, merged", ["render.indirect.rsm_resolution=32",
                                                 "render.pixel_samples=3"]),
        ("ISM, RSM 48^2, 4x4 at edges, merged", ["render.indirect.rsm_resolution=48",
                                                 "render.pixel_samples=4"]),
        ("ISM, RSM 64^2, 4x4 at edges, merged", ["render.indirect.rsm_resolution=64",
                                                 "render.pixel_samples=4"])]
MERGED = ["render.adaptive_pixel_samples=true", "render.indirect.merge_pixel_samples=true"]


def positions(n):
    return [(float(x), 0.273, -0.8) for x in np.linspace(0.2, 0.36, n)]


def truth_indices(n):
    return (0, n // 2, n - 1)


def error(volume, truth):
    t = protocol.rebinned(truth)
    return protocol.rel_l1(protocol.rebinned(volume), t, np.ones_like(t, dtype=bool))


def tofsim_loop(sets, lights, truths):
    import tofsim
    common = protocol.COMMON + [f"camera.resolution=[{SIDE}, {SIDE}]", "render.backend=cpu",
                                "light.attach_to_camera=false", "light.direction=[0, 0, 1]"]
    if any(s.startswith("render.pixel_samples") for s in sets):
        sets = sets + MERGED
    start, cpu = time.perf_counter(), time.process_time()
    renderer = tofsim.Renderer(CONFIG, overrides=common + sets)
    kept = {}
    for i, p in enumerate(lights):
        v = renderer.render([f"light.position=[{p[0]}, {p[1]}, {p[2]}]"]).transient
        if i in truths:
            kept[i] = v
    seconds, cpu = time.perf_counter() - start, time.process_time() - cpu
    return seconds, cpu, float(np.mean([error(kept[i], truths[i]) for i in truths]))


def mitransient_loop(spp, lights, truths, renders=None):
    """(loop seconds for all of `lights`, the same in process CPU seconds,
    mean error at the truth positions, per-render seconds). `renders`: only
    that many positions (the truth ones among them), the loop's times
    extrapolated."""
    import drjit as dr
    import mitsuba as mi
    mi.set_variant("llvm_ad_rgb")
    import mitransient  # noqa: F401
    import mitransient_cornell as mc
    n = len(lights)
    order = list(range(n)) if renders is None else sorted(
        set(np.linspace(0, n - 1, renders).round().astype(int)) | set(truths))
    with tempfile.TemporaryDirectory() as folder:
        start, cpu0 = time.perf_counter(), time.process_time()
        scene = mi.load_dict(mc.scene(folder, SIDE, protocol.BINS, spp, 3))
        params = mi.traverse(scene)
        load, load_cpu = time.perf_counter() - start, time.process_time() - cpu0
        each, each_cpu, kept = [], [], {}
        for i in order:
            t0, c0 = time.perf_counter(), time.process_time()
            p = lights[i]
            params["light.position"] = mi.Point3f(*p)  # world, as tofsim's light.position
            params.update()
            _, transient = mi.render(scene, spp=spp)
            v = np.array(transient, dtype=np.float32)
            each.append(time.perf_counter() - t0)
            each_cpu.append(time.process_time() - c0)
            if i in truths:
                kept[i] = v
    def loop(first, times):
        return first + (sum(times) if len(order) == n else times[0] + (n - 1) * float(np.mean(times[1:])))

    return loop(load, each), loop(load_cpu, each_cpu), \
        float(np.mean([error(kept[i], truths[i]) for i in truths])), each


def truth_volumes(lights, spp, out):
    truths = {}
    for i in truth_indices(len(lights)):
        f = os.path.join(out, f"truth_{SIDE}_{spp}_{lights[i][0]:.4f}.npy")
        if not os.path.exists(f):
            _, _, _ = mitransient_truth(spp, lights[i], f)
        truths[i] = np.load(f)
    return truths


def mitransient_truth(spp, light, path):
    import mitsuba as mi
    mi.set_variant("llvm_ad_rgb")
    import mitransient  # noqa: F401
    import mitransient_cornell as mc
    with tempfile.TemporaryDirectory() as folder:
        scene = mi.load_dict(mc.scene(folder, SIDE, protocol.BINS, spp, 3))
        params = mi.traverse(scene)
        params["light.position"] = mi.Point3f(*light)
        params.update()
        start = time.perf_counter()
        _, transient = mi.render(scene, spp=spp)
        v = np.array(transient, dtype=np.float32)
        seconds = time.perf_counter() - start
    np.save(path, v)
    print(f"truth at x = {light[0]:.3f}: {spp} spp, {seconds:.1f} s", flush=True)
    return v, seconds, path


def option(name, default):
    if name not in sys.argv:
        return default
    at = sys.argv.index(name)
    value = sys.argv[at + 1]
    del sys.argv[at:at + 2]
    return [int(v) for v in value.split(",")]


def main():
    global LADDER, LADDER_RENDERS, ROWS
    LADDER = option("--ladder", LADDER)
    renders = option("--renders", None)
    if renders:
        LADDER_RENDERS = {spp: renders[0] for spp in LADDER}
    ROWS = [ROWS[i] for i in option("--rows", range(len(ROWS)))]
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    truth_spp = int(sys.argv[2]) if len(sys.argv) > 2 else 32768
    out = sys.argv[3] if len(sys.argv) > 3 else tempfile.mkdtemp(prefix="tofsim-mtloop-")
    os.makedirs(out, exist_ok=True)
    lights = positions(n)
    truths = truth_volumes(lights, truth_spp, out)
    ladder, ladder_cpu = [], []
    for spp in LADDER:
        seconds, cpu, err, each = mitransient_loop(spp, lights, truths, LADDER_RENDERS.get(spp))
        ladder.append((seconds, err))
        ladder_cpu.append((cpu, err))
        print(f"mitransient {spp} spp: loop {seconds:.1f} s, {cpu:.1f} CPU-s ({len(each)} renders, first "
              f"{each[0]:.2f} s, then {np.mean(each[1:]):.3f} s each), L1 all {err:.2%}", flush=True)
    print(f"\n{n} renders at {SIDE}^2, the light moving; truth mitransient {truth_spp} spp at "
          f"{len(truths)} positions\n")
    print("| tofsim IR (CPU backend, clamp 0) | tofsim.Renderer loop s / CPU-s | per render ms | L1 all | "
          "mitransient loop s / CPU-s to the same error | speed-up, wall / CPU |")
    print("|---|---|---|---|---|---|")
    fmt = lambda t: "off the ladder" if t is None else f"{t:.1f}"
    ratio = lambda t, s: "-" if t is None else f"{t / s:.1f}x"
    rows = []
    for name, sets in ROWS:
        seconds, cpu, err = tofsim_loop(sets, lights, truths)
        t, tc = protocol.seconds_to(err, ladder), protocol.seconds_to(err, ladder_cpu)
        rows.append((name, seconds, cpu, err))
        print(f"| {name} | {seconds:.2f} / {cpu:.2f} | {seconds / n * 1000:.0f} | {err:.2%} | "
              f"{fmt(t)} / {fmt(tc)} | {ratio(t, seconds)} / {ratio(tc, cpu)} |", flush=True)
    json.dump({"ladder": ladder, "ladder_cpu": ladder_cpu, "rows": rows},
              open(os.path.join(out, f"loop_{n}.json"), "w"))


if __name__ == "__main__":
    main()
