#!/usr/bin/env python3
"""Relative L1 error of H files against the quadrature truth (quadrature_truth.py):
sum |H - truth| / sum truth over every sensor point and bin, after rebinning to
3 cm of path (3 bins; about 100 ps), and of the steady image (summed over time).
Usage: python3 compare.py TRUTH.npy LABEL=H.npy|capture.hdf5 ...  (NumPy; h5py for .hdf5)
"""

import sys

import numpy as np


def load(path):
    if path.endswith(".hdf5"):
        import h5py

        with h5py.File(path, "r") as f:
            return np.array(f["H"], np.float64)
    return np.load(path).astype(np.float64)


def rebin(h, k=3):
    t = h.shape[0] // k * k
    return h[:t].reshape(t // k, k, *h.shape[1:]).sum(axis=1)


def main():
    truth = load(sys.argv[1])
    rt = rebin(truth)
    for arg in sys.argv[2:]:
        label, path = arg.split("=", 1)
        h = load(path)
        transient = np.abs(rebin(h) - rt).sum() / rt.sum()
        steady = np.abs(h.sum(0) - truth.sum(0)).sum() / truth.sum()
        print(f"{label}\ttransient_L1 {transient:.4f}\tsteady_L1 {steady:.4f}\tenergy {h.sum() / truth.sum():.4f}")


if __name__ == "__main__":
    main()
