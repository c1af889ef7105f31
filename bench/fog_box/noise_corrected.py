#!/usr/bin/env python3
"""A render's error against a truth nobody rendered: the noise-corrected
squared error from two independent reference renders (bench/README.md,
"fog_box", "Noise-corrected error").

With A = T + a and B = T + b two renders of the truth T whose noises a, b
are independent, of mean zero and of the same variance, and X a render
independent of both, M = (A + B) / 2 gives

    E ||X - M||^2 = ||X - T||^2 + E ||a + b||^2 / 4
    E ||A - B||^2 = E ||a - b||^2 = E ||a + b||^2

so ||X - M||^2 - ||A - B||^2 / 4 estimates ||X - T||^2 without bias, and
||M||^2 - ||A - B||^2 / 4 estimates ||T||^2. Their ratio's square root is
X's relative RMS error (over every bin and channel of transient.npy), the
truth's noise taken out. Also printed: the truth's own relative RMS error
(||A - B||^2 / 4 over ||T||^2: M's), X's relative L1 against M (noise of M
included, as `tofsim compare` gives it) and its energy over M's.

Usage: noise_corrected.py X A B [X2 ...]   (render folders or .npy files)
       noise_corrected.py --self-test       (synthetic data, known truth)
Prints one line per X: name, rel_rms, rel_l1_vs_mean, energy.
"""

import os
import sys

try:
    import numpy as np
except ImportError:  # ctest's skip code
    print("numpy missing: skipped", file=sys.stderr)
    sys.exit(77)


def load(path):
    if os.path.isdir(path):
        path = os.path.join(path, "transient.npy")
    return np.load(path).astype(np.float64).ravel()


def truth_terms(a, b):
    """(M, the estimate of ||T||^2, ||A - B||^2 / 4)."""
    mean = 0.5 * (a + b)
    half_diff2 = float(np.sum((a - b) ** 2)) / 4.0
    return mean, float(np.sum(mean**2)) - half_diff2, half_diff2


def errors(x, a, b):
    """X's noise-corrected relative RMS error, relative L1 against M, and
    energy over M's."""
    mean, truth2, half_diff2 = truth_terms(a, b)
    err2 = float(np.sum((x - mean) ** 2)) - half_diff2
    # The estimate is unbiased, so it can fall below 0 for an X closer to the
    # truth than the pair can tell: reported signed (-sqrt(-e)).
    rel = np.sign(err2) * np.sqrt(abs(err2) / truth2)
    l1 = float(np.sum(np.abs(x - mean)) / np.sum(np.abs(mean)))
    return rel, l1, float(np.sum(x) / np.sum(mean))


def self_test():
    """On a synthetic truth with known noise: the corrected error matches the
    true one where the uncorrected error (against M) is far off."""
    rng = np.random.default_rng(7)
    truth = rng.gamma(0.5, 1.0, 400_000)  # a skewed, transient-like truth
    noisy = lambda sigma: truth + sigma * truth * rng.standard_normal(truth.size)
    a, b = noisy(0.3), noisy(0.3)  # a truth pair noisier than X
    x = noisy(0.1)
    true_rel = np.sqrt(np.sum((x - truth) ** 2) / np.sum(truth**2))
    rel, _, energy = errors(x, a, b)
    raw = np.sqrt(np.sum((x - 0.5 * (a + b)) ** 2) / np.sum(truth**2))
    ok = abs(rel - true_rel) < 0.05 * true_rel and raw > 1.5 * true_rel and abs(energy - 1) < 0.01
    print(f"self-test: true {true_rel:.4f}, corrected {rel:.4f}, against the mean alone {raw:.4f}: "
          f"{'ok' if ok else 'FAILED'}")
    return 0 if ok else 1


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    a, b = load(argv[-2]), load(argv[-1])
    _, truth2, half_diff2 = truth_terms(a, b)
    print(f"truth (mean of the pair): relative RMS error {np.sqrt(half_diff2 / truth2):.4f}")
    for name in argv[1:-2]:
        rel, l1, energy = errors(load(name), a, b)
        print(f"{name} rel_rms {rel:.4f} rel_l1_vs_mean {l1:.4f} energy {energy:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
