#!/usr/bin/python3
"""Plots and tables of the work-precision benchmark (docs/accuracy.md).

Usage: bench/work_precision/plot.py RESULTS.csv [--img docs/img] [--tables FILE.md] [--prefix work_precision]

Reads the CSV of arnoldweb_work_precision ('#' lines are comments), draws for
each energy error against cost (one curve per method) and prints, for
max|dE| <= 1e-6, 1e-8, 1e-10 at every energy, the cheapest method, step,
precision, math and device, and how many times cheaper it is than the paper's
method (Yoshida-6A, double) at equal accuracy.

Cost is the calibrated cost of a run: core-seconds (CPU time of all threads)
per force evaluation of the kernel, measured once per device, precision, math
and method (least of three runs of >= 0.1 s), x force evaluations per
trajectory per T. On an idle 2-core machine the wall time is about half. Equal accuracy: along
each curve, log(cost) is interpolated linearly in log(max|dE|) between the
two measured steps that bracket the tolerance.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TOLERANCES = [1e-6, 1e-8, 1e-10]
METHOD_ORDER = ["leapfrog", "forest-ruth", "pefrl", "srkn6b", "yoshida6a", "kahan-li-s9", "srkn11b",
                "kahan-li-s15", "yoshida8d", "odeint-sb3a", "saba1", "saba2", "saba3", "saba4", "sbab2", "sbab3",
                "sbab4", "bab84", "aba104", "aba864", "aba1064"]
COLOURS = {"leapfrog": "#999999", "forest-ruth": "#1f77b4", "pefrl": "#17becf", "srkn6b": "#2ca02c",
           "yoshida6a": "#d62728", "kahan-li-s9": "#ff7f0e", "srkn11b": "#9467bd", "kahan-li-s15": "#8c564b",
           "yoshida8d": "#e377c2", "odeint-sb3a": "#000000",
           # the near-integrable families (docs/methods.md): dashed
           "saba1": "#c7c7c7", "saba2": "#aec7e8", "saba3": "#98df8a", "saba4": "#bcbd22", "sbab2": "#ffbb78",
           "sbab3": "#ff9896", "sbab4": "#dbdb8d", "bab84": "#17becf", "aba104": "#393b79", "aba864": "#e6550d",
           "aba1064": "#31a354"}
NEAR_INTEGRABLE = {"saba1", "saba2", "saba3", "saba4", "sbab2", "sbab3", "sbab4", "bab84", "aba104", "aba864",
                   "aba1064"}
PAPER = "yoshida6a"
CPU = "2-core Xeon"  # replaced by the CSV header's cpu device


def read(path):
    rows, comments = [], []
    with open(path) as f:
        lines = []
        for line in f:
            (comments if line.startswith("#") else lines).append(line)
    for r in csv.DictReader(lines):
        for k in ("energy", "step_T", "guard_hkp", "max_dE", "median_dE", "mean_dE", "traj_err_max",
                  "traj_err_median", "traj_err_rms", "seconds", "s_per_traj_per_T", "s_per_force_eval",
                  "cost_s_per_traj_per_T"):
            r[k] = float(r[k])
        for k in ("order", "forces_per_step", "steps_per_T", "unsafe", "trajectories", "lost"):
            r[k] = int(r[k])
        r["forces_per_T"] = r["forces_per_step"] * r["steps_per_T"]
        rows.append(r)
    return rows, comments


def curves(rows):
    """(energy, device, precision, math, method) -> points by increasing cost (safe steps only)."""
    out = {}
    for r in rows:
        if r["unsafe"]:
            continue
        out.setdefault((r["energy"], r["device"], r["precision"], r["math"], r["method"]), []).append(r)
    for k in out:
        out[k].sort(key=lambda r: r["steps_per_T"])
    return out


def at_tolerance(points, tol, key="max_dE"):
    """Interpolated (cost, forces per T, steps per T) where the curve reaches tol, or None."""
    prev = None
    for p in points:
        if math.isfinite(p[key]) and p[key] <= tol:
            if prev is None or not math.isfinite(prev[key]) or prev[key] <= p[key]:
                return p["cost_s_per_traj_per_T"], p["forces_per_T"], p["steps_per_T"], p
            t = (math.log(tol) - math.log(prev[key])) / (math.log(p[key]) - math.log(prev[key]))
            lerp = lambda a, b: math.exp(math.log(a) + t * (math.log(b) - math.log(a)))  # noqa: E731
            return (lerp(prev["cost_s_per_traj_per_T"], p["cost_s_per_traj_per_T"]),
                    lerp(prev["forces_per_T"], p["forces_per_T"]), lerp(prev["steps_per_T"], p["steps_per_T"]), p)
        prev = p
    return None


def cheapest_measured(points, tol):
    ok = [p for p in points if math.isfinite(p["max_dE"]) and p["max_dE"] <= tol]
    return min(ok, key=lambda p: p["cost_s_per_traj_per_T"]) if ok else None


def plot(rows, img_dir, prefix="work_precision"):
    cs = curves(rows)
    energies = sorted({r["energy"] for r in rows})
    precisions = [p for p in ("double", "float") if any(r["precision"] == p for r in rows)]
    files = []
    for e in energies:
        fig, axes = plt.subplots(len(precisions), 2, figsize=(13, 5 * len(precisions)), squeeze=False)
        for row, prec in enumerate(precisions):
            for col, (key, label) in enumerate((("max_dE", "max |dE| over the ensemble"),
                                                ("traj_err_median", "median trajectory error at 1 T"))):
                ax = axes[row][col]
                for m in METHOD_ORDER:
                    for dev, style in (("cpu", "-"), ("opencl:0", ":")):
                        device = "cpu-odeint" if m == "odeint-sb3a" else dev
                        if m == "odeint-sb3a" and dev != "cpu":
                            continue
                        math_mode = "libm" if m == "odeint-sb3a" else "portable"
                        pts = cs.get((e, device, prec, math_mode, m))
                        if not pts:
                            continue
                        xs = [p["cost_s_per_traj_per_T"] for p in pts]
                        ys = [p[key] for p in pts]
                        lab = (m if dev == "cpu" else None)
                        if m == "odeint-sb3a":
                            lab = "Boost.Odeint sb3a (cpu, libm)"
                        if m in NEAR_INTEGRABLE and dev == "cpu":
                            style = "--"
                        ax.loglog(xs, ys, style, marker="o" if dev == "cpu" else None, ms=3, color=COLOURS[m],
                                  label=lab, lw=2.0 if m == PAPER else 1.2)
                paper = [r for r in rows if r["energy"] == e and r["method"] == PAPER and r["device"] == "cpu"
                         and r["precision"] == "double" == prec and r["math"] == "portable"
                         and r["steps_per_T"] == 100]
                for p in paper:
                    ax.plot([p["cost_s_per_traj_per_T"]], [p[key]], "s", ms=9, mfc="none", color="k")
                    ax.annotate("paper: Yoshida-6, h = T/100" + (" (refused by the guard)" if p["unsafe"] else ""),
                                (p["cost_s_per_traj_per_T"], p[key]), textcoords="offset points", xytext=(8, 4),
                                fontsize=8)
                for tol in TOLERANCES:
                    if key == "max_dE":
                        ax.axhline(tol, color="#cccccc", lw=0.8, zorder=0)
                ax.set_xlabel("cost: core-seconds per trajectory per T (" + CPU + ", calibrated)")
                ax.set_ylabel(label)
                legend = ("solid: cpu, dotted: opencl:0 PoCL" if any(r["device"] == "opencl:0" for r in rows)
                          else "cpu")
                if any(r["method"] in NEAR_INTEGRABLE for r in rows):
                    legend += "; dashed: near-integrable methods"
                ax.set_title(f"E = {e:g}, {prec}, portable math ({legend})", fontsize=10)
                ax.grid(True, which="major", alpha=0.3)
        axes[0][0].legend(fontsize=8, loc="lower left")
        fig.tight_layout()
        path = os.path.join(img_dir, f"{prefix}_E{e:g}.png")
        fig.savefig(path, dpi=90)
        plt.close(fig)
        files.append(path)
    return files


def fmt_cost(c):
    return f"{c:.3g}"


def tables(rows):
    cs = curves(rows)
    energies = sorted({r["energy"] for r in rows})
    out = []
    for e in energies:
        out.append(f"\n### E = {e:g}\n")
        out.append("| max abs(dE) | cheapest (measured step) | its max abs(dE) | forces/T | cost core-s/traj/T | "
                   "Yoshida-6A double, same device (step) | cheaper by (equal accuracy) | "
                   "in force evaluations |")
        out.append("|---|---|---|---|---|---|---|---|")
        for tol in TOLERANCES:
            best = None
            for k, pts in cs.items():
                if k[0] != e:
                    continue
                hit = at_tolerance(pts, tol)
                if hit and (best is None or hit[0] < best[1][0]):
                    best = (k, hit)
            if best is None:
                out.append(f"| {tol:g} | not reached by any configuration | | | | | | |")
                continue
            (_, dev, prec, mm, meth), (cost, fpt, spt, _) = best
            grid = cheapest_measured(cs[best[0]], tol)
            ref_dev = dev if dev != "cpu-odeint" else "cpu"
            paper = at_tolerance(cs.get((e, ref_dev, "double", "portable", PAPER), []), tol)
            if paper:
                ratio = paper[0] / cost
                fratio = paper[1] / fpt
                pgrid = cheapest_measured(cs[(e, ref_dev, "double", "portable", PAPER)], tol)
                paper_txt = f"T/{pgrid['steps_per_T']} measured ({fmt_cost(paper[0])} core-s at equal accuracy)"
                ratio_txt, fratio_txt = f"**{ratio:.2f}x**", f"{fratio:.2f}x"
            else:
                paper_txt, ratio_txt, fratio_txt = "not reached", "-", "-"
            out.append(f"| {tol:g} | {meth}, {prec}, {mm}, {dev}: T/{grid['steps_per_T']} "
                       f"(interpolated T/{spt:.0f}) | {grid['max_dE']:.2g} | {grid['forces_per_T']} | "
                       f"{fmt_cost(grid['cost_s_per_traj_per_T'])} | {paper_txt} | {ratio_txt} | {fratio_txt} |")
    return "\n".join(out)


def per_method_table(rows, e, device="cpu", prec="double", mm="portable"):
    """Cost at each tolerance of every method on one device (interpolated)."""
    cs = curves(rows)
    out = [f"\n#### E = {e:g}: every method on {device}, {prec}, {mm} math (odeint: cpu, libm), "
           "cost at equal accuracy in core-microseconds per trajectory per T (force evaluations per T)\n",
           "| method | " + " | ".join(f"max abs(dE) <= {t:g}" for t in TOLERANCES) + " |",
           "|---|" + "---|" * len(TOLERANCES)]
    for m in METHOD_ORDER:
        k = (e, "cpu-odeint", "double", "libm", m) if m == "odeint-sb3a" else (e, device, prec, mm, m)
        if k not in cs:
            continue
        cells = []
        for tol in TOLERANCES:
            hit = at_tolerance(cs[k], tol)
            cells.append(f"{hit[0] * 1e6:.3g} ({hit[1]:.0f})" if hit else "-")
        out.append(f"| {m} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def variants_table(rows, e, method):
    """The same method on every device, precision and math mode."""
    cs = curves(rows)
    out = [f"\n#### E = {e:g}: {method} on every device, precision and math mode\n",
           "| device | precision | math | force evaluations per core-second | smallest max abs(dE) reached | " +
           " | ".join(f"cost at {t:g} (core-us/traj/T)" for t in TOLERANCES) + " |",
           "|---|---|---|---|---|" + "---|" * len(TOLERANCES)]
    for (ee, dev, prec, mm, m), pts in sorted(cs.items()):
        if ee != e or m != method:
            continue
        floor = min(p["max_dE"] for p in pts)
        cells = []
        for tol in TOLERANCES:
            hit = at_tolerance(pts, tol)
            cells.append(f"{hit[0] * 1e6:.3g}" if hit else "-")
        out.append(f"| {dev} | {prec} | {mm} | {1 / pts[0]['s_per_force_eval']:.3g} | {floor:.2g} | " +
                   " | ".join(cells) + " |")
    return "\n".join(out)


def main():
    args = sys.argv[1:]
    if not args:
        print(__doc__)
        return 2
    path = args[0]
    img = "docs/img"
    tables_path = None
    if "--img" in args:
        img = args[args.index("--img") + 1]
    if "--tables" in args:
        tables_path = args[args.index("--tables") + 1]
    prefix = args[args.index("--prefix") + 1] if "--prefix" in args else "work_precision"
    rows, comments = read(path)
    global CPU
    for c in comments:  # the CPU of the run, from the CSV header
        if c.startswith("# device cpu:"):
            name = c.split(":", 1)[1].split("(")[0].strip()
            CPU = "2-core " + name if name else CPU
    os.makedirs(img, exist_ok=True)
    files = plot(rows, img, prefix)
    text = ["<!-- generated by bench/work_precision/plot.py from " + os.path.basename(path) + " -->"]
    text += [c.rstrip() for c in comments if c.startswith("# arnoldweb_work_precision") or
             c.startswith("# device") or c.startswith("# total")]
    text.append(tables(rows))
    for e in sorted({r["energy"] for r in rows}):
        text.append(per_method_table(rows, e))
        text.append(variants_table(rows, e, PAPER))
    paper = [r for r in rows if r["method"] == PAPER and r["steps_per_T"] == 100 and r["precision"] == "double"
             and r["math"] == "portable" and r["device"] == "cpu"]
    text.append("\n#### The paper's choice itself (Yoshida-6A, h = T/100, double, portable, cpu)\n")
    text.append("| E | h k abs(p)max | max abs(dE) | median abs(dE) (bin upper edge) | mean | median trajectory error at 1 T |")
    text.append("|---|---|---|---|---|---|")
    for r in sorted(paper, key=lambda r: r["energy"]):
        text.append(f"| {r['energy']:g} | {r['guard_hkp']:.3g}{' (refused)' if r['unsafe'] else ''} | "
                    f"{r['max_dE']:.2g} | {r['median_dE']:.2g} | {r['mean_dE']:.2g} | {r['traj_err_median']:.2g} |")
    md = "\n".join(text) + "\n"
    if tables_path:
        with open(tables_path, "w") as f:
            f.write(md)
    print(md)
    for f in files:
        print("wrote", f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
