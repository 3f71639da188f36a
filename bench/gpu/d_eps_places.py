#!/usr/bin/env python3
"""The D(eps) law averaged over places along the resonance, from bench/gpu/science.sh (part 2) run
with AW_DSCAN_CENTRES: a table, the law's fits and a picture.

    python3 bench/gpu/d_eps_places.py [--svg PATH] [--csv PATH] [--places C,C,..] [--eps LO:HI]
                                      [--limit K] RESULTS_DIR_OR_CSV...

Each RESULTS_DIR holds dscan_<eps>@<c>/summary.json: the diffusion coefficient along the resonance
of the square about (c, c) (--csv writes them as one table, which this script reads back).
--places and --eps fit a subset: only those places, only eps in [LO, HI].
One square is one sample of the local D, which changes by factors 6-32 from place to place
(docs/frequencies.md, "The D(eps) scan"); so for each eps this takes the mean of ln D over the
places (the geometric mean of D) and its standard error over them, and fits
ln D = ln D0 - c eps^-a weighted by those errors: for each a the weighted least-squares line, its
chi-square, and the chi-square above the best (a 95 % interval for a where that is below 3.84, on a
grid of a from 0.005 to 2). As a -> 0 the law becomes a power law (eps^-a = exp(-a ln eps)):
ln D = ln D0 + n ln eps is fitted the same way.

A run whose variance fell (D <= 0) has no ln D. Dropping it biases the mean upward, so it is kept
as left-censored: its D lies below K D_error (K = 2 unless --limit K: what the run could have
resolved), and the mean and
spread of ln D over the places are the maximum-likelihood estimates of a normal distribution with
those upper limits (a Tobit model), the standard error from the likelihood's curvature. Both
treatments are printed, and the shift of each mean between them.

The means of different eps share their places, whose offsets persist from eps to eps; the last
table fits ln D = ln D0 - c eps^-a + b_place to the runs with D > 0 (an offset per place, equal
weights, the residual variance as the error) to see whether that changes the interval. Pure Python
(d_eps_fit.py's line fit).
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
A_GRID = [0.005 * k for k in range(1, 401)]  # the exponents tried: 0.005 to 2


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


def nelder_mead(f, x0, steps, iterations=4000):
    """The minimum of f over the plane from x0 (Nelder & Mead's simplex; small and dependency-free)."""
    pts = [list(x0)] + [[x0[0] + steps[0], x0[1]], [x0[0], x0[1] + steps[1]]]
    vals = [f(p) for p in pts]
    for _ in range(iterations):
        order = sorted(range(3), key=lambda i: vals[i])
        pts, vals = [pts[i] for i in order], [vals[i] for i in order]
        if abs(vals[2] - vals[0]) < 1e-13 and max(abs(pts[2][k] - pts[0][k]) for k in range(2)) < 1e-10:
            break
        mid = [(pts[0][k] + pts[1][k]) / 2 for k in range(2)]
        refl = [mid[k] + (mid[k] - pts[2][k]) for k in range(2)]
        fr = f(refl)
        if fr < vals[0]:
            exp = [mid[k] + 2 * (mid[k] - pts[2][k]) for k in range(2)]
            fe = f(exp)
            pts[2], vals[2] = (exp, fe) if fe < fr else (refl, fr)
        elif fr < vals[1]:
            pts[2], vals[2] = refl, fr
        else:
            con = [mid[k] + 0.5 * (pts[2][k] - mid[k]) for k in range(2)]
            fc = f(con)
            if fc < vals[2]:
                pts[2], vals[2] = con, fc
            else:
                for i in (1, 2):
                    pts[i] = [pts[0][k] + 0.5 * (pts[i][k] - pts[0][k]) for k in range(2)]
                    vals[i] = f(pts[i])
    return pts[0]


def log_normal_cdf(x):
    return math.log(0.5 * math.erfc(-x / math.sqrt(2)))


def censored_mean(logs, limits):
    """The maximum-likelihood mean of ln D over the places, ln D ~ N(mu, s^2), from the values `logs`
    and the upper limits `limits` (ln of them), with its standard error (from the curvature of the
    log-likelihood, times sqrt(N / (N - 1)) as for the plain mean)."""
    n = len(logs) + len(limits)

    def nll(p):
        mu, s = p[0], math.exp(p[1])
        v = sum(0.5 * ((y - mu) / s) ** 2 + math.log(s) for y in logs)
        return v - sum(log_normal_cdf((u - mu) / s) for u in limits)

    m0 = sum(logs) / len(logs)
    s0 = math.sqrt(sum((y - m0) ** 2 for y in logs) / (len(logs) - 1))
    best = nelder_mead(nll, (m0, math.log(s0)), (0.3 * s0, 0.1))
    h = 1e-4
    e = [(h, 0.0), (0.0, h)]
    H = [[0.0, 0.0], [0.0, 0.0]]
    for i in range(2):
        for j in range(2):
            at = lambda si, sj: nll([best[k] + si * e[i][k] + sj * e[j][k] for k in range(2)])
            H[i][j] = (at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4 * h * h)
    var_mu = H[1][1] / (H[0][0] * H[1][1] - H[0][1] * H[1][0])
    return best[0], math.sqrt(var_mu * n / (n - 1))


def per_eps(cells, censored, limit=2.0):
    """eps -> (mean of ln D, its standard error, places with D > 0, places with D <= 0); only eps with
    >= 3 places with D > 0. censored: runs with D <= 0 kept as upper limits limit D_error, else
    dropped."""
    out = {}
    for eps in sorted({e for e, _ in cells}):
        fits = [f for (e, _), f in cells.items() if e == eps]
        logs = [math.log(f["D"]) for f in fits if f["D"] > 0]
        limits = [math.log(limit * f["D_error"]) for f in fits if f["D"] <= 0]
        if len(logs) < 3:
            continue
        if censored and limits:
            m, se = censored_mean(logs, limits)
        else:
            m = sum(logs) / len(logs)
            se = math.sqrt(sum((x - m) ** 2 for x in logs) / (len(logs) - 1)) / math.sqrt(len(logs))
        out[eps] = (m, se, len(logs), len(limits))
    return out


def fit(points, x_of):
    xs = [x_of(e) for e in points]
    ys = [p[0] for p in points.values()]
    ws = [1 / p[1] ** 2 for p in points.values()]
    return fit_line(xs, ys, ws)


def profile(points):
    """The law's chi-square for every a of A_GRID: (a -> chi2, best a, the a within 3.84 of the best)."""
    chi2 = {a: fit(points, lambda e, a=a: e ** -a)[2] for a in A_GRID}
    best = min(chi2, key=chi2.get)
    return chi2, best, [a for a in A_GRID if chi2[a] - chi2[best] < 3.84]


def least_squares(rows, ys):
    """The residual sum of squares of ys against the columns of rows (normal equations, Gauss-Jordan
    elimination with partial pivoting)."""
    k = len(rows[0])
    A = [[sum(r[i] * r[j] for r in rows) for j in range(k)] + [sum(r[i] * y for r, y in zip(rows, ys))]
         for i in range(k)]
    for c in range(k):
        pivot = max(range(c, k), key=lambda i: abs(A[i][c]))
        A[c], A[pivot] = A[pivot], A[c]
        for i in range(k):
            if i != c:
                f = A[i][c] / A[c][c]
                A[i] = [x - f * y for x, y in zip(A[i], A[c])]
    beta = [A[i][k] / A[i][i] for i in range(k)]
    return sum((y - sum(b * x for b, x in zip(beta, r))) ** 2 for r, y in zip(rows, ys)), beta


def place_offsets(cells):
    """ln D = p + q x(eps) + b_place over the runs with D > 0 (one place's b is 0), for x = eps^-a on
    A_GRID and x = ln eps: the residual spread, the a within 3.84 residual variances of the best, the
    power law's distance from the best."""
    runs = [(e, c, math.log(f["D"])) for (e, c), f in cells.items() if f["D"] > 0]
    places = sorted({c for _, c, _ in runs})[1:]
    design = lambda x_of: [[1.0, x_of(e)] + [1.0 if c == p else 0.0 for p in places] for e, c, _ in runs]
    ys = [y for _, _, y in runs]
    rss = {a: least_squares(design(lambda e, a=a: e ** -a), ys)[0] for a in A_GRID}
    best = min(rss, key=rss.get)
    dof = len(runs) - len(places) - 2
    s2 = rss[best] / dof
    inside = [a for a in A_GRID if (rss[a] - rss[best]) / s2 < 3.84]
    power, beta = least_squares(design(math.log), ys)
    plain = least_squares([[1.0, e ** -best] for e, _, _ in runs], ys)[0] / (len(runs) - 2)  # no offsets
    print(f"\nWith an offset per place (ln D = ln D0 - c eps^-a + b_place, the {len(runs)} runs with D > 0, equal "
          f"weights): residual spread x or / {math.exp(math.sqrt(s2)):.1f} ({dof} degrees of freedom; without the "
          f"offsets x or / {math.exp(math.sqrt(plain)):.1f}); best a {best:g}, a within 3.84 residual variances: "
          f"{min(inside):g} to {max(inside):g}; power law n = {beta[1]:.2f}, {(power - rss[best]) / s2:+.2f} "
          "residual variances from the best a")


def svg(points, cells, a, path):
    """log10 D against eps^-a: every place (grey; a run with D <= 0 as a triangle at its limit 2 D_error),
    the means over the places with their standard errors, the law at a and the power law fitted."""
    W, H, m = 600, 400, 64
    X0 = min(e ** -a for e in points)
    X1 = max(e ** -a for e in points)
    ys = [math.log10(f["D"] if f["D"] > 0 else 2 * f["D_error"]) for f in cells.values()]
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
        if e not in points:
            continue
        x = X(e ** -a)
        if f["D"] > 0:
            out.append(f'<circle cx="{x:.1f}" cy="{Y(math.log10(f["D"])):.1f}" r="2.5" fill="#9ab"/>')
        else:
            y = Y(math.log10(2 * f["D_error"]))
            out.append(f'<path d="M{x - 4:.1f},{y - 3:.1f} L{x + 4:.1f},{y - 3:.1f} L{x:.1f},{y + 4:.1f} Z" '
                       'fill="none" stroke="#9ab"/>')
    p, q, _ = fit(points, lambda e: e ** -a)
    line = [(x, (p + q * x) / math.log(10)) for x in (X0, X1)]
    out.append(f'<line x1="{X(line[0][0]):.1f}" y1="{Y(line[0][1]):.1f}" x2="{X(line[1][0]):.1f}" '
               f'y2="{Y(line[1][1]):.1f}" stroke="#c33" stroke-dasharray="6 4"/>')
    pp, n, _ = fit(points, math.log)
    curve = [X0 + (X1 - X0) * k / 40 for k in range(41)]
    out.append('<polyline fill="none" stroke="#36c" stroke-dasharray="2 3" points="' +
               " ".join(f"{X(x):.1f},{Y((pp + n * math.log(x ** (-1 / a))) / math.log(10)):.1f}" for x in curve) +
               '"/>')
    for e, (mu, se, _, _) in points.items():
        x, y, d = X(e ** -a), mu / math.log(10), se / math.log(10)
        out.append(f'<line x1="{x:.1f}" y1="{Y(y - d):.1f}" x2="{x:.1f}" y2="{Y(y + d):.1f}" stroke="#124" stroke-width="2"/>')
        out.append(f'<circle cx="{x:.1f}" cy="{Y(y):.1f}" r="4.5" fill="#124"/>')
    out.append(f'<text x="{W - m}" y="{m - 40}" text-anchor="end">grey: each place (triangle: D &lt;= 0, below 2 errors); '
               'dark: mean over places</text>')
    out.append(f'<text x="{W - m}" y="{m - 24}" text-anchor="end" fill="#c33">D0 exp(-c / eps^{a:g}), c = {-q:.3g}</text>')
    out.append(f'<text x="{W - m}" y="{m - 8}" text-anchor="end" fill="#36c">power law D0 eps^{n:.2f}: as good a fit</text>')
    out.append("</svg>")
    open(path, "w").write("\n".join(out) + "\n")


def report(points, label):
    n = len(points)
    chi2, best, inside = profile(points)
    print(f"\n{label}: ln D = ln D0 - c eps^-a weighted by the standard errors ({n} values of eps, {n - 2} "
          "degrees of freedom at a fixed a):\n")
    print("| a | c | D0 | chi-square | above the best |")
    print("|---|---|---|---|---|")
    for a in (0.1, 0.21, 0.25, 0.3, 0.5, 0.75, 1.0, 1.5, 2.0):
        p, q, c2 = fit(points, lambda e: e ** -a)
        print(f"| {a:g} | {-q:.3g} | {math.exp(p):.3g} | {c2:.2f} | {c2 - chi2[best]:.2f} |")
    low = f"{min(inside):g}" + (" (the grid's smallest a: the interval reaches a -> 0, the power law)"
                                if min(inside) == A_GRID[0] else "")
    print(f"\nbest a on the grid: {best:g} (chi-square {chi2[best]:.2f}); a with chi-square within 3.84 of the "
          f"best (95 %): {low} to {max(inside):g}")
    p, q, c2 = fit(points, math.log)
    print(f"power law ln D = ln D0 + n ln eps: n = {q:.2f}, chi-square {c2:.2f} ({c2 - chi2[best]:+.2f} against the "
          "best a)")


def main():
    args = sys.argv[1:]
    options = {}
    while args[:1] and args[0] in ("--svg", "--csv", "--places", "--eps", "--limit"):
        options[args[0]] = args[1]
        args = args[2:]
    cells = load(args)
    if "--csv" in options:
        write_csv(cells, options["--csv"])
    if "--places" in options:
        keep = {float(c) for c in options["--places"].split(",")}
        cells = {k: f for k, f in cells.items() if k[1] in keep}
    if "--eps" in options:
        lo, hi = (float(v) for v in options["--eps"].split(":"))
        cells = {k: f for k, f in cells.items() if lo <= k[0] <= hi}
    dropped, censored = per_eps(cells, False), per_eps(cells, True, float(options.get("--limit", 2)))
    if len(censored) < 3:
        sys.exit("fewer than 3 values of eps with 3 places or more")
    places = sorted({c for _, c in cells})
    print("D along the resonance (per T) by place c (the square about (c, c)) and eps; the mean of ln D over the "
          f"places with runs of D <= 0 kept as upper limits {options.get('--limit', 2)} D_error (censored), and "
          "without them (dropped):\n")
    print("| eps | " + " | ".join(f"{c:g}" for c in places) +
          " | geometric mean, censored | × or ÷ | D <= 0 | dropped | shift (decades) |")
    print("|---" * (len(places) + 6) + "|")
    for e in sorted(censored):
        row = [f"{cells[(e, c)]['D']:.1e}" if (e, c) in cells else "" for c in places]
        mu, se, _, k = censored[e]
        shift = (mu - dropped[e][0]) / math.log(10)
        print(f"| {e:g} | " + " | ".join(row) + f" | **{math.exp(mu):.2e}** | {math.exp(se):.2f} | {k} | "
              f"{math.exp(dropped[e][0]):.2e} | {shift:+.2f} |")
    report(censored, "Censored (runs with D <= 0 as upper limits)")
    report(dropped, "Dropped (runs with D <= 0 left out: the means biased upward)")
    place_offsets(cells)
    if "--svg" in options:
        svg(censored, cells, 0.25, options["--svg"])


if __name__ == "__main__":
    main()
