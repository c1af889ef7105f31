#!/usr/bin/env python3
"""Issue 27's equal-error table on the Cornell box at SIDE x SIDE: tofsim IR
(CPU backend) against mitransient, by hand, never in CI. mitransient renders
the truth (max_depth 3: direct + one bounce, TRUTH_SPP) and a ladder of spp
(64 .. 16384); each tofsim variant's relative L1 error (R + G + B, the
transient rebinned to 100 ps) over all pixels and over interior pixels
(the 3 x 3 neighbourhood's pixel centres all on one of the scene's glTF
meshes, by a ray cast here), and
mitransient's seconds to the same error, interpolated log-log between its
runs. tofsim's time is its process wall (the whole run) and stats.seconds.

    python3 -m venv ~/mt && ~/mt/bin/pip install mitransient numpy
    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
      ~/mt/bin/python bench/equal_error/compare_mitransient.py [--edges|--footprint|--merged] [--reference] [--repeat N] [SIDE=64] [TRUTH_SPP=65536] [OUT]

--edges: instead of the issue's rows, ISM at RSM 64^2 with 1, 2x2, 4x4, 8x8
samples at G-buffer edges and the default clamp: where the error is.
--footprint: ISM at RSM 64^2 and 128^2 and exact at 128^2, each with the
footprints (the default), without the VPL's patch footprint, and with point
pixels (no footprint at all): what the footprint deposit costs and buys.
--repeat N: each IR row and each ladder rung run N times, the fastest run's
seconds kept. Every run starts after an os.sync(), so that no run pays for
an earlier one's writeback (mitransient's np.save leaves 292 MB of dirty
pages at 256^2). On a virtual machine whose host takes back free pages a process's first touch of
memory costs 0.1-4 s more or less from run to run, both programs alike
(bench/README.md, "Writing volumes").
--merged: ISM at RSM 32..96^2 with 2x2..4x4 samples at edges, merged
(render.indirect.merge_pixel_samples): the best rows over all pixels.
--reference: the ladder is tofsim's own reference path tracer (the CLI,
`renderer: reference`, box pixel filter, 2 interactions, the spot light),
its process wall at 64 .. 4096 paths per pixel, instead of mitransient's;
the truth stays mitransient's.
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
# --edges: where the error is, by edge samples (ISM, RSM 64^2, the default clamp).
EDGE_VARIANTS = [
    (f"ISM, RSM 64^2, {n}x{n} at edges, clamp 100",
     ["render.indirect.rsm_resolution=64", "render.indirect.visibility=ism",
      f"render.pixel_samples={n}", "render.adaptive_pixel_samples=true",
      "render.indirect.geometry_clamp=100"]) for n in (1, 2, 4, 8)]
# --footprint: what the pixel and VPL footprints cost and buy (1 sample, clamp 0).
FOOTPRINT_VARIANTS = [
    (f"{vis}, RSM {rsm}^2, {what}",
     [f"render.indirect.rsm_resolution={rsm}", f"render.indirect.visibility={vis}"] + sets)
    for vis, rsm in (("ism", 64), ("ism", 128), ("exact", 128))
    for what, sets in (("footprint", []), ("no VPL footprint", ["render.indirect.vpl_footprint=false"]),
                       ("point pixels", ["render.pixel_footprint=false"]))]
# --merged: the best all-pixel rows, ISM with merged pixel samples
# (render.indirect.merge_pixel_samples) at edges.
MERGED_VARIANTS = [
    (f"ISM, RSM {rsm}^2, {n}x{n} at edges, merged",
     [f"render.indirect.rsm_resolution={rsm}", "render.indirect.visibility=ism",
      f"render.pixel_samples={n}", "render.adaptive_pixel_samples=true",
      "render.indirect.merge_pixel_samples=true"])
    for rsm, n in ((32, 3), (32, 4), (48, 3), (48, 4), (64, 2), (64, 3), (64, 4), (80, 3), (96, 3))]
COMMON = ["output.video=false", "sensors=[]", "output.components=[]", "light.cone_angle=30 deg",
          "light.cone_falloff=0 deg", "time.start=1.5 m", "time.bin_width=20 ps", f"time.bins={BINS}",
          "render.indirect.geometry_clamp=0"]  # the protocol's clamp 0 (EDGE_VARIANTS set their own)


def rebinned(v):
    """(H, W, T, 3) -> (H, W, T / REBIN), R + G + B."""
    s = v.sum(axis=3)
    t = (s.shape[2] // REBIN) * REBIN
    return s[:, :, :t].reshape(s.shape[0], s.shape[1], -1, REBIN).sum(axis=3)


def rel_l1(v, truth, mask):
    return float(np.abs(v - truth)[mask].sum() / np.abs(truth)[mask].sum())


def plane_ids(side):
    """The glTF mesh (one plane or block) each pixel centre sees, -1 for
    none: the demo camera's rays (tofsim's pinhole: right = forward x up)
    against the scene's triangles (Moller-Trumbore)."""
    import base64
    import struct
    doc = json.load(open(os.path.join(ROOT, "configs", "scenes", "cornell_box.gltf")))
    blob = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    tris, ids = [], []
    for mesh_id, m in enumerate(doc["meshes"]):
        acc = doc["accessors"][m["primitives"][0]["attributes"]["POSITION"]]
        view = doc["bufferViews"][acc["bufferView"]]
        xyz = np.array(struct.unpack_from(f"<{3 * acc['count']}f", blob, view.get("byteOffset", 0)),
                       dtype=np.float64).reshape(-1, 3, 3)
        tris.append(xyz)
        ids += [mesh_id] * len(xyz)
    tris, ids = np.concatenate(tris), np.array(ids)
    eye = np.array([0.278, 0.273, -0.8])
    forward, up = np.array([0.0, 0.0, 1.0]), np.array([0.0, 1.0, 0.0])
    right = np.cross(forward, up)
    t = math.tan(math.radians(39.3076481) / 2)
    u = (2 * (np.arange(side) + 0.5) / side - 1) * t
    v = (1 - 2 * (np.arange(side) + 0.5) / side) * t
    d = forward[None, None] + u[None, :, None] * right + v[:, None, None] * up  # (H, W, 3)
    d = d.reshape(-1, 3)
    e1, e2 = tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]
    p = np.cross(d[:, None], e2[None])                      # (R, T, 3)
    det = np.einsum("rtk,tk->rt", p, e1)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        s = eye[None] - tris[:, 0]                         # (T, 3)
        bu = np.einsum("rtk,tk->rt", p, s) * inv
        q = np.cross(s, e1)                                # (T, 3)
        bv = np.einsum("rk,tk->rt", d, q) * inv
        dist = np.einsum("tk,tk->t", e2, q)[None] * inv
    hit = (np.abs(det) > 1e-12) & (bu >= 0) & (bv >= 0) & (bu + bv <= 1) & (dist > 1e-6)
    dist = np.where(hit, dist, np.inf)
    best = dist.argmin(axis=1)
    out = np.where(np.isfinite(dist.min(axis=1)), ids[best], -1)
    return out.reshape(side, side)


