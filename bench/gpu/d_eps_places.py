#!/usr/bin/env python3
"""The D(eps) law averaged over places along the resonance, from bench/gpu/science.sh (part 2) run
with AW_DSCAN_CENTRES: a table, the law's fits and a picture.

    python3 bench/gpu/d_eps_places.py [--svg PATH] [--csv PATH] RESULTS_DIR_OR_CSV...

Each RESULTS_DIR holds dscan_<eps>@<c>/summary.json: the diffusion coefficient along the resonance
of the square about (c, c) (--csv writes them as one table, which this script reads back).
One square is one sample of the local D, which changes by factors 6-32
from place to place (docs/frequencies.md, "The D(eps) scan"); so for each eps this takes the mean of
ln D over the places (the geometric mean of D) and its standard error over them, and fits
ln D = ln D0 - c eps^-a weighted by those errors: for each a the weighted least-squares line, its
chi-square, and the chi-square above the best (a 95 % interval for a where that is below 3.84).
A power law ln D = ln D0 + n ln eps is fitted the same way. Pure Python (d_eps_fit.py's line fit).
"""
import csv
import glob
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from d_eps_fit import fit_line, svg_axes  # noqa: E402


FIELDS = ["D", "D_error", "slope_first_half", "slope_second_half", "drift"]


def load(sources):
    """(eps, c) -> the along_fit entry, from results directories or from CSV files written by --csv."""
    cells = {}
    for src in sources:
        if src.endswith(".csv"):
            for row in csv.DictReader(open(src)):
                cells[(float(row["eps"]), float(row["c"]))] = {k: float(row[k]) for k in FIELDS}
            continue
        for path in glob.glob(os.path.join(src, "dscan_*@*", "summary.json")):
            name = os.path.basename(os.path.dirname(path))[len("dscan_"):]
            eps, c = (float(v) for v in name.split("@"))
            cells[(eps, c)] = json.load(open(path))["analyses"]["diffusion"]["along_fit"]
    return cells


def write_csv(cells, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["eps", "c"] + FIELDS)
        for (e, c), fit in sorted(cells.items()):
            w.writerow([e, c] + [repr(fit[k]) for k in FIELDS])


def per_eps(cells):
    """eps -> (mean of ln D, its standard error, number of places); only eps with >= 3 places."""
    out = {}
    for eps in sorted({e for e, _ in cells}):
        logs = [math.log(f["D"]) for (e, _), f in cells.items() if e == eps and f["D"] > 0]
        if len(logs) < 3:
            continue
        m = sum(logs) / len(logs)
        sd = math.sqrt(sum((x - m) ** 2 for x in logs) / (len(logs) - 1))
        out[eps] = (m, sd / math.sqrt(len(logs)), len(logs))
    return out


def fit(points, x_of):
    xs = [x_of(e) for e in points]
    ys = [m for m, _, _ in points.values()]
    ws = [1 / se ** 2 for _, se, _ in points.values()]
    return fit_line(xs, ys, ws)


