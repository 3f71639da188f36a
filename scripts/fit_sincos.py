#!/usr/bin/env python3
"""The coefficients of the portable sin/cos kernels in lib/device/aw_math.h.

sin(2 pi u) and cos(2 pi u) are reduced exactly to f = 4u - rint(4u) in
[-1/2, 1/2]; then

    sin(pi f / 2) = f S(f^2),    cos(pi f / 2) = 1 + f^2 C(f^2),

with S and C near-minimax (Chebyshev) fits on f^2 in [0, 1/4], computed here
in 60-digit arithmetic with mpmath and rounded to double. Double: S of degree
6, C of degree 6; float: degree 3 and 3. Run: python3 scripts/fit_sincos.py
(mpmath from PyPI or Debian's python3-mpmath). The accuracy of the rounded
polynomials is measured by tests/device/test_math*.cpp.
"""
import mpmath as mp

mp.mp.dps = 60


def fit(fun, terms):
    coeffs, err = mp.chebyfit(fun, [mp.mpf(0), mp.mpf(1) / 4], terms, error=True)
    return [float(c) for c in coeffs[::-1]], err  # ascending powers


def sin_over_f(w):
    return mp.sin(mp.pi / 2 * mp.sqrt(w)) / mp.sqrt(w) if w > 0 else mp.pi / 2


def cos_minus_one(w):
    return (mp.cos(mp.pi / 2 * mp.sqrt(w)) - 1) / w if w > 0 else -(mp.pi / 2) ** 2 / 2


for name, terms_s, terms_c in (("double", 7, 7), ("float", 4, 4)):
    s, es = fit(sin_over_f, terms_s)
    c, ec = fit(cos_minus_one, terms_c)
    print(f"{name}: S (fit error {mp.nstr(es, 3)}), lowest power first")
    print("  " + ", ".join(repr(x) for x in s))
    print(f"{name}: C (fit error {mp.nstr(ec, 3)}), lowest power first")
    print("  " + ", ".join(repr(x) for x in c))
