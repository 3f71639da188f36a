#!/usr/bin/env python3
"""The D(eps) law from the runs of bench/gpu/science.sh (part 2): a table and a fit.

    python3 bench/gpu/d_eps_fit.py RESULTS_DIR [SVG]

RESULTS_DIR holds dscan_<eps>/summary.json (the analyses.diffusion entry of each run:
the diffusion coefficient along and across the resonance with its bootstrap error).
Fits log D = log D0 - c eps^-a to the coefficients along the resonance, weighted by
their bootstrap errors: for each a on a grid in [0.05, 1.5] the weighted linear
least-squares (log D0, c), and the a with the smallest chi-square. Prints a Markdown
table and the fit; writes an SVG of log10 D against eps^-a_best (no plotting library
needed) when SVG is given. Pure Python: runs where numpy is not installed.
"""
import glob
import json
import math
import os
import sys


def load(results):
    rows = []
    for path in glob.glob(os.path.join(results, "dscan_*", "summary.json")):
        s = json.load(open(path))
        d = s["analyses"]["diffusion"]
        name = os.path.basename(os.path.dirname(path))[len("dscan_"):]
        if "@" in name:  # another place along the resonance (AW_DSCAN_CENTRES): not in the law's fit
            continue
        eps = float(name)
        rows.append({"eps": eps, "along": d["along_fit"], "across": d["across_fit"],
                     "seconds": s["wall_seconds"], "trajectories": s["trajectories"],
                     "duration": s.get("scene", {}).get("run", {}).get("duration")})
    return sorted(rows, key=lambda r: r["eps"])


def fit_line(xs, ys, ws):
    """Weighted least squares y = p + q x; returns p, q, chi2."""
    sw = sum(ws)
    mx = sum(w * x for w, x in zip(ws, xs)) / sw
    my = sum(w * y for w, y in zip(ws, ys)) / sw
    sxx = sum(w * (x - mx) ** 2 for w, x in zip(ws, xs))
    sxy = sum(w * (x - mx) * (y - my) for w, x, y in zip(ws, xs, ys))
    q = sxy / sxx
    p = my - q * mx
    chi2 = sum(w * (y - p - q * x) ** 2 for w, x, y in zip(ws, xs, ys))
    return p, q, chi2


def fit_law(rows, fixed_a=None, weighted=True):
    # resolved coefficients only: D above three bootstrap errors
    good = [r for r in rows if r["along"]["D"] > 3 * r["along"]["D_error"] > 0]
    if len(good) < 3:
        return None
    ys = [math.log(r["along"]["D"]) for r in good]
    # 1 / var(log D) from the bootstrap, or equal weights (when the scatter between
    # neighbouring eps is far above the bootstrap errors: then chi2 / (n - 2) is the
    # variance of ln D about the law)
    ws = [(r["along"]["D"] / r["along"]["D_error"]) ** 2 if weighted else 1.0 for r in good]
    best = None
    grid = [fixed_a] if fixed_a else [0.05 + (1.5 - 0.05) * (i - 1) / 299 for i in range(1, 301)]
    for a in grid:
        xs = [r["eps"] ** -a for r in good]
        p, q, chi2 = fit_line(xs, ys, ws)
        if best is None or chi2 < best["chi2"]:
            best = {"a": a, "logD0": p, "c": -q, "chi2": chi2, "n": len(good)}
    return best


def svg_axes(W, H, m, xlabel, ylabel):
    """The opening of a W x H picture with axes m pixels in from its edges and their labels."""
    return [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
            f'<rect width="{W}" height="{H}" fill="white"/>',
            f'<line x1="{m}" y1="{H - m}" x2="{W - m}" y2="{H - m}" stroke="black"/>',
            f'<line x1="{m}" y1="{m}" x2="{m}" y2="{H - m}" stroke="black"/>',
            f'<text x="{W / 2}" y="{H - 20}" text-anchor="middle">{xlabel}</text>',
            f'<text x="15" y="{H / 2}" transform="rotate(-90 15 {H / 2})" text-anchor="middle">{ylabel}</text>']


