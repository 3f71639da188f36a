#!/usr/bin/env python3
"""Plot bench.csv (arnoldweb bench): trajectory-steps/s against N, one panel per
precision, one line per device and variant; the naive baselines dashed.

usage: plot_bench.py bench.csv out.png [title]
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    src, png = sys.argv[1], sys.argv[2]
    rows = [r for r in csv.DictReader(open(src)) if r["kind"] in ("library", "baseline") and float(r["rate"] or 0) > 0]
    meta = {}
    js = os.path.join(os.path.dirname(src), "bench.json")
    if os.path.exists(js):
        meta = json.load(open(js))
    precisions = [p for p in ("double", "float") if any(r["precision"] == p for r in rows)]
    if not precisions:
        sys.exit("no rows with a rate in " + src)
    fig, axes = plt.subplots(1, len(precisions), figsize=(6.5 * len(precisions), 5), squeeze=False)
    for ax, prec in zip(axes[0], precisions):
        lines = {}
        for r in rows:
            if r["precision"] != prec:
                continue
            key = (r["kind"], r["device"], r["name"], r["variant"], r["math"])
            lines.setdefault(key, []).append((int(r["trajectories"]), float(r["rate"])))
        for (kind, dev, name, variant, math), pts in sorted(lines.items()):
            pts.sort()
            xs, ys = zip(*pts)
            base = kind == "baseline"
            label = f"{dev} {name[:28]}" + ("" if base else f" [{variant}{'' if math == 'portable' else ', ' + math}]")
            ax.plot(xs, ys, ("--x" if base else ("-o" if variant == "default" else ":s")), label=label,
                    color="0.3" if base else None, markersize=4)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("trajectories N")
        ax.set_ylabel("trajectory-steps / s")
        ax.set_title(f"Yoshida-6, E = {meta.get('energy', 15):g}, h = {meta.get('step_T', 0.01):g} T, {prec}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    sub = " ".join(x for x in (meta.get("date", ""), meta.get("host", "")) if x)
    if len(sys.argv) > 3:
        sub = sys.argv[3] + ("; " + sub if sub else "")
    if sub:
        fig.suptitle("arnoldweb bench: " + sub, fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