def interior(ids):
    """Pixels whose 3 x 3 neighbourhood's centres all see the pixel's plane."""
    ok = np.zeros_like(ids, dtype=bool)
    c = ids[1:-1, 1:-1]
    same = c >= 0
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            same &= ids[1 + dy:ids.shape[0] - 1 + dy, 1 + dx:ids.shape[1] - 1 + dx] == c
    ok[1:-1, 1:-1] = same
    return ok


REPEAT = 1  # --repeat: runs per row and rung, the fastest kept


def mitransient(spp, side, out):
    env = dict(os.environ)
    best = math.inf
    for _ in range(REPEAT):
        os.sync()
        r = subprocess.run([sys.executable, MT, str(spp), "3", out, str(side), str(BINS)], env=env,
                           check=True, capture_output=True, text=True)
        best = min(best, json.loads(r.stdout.strip().splitlines()[-1])["seconds"])
    return best


def tofsim(side, sets, out):
    args = [TOFSIM, "render", os.path.join(ROOT, "configs", "cornell_box.yaml"), "--backend", "cpu",
            "-q", "-o", out, "--set", f"camera.resolution=[{side}, {side}]"]
    for s in COMMON + sets:
        args += ["--set", s]
    wall = render = math.inf
    for _ in range(REPEAT):
        os.sync()
        start = time.time()
        subprocess.run(args, check=True)
        wall = min(wall, time.time() - start)
        render = min(render, json.load(open(os.path.join(out, "transient.json")))["stats"]["seconds"])
    return np.load(os.path.join(out, "transient.npy")), np.load(os.path.join(out, "depth.npy")), \
        wall, render


def tofsim_reference(spp, side, out):
    """tofsim's reference path tracer at `spp` (box filter, direct + one
    bounce) on the protocol's light and time axis: (volume, process wall s)."""
    _, _, wall, _ = tofsim(side, ["render.renderer=reference", "render.reference.bounces=2",
                                  f"render.reference.samples_per_pixel={spp}",
                                  "render.reference.pixel_filter=box"], out)
    return np.load(os.path.join(out, "transient.npy")), wall


def silhouettes(depth):
    """Pixels whose 3 x 3 neighbourhood's depth jumps by more than 5 %: the
    silhouettes (an edge pixel that is not one is a crease)."""
    side = depth.shape[0]
    pad = np.pad(depth, 1, mode="edge")
    around = np.stack([pad[1 + dy:1 + dy + side, 1 + dx:1 + dx + side] for dy in (-1, 0, 1) for dx in (-1, 0, 1)])
    return np.abs(around - depth[None]).max(axis=0) > 0.05 * depth