def svg(rows, law, path):
    pts = [(r["eps"] ** -law["a"], math.log10(r["along"]["D"]),
            r["along"]["D_error"] / (r["along"]["D"] * math.log(10))) for r in rows if r["along"]["D"] > 0]
    x0, x1 = min(p[0] for p in pts), max(p[0] for p in pts)
    y0 = min(p[1] - p[2] for p in pts) - 0.3
    y1 = max(p[1] + p[2] for p in pts) + 0.3
    W, H, m = 560, 380, 60
    X = lambda x: m + (x - x0) / (x1 - x0 or 1) * (W - 2 * m)
    Y = lambda y: H - m - (y - y0) / (y1 - y0) * (H - 2 * m)
    out = svg_axes(W, H, m, f'eps^-{law["a"]:.2f}', "log10 D (along)")
    for k in range(5):
        x = x0 + (x1 - x0) * k / 4
        y = y0 + (y1 - y0) * k / 4
        out.append(f'<text x="{X(x)}" y="{H - m + 16}" text-anchor="middle">{x:.2f}</text>')
        out.append(f'<text x="{m - 6}" y="{Y(y) + 4}" text-anchor="end">{y:.1f}</text>')
    line = [(x, (law["logD0"] - law["c"] * x) / math.log(10)) for x in (x0, x1)]
    out.append(f'<line x1="{X(line[0][0])}" y1="{Y(line[0][1])}" x2="{X(line[1][0])}" y2="{Y(line[1][1])}" '
               'stroke="#c33" stroke-dasharray="6 4"/>')
    for x, y, e in pts:
        out.append(f'<line x1="{X(x)}" y1="{Y(y - e)}" x2="{X(x)}" y2="{Y(y + e)}" stroke="#236"/>')
        out.append(f'<circle cx="{X(x)}" cy="{Y(y)}" r="4" fill="#236"/>')
    out.append(f'<text x="{W - m}" y="{m - 10}" text-anchor="end">D = D0 exp(-c / eps^a): a = {law["a"]:.2f}, '
               f'c = {law["c"]:.3g}</text>')
    out.append("</svg>")
    open(path, "w").write("\n".join(out) + "\n")


def main():
    rows = load(sys.argv[1])
    if not rows:
        sys.exit(f"no dscan_*/summary.json under {sys.argv[1]}")
    print("| eps | D along (per T) | bootstrap error | growth, 2nd half / 1st half | D across (per T) | run seconds |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        a = r["along"]
        halves = a["slope_second_half"] / a["slope_first_half"] if a.get("slope_first_half") else float("nan")
        print(f"| {r['eps']:g} | {a['D']:.3e} | {a['D_error']:.1e} | {halves:.2f} | "
              f"{r['across']['D']:.3e} | {r['seconds']:.1f} |")
    law = fit_law(rows)
    if law is None:
        print("fewer than 3 positive coefficients: no fit")
        return
    print(f"\nfit log D = log D0 - c eps^-a over {law['n']} values: a = {law['a']:.3f}, c = {law['c']:.4g}, "
          f"D0 = {math.exp(law['logD0']):.3e}, chi2 = {law['chi2']:.3g} ({law['n'] - 3} degrees of freedom)")
    fixed = fit_law(rows, 0.25)
    print(f"fit at a = 0.25 (the exponent Efthymiopoulos & Harsoula report): c = {fixed['c']:.4g}, "
          f"D0 = {math.exp(fixed['logD0']):.3e}, chi2 = {fixed['chi2']:.3g} ({fixed['n'] - 2} degrees of freedom)")
    print("\nequal weights in ln D (the scatter between neighbouring eps, not the bootstrap, sets the error):")
    print("| a | c | D0 | rms of ln D about the law |")
    print("|---|---|---|---|")
    for a in (0.1, 0.21, 0.25, 0.5, 1.0, 2.0):
        f = fit_law(rows, a, weighted=False)
        print(f"| {a:g} | {f['c']:.3g} | {math.exp(f['logD0']):.3g} | {math.sqrt(f['chi2'] / (f['n'] - 2)):.3f} |")
    if len(sys.argv) > 2:
        shown = fit_law(rows, 0.25, weighted=False)
        svg([r for r in rows if r["along"]["D"] > 3 * r["along"]["D_error"] > 0], shown, sys.argv[2])


if __name__ == "__main__":
    main()
