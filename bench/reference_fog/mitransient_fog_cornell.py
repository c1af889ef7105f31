#!/usr/bin/env python3
"""Issue 42, item 5, by hand: the Cornell box in fog rendered by mitransient's
transient_prbvolpath and by tofsim's reference path tracer
(build/bench/tofsim_reference_fog_cornell), compared. The scene is
bench/equal_error/mitransient_cornell.py's (the demo camera, a point light
5 cm beside it and 1 cm ahead, box filter, 20 ps bins from 1.5 m) with a
homogeneous medium inside a null-BSDF cube around everything but the pinhole
(mitransient's camera rays start in vacuum), so it fills the scene:
sigma_s 2 /m, sigma_a 0.1 /m, Henyey-Greenstein g 0.5, max_depth 3 (two
vertices, surface or medium, as the reference's bounces 2). A measurement
tool run by hand in a venv with mitransient:

    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
      ~/mt/bin/python bench/reference_fog/mitransient_fog_cornell.py SPP REF_SPP [SIDE] [BINS]

Prints each renderer's seconds, the energy ratio (all bins, pixels and
channels), the relative L1 between the image-summed transients (100 ps
bins), between the steady images, and between the whole transients rebinned
to 100 ps (per pixel: noise-dominated at these sample counts).
"""

import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "equal_error"))
import mitransient_cornell as mc  # noqa: E402  (sets the variant, registers mitransient)
import drjit as dr  # noqa: E402
import mitsuba as mi  # noqa: E402
import numpy as np  # noqa: E402

SIGMA_S, SIGMA_A, G = 2.0, 0.1, 0.5
LIGHT = (0.228, 0.273, -0.79)  # 5 cm right of the pinhole (right = -x), 1 cm ahead: inside the fog


def fog_scene(folder, side, bins, spp):
    d = mc.scene(folder, side, bins, spp, 3)
    d["integrator"] = {"type": "transient_prbvolpath", "max_depth": 3, "rr_depth": 100,
                       "camera_unwarp": False, "temporal_filter": "box"}
    sigma_t = SIGMA_S + SIGMA_A
    # transient_prbvolpath starts every camera ray in vacuum ("TODO: support
    # sensors inside media"): the fog is the interior of a null-BSDF cube
    # that holds the box and the light, whose near face is 0.1 mm in front
    # of the pinhole (tofsim's fog there: transmittance 0.9998).
    d["fog"] = {"type": "cube", "bsdf": {"type": "null"},
                "to_world": mi.ScalarTransform4f().translate([0.278, 0.273, 0.60005]).scale([3.0, 3.0, 1.39995]),
                "interior": {"type": "homogeneous", "sigma_t": sigma_t,
                             "albedo": {"type": "rgb", "value": [SIGMA_S / sigma_t] * 3},
                             "phase": {"type": "hg", "g": G}}}
    d["light"]["position"] = LIGHT
    return d


def rebin(v, k=5):
    t = v.shape[2] // k * k
    return v[:, :, :t].reshape(v.shape[0], v.shape[1], t // k, k, v.shape[3]).sum(axis=3)


def main():
    spp, ref_spp = int(sys.argv[1]), int(sys.argv[2])
    side = int(sys.argv[3]) if len(sys.argv) > 3 else 64
    bins = int(sys.argv[4]) if len(sys.argv) > 4 else 200
    with tempfile.TemporaryDirectory() as folder:
        s = mi.load_dict(fog_scene(folder, side, bins, spp))
        start = time.time()
        _, transient = mi.render(s, spp=spp)
        dr.eval(transient)
        dr.sync_thread()
        mt_seconds = time.time() - start
        mt = np.array(transient, dtype=np.float64)
        out = os.path.join(folder, "ref.npy")
        binary = os.path.join(HERE, "..", "..", "build", "bench", "tofsim_reference_fog_cornell")
        ref_info = json.loads(subprocess.check_output([binary, str(ref_spp), out, str(side), str(bins)]))
        ref = np.load(out).astype(np.float64)
    a, b = rebin(mt), rebin(ref)
    l1 = np.abs(a - b).sum() / np.abs(b).sum()
    l1_flipped = np.abs(a[:, ::-1] - b).sum() / np.abs(b).sum()
    ta, tb = a.sum(axis=(0, 1, 3)), b.sum(axis=(0, 1, 3))  # the image's transient
    sa, sb = mt.sum(axis=(2, 3)), ref.sum(axis=(2, 3))    # steady images
    print(json.dumps({
                      "image_transient_L1": float(np.abs(ta - tb).sum() / np.abs(tb).sum()),
                      "steady_L1": float(np.abs(sa - sb).sum() / np.abs(sb).sum()),"mitransient_spp": spp, "mitransient_seconds": round(mt_seconds, 2),
                      "reference_spp": ref_spp, "reference_seconds": ref_info["seconds"],
                      "energy_ratio_mitransient_over_reference": float(mt.sum() / ref.sum()),
                      "relative_L1_100ps": float(l1), "relative_L1_100ps_mirrored": float(l1_flipped),
                      "image_total_per_100ps_mitransient": [float(x) for x in a.sum(axis=(0, 1, 3))[:12]],
                      "image_total_per_100ps_reference": [float(x) for x in b.sum(axis=(0, 1, 3))[:12]]}))


if __name__ == "__main__":
    main()