def seconds_to(error, ladder):
    """mitransient's seconds to `error`, log-log between its runs (None off the ladder)."""
    pts = sorted(ladder, key=lambda p: -p[1])  # (seconds, error), error decreasing
    for (s0, e0), (s1, e1) in zip(pts, pts[1:]):
        if e1 <= error <= e0:
            f = (math.log(error) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(s0) + f * (math.log(s1) - math.log(s0)))
    return None


def main():
    global REPEAT
    variants = VARIANTS
    if "--repeat" in sys.argv:
        at = sys.argv.index("--repeat")
        REPEAT = int(sys.argv[at + 1])
        del sys.argv[at:at + 2]
    against_reference = "--reference" in sys.argv
    if against_reference:
        sys.argv.remove("--reference")
    for flag, rows in (("--edges", EDGE_VARIANTS), ("--footprint", FOOTPRINT_VARIANTS),
                       ("--merged", MERGED_VARIANTS)):
        if flag in sys.argv:
            sys.argv.remove(flag)
            variants = rows
    side = int(sys.argv[1]) if len(sys.argv) > 1 else 64
    truth_spp = int(sys.argv[2]) if len(sys.argv) > 2 else 65536
    folder = sys.argv[3] if len(sys.argv) > 3 else tempfile.mkdtemp(prefix="tofsim-mt-")
    os.makedirs(folder, exist_ok=True)
    truth_file = os.path.join(folder, f"truth_{side}_{truth_spp}.npy")
    if not os.path.exists(truth_file):
        mitransient(truth_spp, side, truth_file)
    truth = rebinned(np.load(truth_file))
    runs = [(name, *tofsim(side, sets, os.path.join(folder, f"tofsim{i}")))
            for i, (name, sets) in enumerate(variants)]
    inside = np.broadcast_to(interior(plane_ids(side))[:, :, None], truth.shape)
    everywhere = np.ones_like(truth, dtype=bool)
    ladder_in, ladder_all = [], []
    spp = 64
    ladder_name = "tofsim reference" if against_reference else "mitransient"
    while spp <= min(16384 if not against_reference else 4096, truth_spp // 4):
        if against_reference:
            volume, s = tofsim_reference(spp, side, os.path.join(folder, f"reference{spp}"))
            v = rebinned(volume)
        else:
            f = os.path.join(folder, f"mt_{side}_{spp}.npy")
            s = mitransient(spp, side, f)
            v = rebinned(np.load(f))
        ladder_in.append((s, rel_l1(v, truth, inside)))
        ladder_all.append((s, rel_l1(v, truth, everywhere)))
        print(f"{ladder_name} {spp} spp: {s:.2f} s, L1 interior {ladder_in[-1][1]:.2%} / all {ladder_all[-1][1]:.2%}")
        spp *= 4
    print(f"\n{side}x{side}, truth mitransient {truth_spp} spp, {inside[:, :, 0].sum()} interior pixels of {side * side}"
          f", fastest of {REPEAT} run(s) each")
    print("| tofsim IR (CPU backend, clamp 0) | process s / render s | transient L1 interior / all | "
          f"{ladder_name} s to the same error, interior / all | speed-up (process) interior / all | "
          "edges' share of the error | L1 by pixel class: interior / silhouette / crease |")
    print("|---|---|---|---|---|---|---|")
    for name, v, depth, wall, render in runs:
        ei, ea = rel_l1(rebinned(v), truth, inside), rel_l1(rebinned(v), truth, everywhere)
        ti, ta = seconds_to(ei, ladder_in), seconds_to(ea, ladder_all)
        fmt = lambda t: "off the ladder" if t is None else f"{t:.2f}"
        sp = lambda t: "-" if t is None else f"{t / wall:.1f}x"
        edge_share = float(np.abs(rebinned(v) - truth)[~inside].sum() / np.abs(rebinned(v) - truth).sum())
        # Each class's share of the all-pixel relative L1 (they add up to it).
        per_pixel = np.abs(rebinned(v) - truth).sum(axis=2) / truth.sum()
        sil = ~inside[:, :, 0] & silhouettes(depth)
        crease = ~inside[:, :, 0] & ~sil
        classes = " / ".join(f"{per_pixel[m].sum():.1%}" for m in (inside[:, :, 0], sil, crease))
        print(f"| {name} | {wall:.2f} / {render:.2f} | {ei:.1%} / {ea:.1%} | {fmt(ti)} / {fmt(ta)} | "
              f"{sp(ti)} / {sp(ta)} | {edge_share:.0%} | {classes} |")


if __name__ == "__main__":
    main()
