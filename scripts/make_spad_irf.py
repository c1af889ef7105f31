#!/usr/bin/env python3
"""Writes configs/irf/spad_exgauss_2ps.csv: an instrument response as a TCSPC
measurement of a fast SPAD would record it, for configs/spad_lidar.yaml.

Shape: y-tal's parametric SPAD response (diegoroyo/tal PR #13, the research
note's [TAL13]): an exponentially modified Gaussian (SPAD jitter 20 ps FWHM,
diffusion tail 50 ps) convolved with a 30 ps FWHM Gaussian laser pulse.
Measured: 200,000 detections drawn from that law plus a flat dark/ambient
floor of 20 counts per sample, histogrammed in 2 ps samples from -200 ps to
+800 ps (500 rows). The config subtracts the floor (`floor: 20`) and puts
time zero at the peak (`t0: peak`), as one does with a real measurement.

Deterministic: a fixed seed of Python's Mersenne Twister (random.gauss and
random.expovariate), standard library only, so the committed file is what
this script writes. Usage: python3 scripts/make_spad_irf.py [out.csv]
"""

import math
import os
import random
import sys

FWHM_TO_SIGMA = 1.0 / (2.0 * math.sqrt(2.0 * math.log(2.0)))
SPAD_FWHM_S = 20e-12
TAIL_S = 50e-12
LASER_FWHM_S = 30e-12
DETECTIONS = 200_000
FLOOR_COUNTS = 20  # expected counts per sample from dark counts and ambient light
SAMPLE_S = 2e-12
FIRST_S = -200e-12
SAMPLES = 500
SEED = 24


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "configs", "irf",
                                                               "spad_exgauss_2ps.csv")
    rng = random.Random(SEED)
    sigma = math.hypot(SPAD_FWHM_S, LASER_FWHM_S) * FWHM_TO_SIGMA
    counts = [0] * SAMPLES
    for _ in range(DETECTIONS):
        t = rng.gauss(0.0, sigma) + rng.expovariate(1.0 / TAIL_S)
        k = math.floor((t - FIRST_S) / SAMPLE_S + 0.5)  # sample k covers t_k +- SAMPLE_S / 2
        if 0 <= k < SAMPLES:
            counts[k] += 1
    # The floor: Poisson(FLOOR_COUNTS) per sample, by inversion.
    for k in range(SAMPLES):
        u, n, p = rng.random(), 0, math.exp(-FLOOR_COUNTS)
        cdf = p
        while u > cdf:
            n += 1
            p *= FLOOR_COUNTS / n
            cdf += p
        counts[k] += n
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    with open(out, "w", newline="\n") as f:
        f.write("# SPAD instrument response (scripts/make_spad_irf.py): exGaussian, 20 ps FWHM\n")
        f.write("# jitter, 50 ps tail, with a 30 ps FWHM laser [TAL13]; 200000 detections on a\n")
        f.write("# floor of 20 counts per 2 ps sample. Use with floor: 20, t0: peak.\n")
        f.write("time_s,counts\n")
        for k in range(SAMPLES):
            f.write("%.4e,%d\n" % (FIRST_S + k * SAMPLE_S, counts[k]))


if __name__ == "__main__":
    main()
