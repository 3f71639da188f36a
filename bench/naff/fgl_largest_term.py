#!/usr/bin/env python3
"""The frequencies of an FGL frequency map against an independent NAFF (docs/frequencies.md, "The
largest term of an angle").

    python3 bench/naff/fgl_largest_term.py RUN_DIR [RUN_DIR ...]

Each RUN_DIR is the output of scenes/fgl_frequency_map.toml at a small grid, e.g.

    arnoldweb run scenes/fgl_frequency_map.toml --device cpu --set ensemble.grid.resolution=[64,64] \\
        --set output.images=false --out out/map64

This integrates the same initial conditions in numpy (Yoshida's 4th-order composition of leapfrog
steps of 0.01 T: not arnoldweb's integrator, so chaotic orbits differ slightly), samples the angles
as arnoldweb does (every `every` T from t = every, two windows of `samples`), and finds each
signal's largest term independently: |phi| of the Hanning-windowed signal on a zero-padded FFT
(1/16 of a bin), its 3 largest local maxima refined by Brent's method on |phi| summed directly,
the highest. It prints how many signals of frequencies.h5 differ from that by more than 1e-4 turns
per T (integration differences are ~1e-6), and the largest difference. Needs numpy, scipy, h5py.
"""
import json
import sys

import h5py
import numpy as np
from scipy.optimize import minimize_scalar


def samples(eps, i1, i2, every, n, h=0.01):
    """The angles (turns) of fgl orbits from actions (i1, i2), angles 0, I3 = 0: 2 n samples x 3 x N."""
    u = np.zeros((3, i1.size))
    p = np.stack([i1, i2, np.zeros(i1.size)])
    w1 = 1 / (2 - 2 ** (1 / 3))
    w0 = 1 - 2 * w1
    sub = int(round(every / h))
    out = np.empty((2 * n, 3, i1.size))
    for k in range(2 * n):
        for _ in range(sub):
            for w in (w1, w0, w1):
                u[:2] += 0.5 * w * h * p[:2]
                u[2] += 0.5 * w * h
                s, c = np.sin(2 * np.pi * u), np.cos(2 * np.pi * u)
                p -= w * h * 2 * np.pi * eps * s / (c.sum(0) + 4) ** 2  # dI/dT = -2 pi eps sin(phi) / D^2
                u[:2] += 0.5 * w * h * p[:2]
                u[2] += 0.5 * w * h
        out[k] = u
    return out


def largest(z, pad=16, top=3):
    """The frequency (cycles per sample) of the largest |phi| of z under the Hanning window."""
    n = len(z)
    m = np.arange(n) - (n - 1) / 2
    w = 1 + np.cos(2 * np.pi * m / (n - 1))
    phi = lambda s: abs(np.sum(w * z * np.exp(-2j * np.pi * s * m)))
    size = pad * (1 << int(np.ceil(np.log2(n))))
    spectrum = np.abs(np.fft.fft(w * z, size))
    peaks = np.where((spectrum >= np.roll(spectrum, 1)) & (spectrum >= np.roll(spectrum, -1)))[0]
    best = None
    for j in peaks[np.argsort(-spectrum[peaks])][:top]:
        s0 = j / size - (1 if j / size >= 0.5 else 0)
        r = minimize_scalar(lambda s: -phi(s), bounds=(s0 - 1 / size, s0 + 1 / size), method="bounded",
                            options={"xatol": 1e-15})
        if best is None or phi(r.x) > best[1]:
            best = (r.x, phi(r.x))
    return best[0]


def check(run):
    scene = json.load(open(run + "/summary.json"))["scene"]
    f = h5py.File(run + "/frequencies.h5")
    eps, n, every = scene["model"]["epsilon"], int(f.attrs["samples"]), float(f.attrs["every"])
    i1, i2 = np.meshgrid(f["grid/axis1"][...], f["grid/axis2"][...])
    nu = np.stack([f["nu_first"][...].reshape(-1, 3), f["nu_second"][...].reshape(-1, 3)], axis=1)
    u = samples(eps, i1.ravel(), i2.ravel(), every, n)
    differ, worst = 0, 0.0
    for i in range(i1.size):
        for window in (0, 1):
            for d in range(3):
                a = u[window * n:(window + 1) * n, d, i]
                whole = np.rint((a[-1] - a[0]) / (n - 1))
                want = (largest(np.exp(2j * np.pi * a)) + whole) / every
                diff = abs(nu[i, window, d] - want)
                differ += diff > 1e-4
                worst = max(worst, diff)
    print(f"{run}: eps {eps}, {i1.size} cells, {6 * i1.size} signals: {differ} differ from the independent NAFF by "
          f"more than 1e-4 turns per T, the largest difference {worst:.3g}")


if __name__ == "__main__":
    for run in sys.argv[1:]:
        check(run)