def svg(points, cells, a, p, q, path):
    W, H, m = 600, 400, 64
    X0 = min(e ** -a for e in points)
    X1 = max(e ** -a for e in points)
    ys = [math.log10(f["D"]) for f in cells.values() if f["D"] > 0]
    y0, y1 = math.floor(min(ys)), math.ceil(max(ys))
    X = lambda x: m + (x - X0) / (X1 - X0) * (W - 2 * m)
    Y = lambda y: H - m - (y - y0) / (y1 - y0) * (H - 2 * m)
    out = svg_axes(W, H, m, f"eps^-{a:g} (eps from {max(points):g} to {min(points):g})",
                   "log10 D along the resonance (per T)")
    for k in range(5):
        x = X0 + (X1 - X0) * k / 4
        out.append(f'<text x="{X(x):.1f}" y="{H - m + 16}" text-anchor="middle">{x:.2f}</text>')
    for y in range(y0, y1 + 1):
        out.append(f'<text x="{m - 6}" y="{Y(y) + 4:.1f}" text-anchor="end">{y}</text>')
    for (e, _), f in cells.items():
        if f["D"] > 0 and e in points:
            out.append(f'<circle cx="{X(e ** -a):.1f}" cy="{Y(math.log10(f["D"])):.1f}" r="2.5" fill="#9ab"/>')
    line = [(x, (p + q * x) / math.log(10)) for x in (X0, X1)]
    out.append(f'<line x1="{X(line[0][0]):.1f}" y1="{Y(line[0][1]):.1f}" x2="{X(line[1][0]):.1f}" '
               f'y2="{Y(line[1][1]):.1f}" stroke="#c33" stroke-dasharray="6 4"/>')
    for e, (mu, se, _) in points.items():
        x, y, d = X(e ** -a), mu / math.log(10), se / math.log(10)
        out.append(f'<line x1="{x:.1f}" y1="{Y(y - d):.1f}" x2="{x:.1f}" y2="{Y(y + d):.1f}" stroke="#124" stroke-width="2"/>')
        out.append(f'<circle cx="{x:.1f}" cy="{Y(y):.1f}" r="4.5" fill="#124"/>')
    out.append(f'<text x="{W - m}" y="{m - 24}" text-anchor="end">grey: each place; dark: geometric mean over places, standard error</text>')
    out.append(f'<text x="{W - m}" y="{m - 8}" text-anchor="end" fill="#c33">D0 exp(-c / eps^{a:g}), c = {-q:.3g}</text>')
    out.append("</svg>")
    open(path, "w").write("\n".join(out) + "\n")


def main():
    args = sys.argv[1:]
    path = table = None
    while args[:1] in (["--svg"], ["--csv"]):
        if args[0] == "--svg":
            path = args[1]
        else:
            table = args[1]
        args = args[2:]
    cells = load(args)
    if table:
        write_csv(cells, table)
    points = per_eps(cells)
    if len(points) < 3:
        sys.exit("fewer than 3 values of eps with 3 places or more")
    places = sorted({c for _, c in cells})
    print("D along the resonance (per T) by place c (the square about (c, c)) and eps:\n")
    print("| eps | " + " | ".join(f"{c:g}" for c in places) + " | geometric mean | × or ÷ (standard error) |")
    print("|---" * (len(places) + 3) + "|")
    for e in sorted(points):
        row = [f"{cells[(e, c)]['D']:.1e}" if (e, c) in cells else "" for c in places]
        mu, se, _ = points[e]
        print(f"| {e:g} | " + " | ".join(row) + f" | **{math.exp(mu):.2e}** | {math.exp(se):.2f} |")
    n = len(points)
    law = lambda a: fit(points, lambda e: e ** -a)
    fits = {a: law(a) for a in [0.05 * k for k in range(1, 41)]}  # the grid for the best a and its interval
    best = min(fits, key=lambda a: fits[a][2])
    print(f"\nln D = ln D0 - c eps^-a weighted by the standard errors ({n} values of eps, {n - 2} degrees of freedom "
          "at a fixed a):\n")
    print("| a | c | D0 | chi-square | above the best |")
    print("|---|---|---|---|---|")
    for a in (0.1, 0.21, 0.25, 0.3, 0.5, 0.75, 1.0, 1.5, 2.0):
        p, q, chi2 = law(a)
        print(f"| {a:g} | {-q:.3g} | {math.exp(p):.3g} | {chi2:.2f} | {chi2 - fits[best][2]:.2f} |")
    inside = [a for a in sorted(fits) if fits[a][2] - fits[best][2] < 3.84]
    print(f"\nbest a on the grid: {best:g} (chi-square {fits[best][2]:.2f}); a with chi-square within 3.84 of the "
          f"best (95 %): {min(inside):g} to {max(inside):g}")
    p, q, chi2 = fit(points, math.log)
    print(f"power law ln D = ln D0 + n ln eps: n = {q:.2f}, chi-square {chi2:.2f}")
    if path:
        p, q, _ = law(0.25)
        svg(points, cells, 0.25, p, q, path)


if __name__ == "__main__":
    main()
