#!/usr/bin/env python3
"""The D(eps) scan of issue 41: places along I1 = I2, orbits of each place's chaotic layer chosen by
their FLI, one run per eps holding every place, and the law fitted with the unresolved runs kept.
The plan, its rules and the commands: bench/gpu/campaigns/README.md ("The D(eps) scan").

    d_eps_scan.py places [--n 128] [--out FILE]          the places, by the rule written down first
    d_eps_scan.py campaigns [--dir bench/gpu/campaigns/d_eps]   the campaign folders of the plan
    d_eps_scan.py candidates --eps E --places FILE --out H5           (h5py) the FLI run's states
    d_eps_scan.py select --eps E --places FILE --fli H5 --out DIR      (h5py) the orbits chosen
    d_eps_scan.py states --eps E --places FILE --chosen FILE [--every-place K] --out H5   (h5py)
    d_eps_scan.py extract --run DIR --places FILE [--every-place K] --out DIR            (h5py)
    d_eps_scan.py fit [--step MAIN_DIR STEP_DIR T_LO T_HI] [--shift EPS LN] [--svg PATH] RESULT_DIR...
                                                         the law, pure Python; --shift: every D at EPS
                                                         times exp(LN), a step error's bound, refitted
    d_eps_scan.py design [--csv 16-PLACE CSV]            the Fisher estimate of sigma(a) of designs
    d_eps_scan.py synthetic --a A --out DIR [...]        data of a known law (the test's)

Only the subcommands that read or write HDF5 need h5py (and numpy): they run where the runs run.
The statistics are pure Python: D per place from the variance of the averaged actions along the
resonance, Var(t) = sigma0^2 + 2 D t by least squares (as arnoldweb's fit_diffusion), over the
whole fitted range and its two halves, each with a jackknife error over the place's orbits; the
law ln D = ln D0 - c eps^-a + u_place against the power law ln D = ln D0 + n ln eps + u_place,
by maximum likelihood with a normal scatter between places and runs, where an unresolved D
(D <= 3 errors, or <= 0) is an upper limit and a D whose growth is not linear (its halves differ
by more than 2x) an interval between its halves: censored, not dropped.
"""
import csv
import gzip
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from d_eps_fit import fit_line, svg_axes  # noqa: E402

E_FGL = 0.5                     # model.energy of the scenes
V_AT_ZERO = 1.0 / 7.0           # the fgl potential's 1/(cos + cos + cos + 4) at angles 0
ACROSS_HALF = 2e-5              # candidates: |I1 - I2|/2 from 1e-8 to this, geometric ...
ACROSS_STEPS = 16               # ... in 16 steps, both signs
ACROSS_SMALLEST = 1e-8
ALONG_HALF = 5e-7               # and (I1 + I2)/2 - c in 16 steps over +-5e-7
ALONG_STEPS = 16
ORBITS = 128                    # orbits per place
FLI_SPAN = 2e4                  # the FLI run's length (T)
EXCLUDE = {1: 0.02, 2: 0.02, 3: 0.02, 4: 0.01, 5: 0.01, 6: 0.005, 7: 0.005}  # by denominator q
PLACE_RANGE = (0.15, 0.48)


# ------------------------------------------------------------------ the rules written down first
def allowed_intervals(lo=PLACE_RANGE[0], hi=PLACE_RANGE[1]):
    """[lo, hi] on I1 = I2 = c without the crossings c = p/q (q <= 7) and their margins."""
    cuts = sorted((p / q - r, p / q + r) for q, r in EXCLUDE.items() for p in range(0, q + 1)
                  if math.gcd(p, q) == 1)
    pieces, start = [], lo
    for a, b in cuts:
        if b <= start or a >= hi:
            continue
        if a > start:
            pieces.append((start, a))
        start = max(start, b)
    if start < hi:
        pieces.append((start, hi))
    return pieces


def places(n):
    """n places: the midpoints of n equal parts of the allowed set's length, in order."""
    pieces = allowed_intervals()
    total = sum(b - a for a, b in pieces)
    out = []
    for k in range(n):
        s = (k + 0.5) * total / n
        for a, b in pieces:
            if s <= b - a:
                out.append(round(a + s, 6))
                break
            s -= b - a
    return out


def read_places(path):
    with open(path) as f:
        return [float(line.split()[0]) for line in f if line.strip() and not line.startswith("#")]


def across_offsets():
    r = (ACROSS_SMALLEST / ACROSS_HALF) ** (1.0 / (ACROSS_STEPS - 1))
    mags = [ACROSS_HALF * r ** j for j in range(ACROSS_STEPS)]
    return [-m for m in mags] + mags[::-1]


def candidates(eps, cs):
    """Per place, the candidates' actions (I1, I2, I3) in index order; angles 0; H = E."""
    along = [ALONG_HALF * ((2 * k + 1) / ALONG_STEPS - 1) for k in range(ALONG_STEPS)]
    out = []
    for c in cs:
        for u in across_offsets():
            for v in along:
                i1, i2 = c + u + v, c - u + v
                out.append((i1, i2, E_FGL - (i1 * i1 + i2 * i2) / 2 - eps * V_AT_ZERO))
    return out


def per_place():
    return 2 * ACROSS_STEPS * ALONG_STEPS


def chaotic_threshold():
    """FLI (natural log of the tangent vector) of a chaotic orbit: above twice a regular one's ln t."""
    return 2 * math.log(FLI_SPAN)


def choose(fli):
    """The ORBITS of one place: those above the threshold spread evenly over the index order
    (so over the layer's width); where fewer pass, all of them and then the highest of the rest."""
    passing = [i for i, f in enumerate(fli) if f >= chaotic_threshold()]
    if len(passing) >= ORBITS:
        return [passing[m * len(passing) // ORBITS] for m in range(ORBITS)], len(passing)
    rest = sorted((i for i in range(len(fli)) if fli[i] < chaotic_threshold()), key=lambda i: -fli[i])
    return sorted(passing + rest[:ORBITS - len(passing)]), len(passing)


# ------------------------------------------------------------------ the plan's campaigns
SCAN_EPS = [0.0013, 0.00167, 0.00214, 0.00274, 0.00351, 0.0045, 0.00577, 0.0074, 0.00949, 0.0122, 0.0156, 0.02]
STEP_EPS, STEP_EVERY_PLACE, STEP_SPAN = 0.0013, 4, 9e6  # the h/2 check: every 4th place, to 9e6 T


def run_length(eps):
    """T of the run at eps: 2 D T well above the averaged actions' floor (~1e-11) at the law's D."""
    return 3e7 if eps < 0.0015 else (1e7 if eps < 0.005 else 1e6)


def cmd_campaigns(o):
    root = o.get("dir", "bench/gpu/campaigns/d_eps")
    here, tool = root + "/places.txt", "python3 bench/gpu/d_eps_scan.py"

    def write(name, lines):
        os.makedirs(os.path.join(root, name), exist_ok=True)
        with open(os.path.join(root, name, "campaign.conf"), "w") as f:
            f.write("\n".join(lines) + "\n")

    def diffusion_sets(eps, T, every, h=None):
        return ([f"set = model.epsilon={eps!r}", f"set = run.duration={T:.1f}", f"set = run.average={T:.1f}",
                 f"set = run.slice={every:.1f}", f"set = observe.energy_error.every={every:.1f}",
                 f"set = observe.diffusion.every={every:.1f}", f"set = observe.diffusion.average={every:.1f}",
                 f"set = observe.diffusion.fit_from={T / 10 if h is None else 3 * every:.1f}",
                 "set = run.checkpoint_every=120", "set = ensemble.file={work}/states.h5"]
                + ([f"set = integrator.step={h!r}"] if h else []))

    for eps in SCAN_EPS:
        T = run_length(eps)
        write(f"fli-{eps!r}", [
            f"# the FLI pre-selection at eps = {eps!r} (d_eps_scan.py campaigns; bench/gpu/campaigns/README.md)",
            f"scene = {root}/fli.toml", f"set = model.epsilon={eps!r}", "set = ensemble.file={work}/candidates.h5",
            "device = cuda:0",
            f"prepare = {tool} candidates --eps {eps!r} --places {here} --out {{work}}/candidates.h5",
            "inputs = {work}/candidates.h5",
            f"collect = {tool} select --eps {eps!r} --places {here} --fli {{run}}/indicators.h5 --out {{result}}",
            "keep = summary.json"])
        write(f"run-{eps!r}", [
            f"# the D(eps) run at eps = {eps!r}, {T:g} T (d_eps_scan.py campaigns; bench/gpu/campaigns/README.md)",
            f"scene = {root}/diffusion.toml"] + diffusion_sets(eps, T, T / 100) + [
            "device = cuda:0",
            f"prepare = {tool} states --eps {eps!r} --places {here} --chosen {root}/fli-{eps!r}/result/chosen.txt.gz "
            "--out {work}/states.h5",
            "inputs = {work}/states.h5",
            f"collect = {tool} extract --run {{run}} --places {here} --out {{result}}",
            "keep = summary.json diffusion.csv diffusion.png"])
    every = run_length(STEP_EPS) / 100
    write(f"step-{STEP_EPS!r}", [
        f"# the step-size check at eps = {STEP_EPS!r}: h/2 = 0.01 T on every {STEP_EVERY_PLACE}th place to "
        f"{STEP_SPAN:g} T, sampled as run-{STEP_EPS!r} (bench/gpu/campaigns/README.md)",
        f"scene = {root}/diffusion.toml"] + diffusion_sets(STEP_EPS, STEP_SPAN, every, 0.01) + [
        "device = cuda:0",
        f"prepare = {tool} states --eps {STEP_EPS!r} --places {here} --chosen {root}/fli-{STEP_EPS!r}/result/chosen.txt.gz "
        f"--every-place {STEP_EVERY_PLACE} --out {{work}}/states.h5",
        "inputs = {work}/states.h5",
        f"collect = {tool} extract --run {{run}} --places {here} --every-place {STEP_EVERY_PLACE} --out {{result}}",
        "keep = summary.json diffusion.csv diffusion.png"])
    print(f"{2 * len(SCAN_EPS) + 1} campaign folders under {root}")


# ------------------------------------------------------------------ HDF5 in and out (the device's side)
def write_states(path, actions):
    import h5py
    import numpy as np
    with h5py.File(path, "w") as f:
        f["momentum"] = np.array(actions, dtype=np.float64)
        f["position_turns"] = np.zeros((len(actions), 3))
        f["winding"] = np.zeros((len(actions), 3), dtype=np.int64)


def read_chosen(path):
    """place index -> candidate indices (chosen.txt.gz: one line a place)."""
    out = {}
    with gzip.open(path, "rt") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            head, rest = line.split(":")
            out[int(head.split()[0])] = [int(x) for x in rest.split()]
    return out


def subset(cs, every):
    return [k for k in range(len(cs)) if k % every == 0]


def cmd_candidates(o):
    cs = read_places(o["places"])
    write_states(o["out"], candidates(float(o["eps"]), cs))
    print(f"{len(cs)} places x {per_place()} candidates -> {o['out']}")


def cmd_select(o):
    import h5py
    cs = read_places(o["places"])
    fli = h5py.File(o["fli"], "r")["fli"][()].tolist()
    m = per_place()
    if len(fli) != len(cs) * m:
        sys.exit(f"{o['fli']}: {len(fli)} values, not {len(cs)} places x {m}")
    os.makedirs(o["out"], exist_ok=True)
    rows = []
    with gzip.open(os.path.join(o["out"], "chosen.txt.gz"), "wt") as z:
        z.write(f"# eps {o['eps']}: place index c: the {ORBITS} candidate indices chosen (FLI >= "
                f"{chaotic_threshold():.3f} at {FLI_SPAN:g} T)\n")
        for p, c in enumerate(cs):
            f = fli[p * m:(p + 1) * m]
            idx, n_pass = choose(f)
            z.write(f"{p} {c!r}: " + " ".join(map(str, idx)) + "\n")
            s = sorted(f)
            rows.append([p, c, n_pass, s[len(s) // 10], s[len(s) // 2], s[9 * len(s) // 10]])
    with open(os.path.join(o["out"], "fli_places.csv"), "w", newline="") as g:
        w = csv.writer(g)
        w.writerow(["place", "c", "chaotic", "fli_10", "fli_50", "fli_90"])
        w.writerows(rows)
    thin = [r for r in rows if r[2] < ORBITS]
    print(f"eps {o['eps']}: {len(rows)} places, {sum(r[2] for r in rows)} of {len(fli)} candidates chaotic; "
          f"{len(thin)} places with fewer than {ORBITS} (filled with their highest FLI)")


def cmd_states(o):
    cs = read_places(o["places"])
    cand = candidates(float(o["eps"]), cs)
    chosen = read_chosen(o["chosen"])
    keep = subset(cs, int(o.get("every-place", 1)))
    out = []
    for p in keep:
        out += [cand[p * per_place() + i] for i in chosen[p]]
    write_states(o["out"], out)
    print(f"{len(keep)} places x {ORBITS} orbits -> {o['out']}")


# ------------------------------------------------------------------ D per place (pure)
def line_fit(t, y):
    """Least squares y = p + q t, equal weights: (p, q)."""
    return fit_line(list(t), list(y), [1.0] * len(t))[:2]


def ols_weights(t):
    """w with slope = sum w_k y_k."""
    n = len(t)
    mt = sum(t) / n
    stt = sum((a - mt) ** 2 for a in t)
    return [(a - mt) / stt for a in t]


def ranges_of(t, fit_from):
    """Index ranges [first, last] (inclusive): the whole fit (t >= fit_from) and its halves, as
    arnoldweb's fit_diffusion cuts them."""
    first = next(k for k, x in enumerate(t) if x >= fit_from)
    last = len(t) - 1
    mid = first + (last - first) // 2
    return {"full": (first, last), "first": (first, mid), "second": (mid, last)}


def place_fit(q, t, ranges):
    """q[i][k]: orbit i's displacement along e at t[k]. For each range: D = slope / 2 of the
    variance over the orbits, and its jackknife error (leave one orbit out)."""
    m, K = len(q), len(t)
    s1 = [sum(q[i][k] for i in range(m)) for k in range(K)]
    s2 = [sum(q[i][k] ** 2 for i in range(m)) for k in range(K)]
    var = [s2[k] / m - (s1[k] / m) ** 2 for k in range(K)]
    out = {"var": var, "mean": [x / m for x in s1]}
    for name, (a, b) in ranges.items():
        w = ols_weights(t[a:b + 1])
        d = sum(wk * v for wk, v in zip(w, var[a:b + 1])) / 2
        jack = []
        for i in range(m):
            dv = 0.0
            for j, k in enumerate(range(a, b + 1)):
                x = q[i][k]
                v = (s2[k] - x * x) / (m - 1) - ((s1[k] - x) / (m - 1)) ** 2
                dv += w[j] * v
            jack.append(dv / 2)
        jm = sum(jack) / m
        se = math.sqrt((m - 1) / m * sum((x - jm) ** 2 for x in jack))
        out[name] = (d, se)
    out["sigma0sq"] = line_fit(t[ranges["full"][0]:], var[ranges["full"][0]:])[0]
    return out


def project(actions, e, first):
    """actions[i][k] = (I1, I2, I3); the displacements from sample `first` along unit e."""
    return [[sum(e[c] * (row[k][c] - row[first][c]) for c in range(3)) for k in range(first, len(row))]
            for row in actions]


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


PLACE_FIELDS = ["eps", "duration", "place", "c", "orbits", "used", "D", "D_se", "D_first", "D_first_se",
                "D_second", "D_second_se", "sigma0sq", "D_across", "D_across_se"]


def cmd_extract(o):
    import json
    import h5py
    run = o["run"]
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)
    sc = summary["scene"]
    eps, duration = sc["model"]["epsilon"], sc["run"]["duration"]
    dif = sc["observe"]["diffusion"]
    cs = read_places(o["places"])
    keep = subset(cs, int(o.get("every-place", 1)))
    h = h5py.File(os.path.join(run, "diffusion.h5"), "r")
    mom, status = h["momentum"], h["status"][()].tolist()
    if mom.shape[0] != len(keep) * ORBITS:
        sys.exit(f"{run}: {mom.shape[0]} trajectories, not {len(keep)} places x {ORBITS}")
    first = 1 if dif.get("average", 0) > 0 else 0
    t = [k * dif["every"] for k in range(first, mom.shape[1])]
    ranges = ranges_of(t, dif["fit_from"])
    e = unit(dif["along"])
    f = [x - sum(a * b for a, b in zip(dif["across"], e)) * y for x, y in zip(dif["across"], e)]
    f = unit(f)
    os.makedirs(o["out"], exist_ok=True)
    rows, curves = [], []
    for j, p in enumerate(keep):
        block = mom[j * ORBITS:(j + 1) * ORBITS].tolist()
        ok = [block[i] for i in range(ORBITS) if status[j * ORBITS + i] == 0]
        fa = place_fit(project(ok, e, first), t, ranges)
        fx = place_fit(project(ok, f, first), t, {"full": ranges["full"]})
        rows.append([eps, duration, p, cs[p], ORBITS, len(ok), fa["full"][0], fa["full"][1], fa["first"][0],
                     fa["first"][1], fa["second"][0], fa["second"][1], fa["sigma0sq"], fx["full"][0], fx["full"][1]])
        curves += [[p, f"{t[k]:.9g}", f"{fa['var'][k]:.7g}", f"{fx['var'][k]:.7g}", f"{fa['mean'][k]:.7g}"]
                   for k in range(len(t))]
    with open(os.path.join(o["out"], "places.csv"), "w", newline="") as g:
        w = csv.writer(g)
        w.writerow(PLACE_FIELDS)
        w.writerows(rows)
    with gzip.open(os.path.join(o["out"], "curves.csv.gz"), "wt", newline="") as g:
        w = csv.writer(g)
        w.writerow(["place", "t", "var_along", "var_across", "mean_along"])
        w.writerows(curves)
    print(f"eps {eps}, {duration:g} T: {len(rows)} places -> {o['out']}/places.csv, curves.csv.gz")


# ------------------------------------------------------------------ the law, censored (pure)
def phi(z):
    return math.exp(-0.5 * z * z) / math.sqrt(2 * math.pi)


def Phi(z):
    return 0.5 * math.erfc(-z / math.sqrt(2))


def classify(row, k=3.0, halves=2.0):
    """(kind, lo, hi) in ln D: 'point' (lo = hi), 'upper' (ln D < hi: unresolved), 'interval'
    (growth not linear: between the halves' D)."""
    d, se = row["D"], row["D_se"]
    if not d > k * se:
        return "upper", -math.inf, math.log(max(d, 0.0) + k * se)
    d1, d2 = row["D_first"], row["D_second"]
    if d1 > 0 and d2 > 0 and max(d1, d2) <= halves * min(d1, d2):
        return "point", math.log(d), math.log(d)
    lo, hi = min(d1, d2), max(d1, d2, d)
    if lo <= 0:
        return "upper", -math.inf, math.log(hi)
    return "interval", math.log(lo), math.log(hi)


def truncated_moments(mu, tau, lo, hi):
    """Mean and second moment of N(mu, tau^2) restricted to [lo, hi]; log of its probability."""
    a = (lo - mu) / tau if lo > -math.inf else -math.inf
    b = (hi - mu) / tau
    pa, pb = (phi(a) if a > -math.inf else 0.0), phi(b)
    z = (Phi(b) - (Phi(a) if a > -math.inf else 0.0))
    if z < 1e-300:  # far out: the moments of the nearest edge
        edge = hi if a == -math.inf or mu > hi else lo
        return edge, edge * edge, math.log(1e-300)
    ea, eb = (a * pa if a > -math.inf else 0.0), b * pb
    m = mu + tau * (pa - pb) / z
    v = tau * tau * (1 + (ea - eb) / z - ((pa - pb) / z) ** 2)
    return m, max(v, 0.0) + m * m, math.log(z)


def fit_censored(obs, xs, places_effect=True, start=None, iters=400, tol=1e-9):
    """obs: list of (place, x-index, kind, lo, hi); xs: regressor per x-index. Model
    y = b0 + b1 x + u_place + N(0, tau^2), sum u = 0. EM (censored points by their truncated
    moments). Returns dict(b0, b1, tau, u, loglik)."""
    P = sorted({o[0] for o in obs})
    par = dict(start) if start else None
    if par is None:
        ys = [o[4] if o[2] != "point" else o[3] for o in obs]
        par = {"b0": sum(ys) / len(ys), "b1": 0.0, "tau": 2.0, "u": {p: 0.0 for p in P}}
    last = -math.inf
    for _ in range(iters):
        ey, ey2, ll = [], [], 0.0
        for (p, k, kind, lo, hi) in obs:
            mu = par["b0"] + par["b1"] * xs[k] + par["u"][p]
            if kind == "point":
                ey.append(lo)
                ey2.append(lo * lo)
                r = (lo - mu) / par["tau"]
                ll += -0.5 * r * r - math.log(par["tau"] * math.sqrt(2 * math.pi))
            else:
                m, m2, lz = truncated_moments(mu, par["tau"], lo, hi)
                ey.append(m)
                ey2.append(m2)
                ll += lz
        # M-step: within places for the slope, then the place intercepts
        groups = {}
        for j, (p, k, *_r) in enumerate(obs):
            groups.setdefault(p, []).append(j)
        if places_effect:
            xbar = {p: sum(xs[obs[j][1]] for j in g) / len(g) for p, g in groups.items()}
            ybar = {p: sum(ey[j] for j in g) / len(g) for p, g in groups.items()}
            sxx = sum((xs[obs[j][1]] - xbar[p]) ** 2 for p, g in groups.items() for j in g)
            sxy = sum((xs[obs[j][1]] - xbar[p]) * (ey[j] - ybar[p]) for p, g in groups.items() for j in g)
            b1 = sxy / sxx
            alpha = {p: ybar[p] - b1 * xbar[p] for p in groups}
            b0 = sum(alpha.values()) / len(alpha)
            u = {p: alpha[p] - b0 for p in groups}
        else:
            b0, b1 = line_fit([xs[o[1]] for o in obs], ey)
            u = {p: 0.0 for p in groups}
        s = 0.0
        for j, (p, k, *_r) in enumerate(obs):
            mu = b0 + b1 * xs[k] + u[p]
            s += ey2[j] - 2 * ey[j] * mu + mu * mu
        par = {"b0": b0, "b1": b1, "tau": math.sqrt(max(s / len(obs), 1e-12)), "u": u}
        if abs(ll - last) < tol * max(1.0, abs(ll)):
            break
        last = ll
    par["loglik"] = ll
    return par


def load_results(dirs):
    rows = []
    for d in dirs:
        path = d if d.endswith(".csv") else os.path.join(d, "places.csv")
        with open(path) as f:
            rows += [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    return rows


def shifted(rows, eps, ln):
    """The rows with every D of one eps (its value, error and halves) times exp(ln): how the fit
    moves if that eps's D carried a systematic error of that size (the h/2 check's bound)."""
    f = math.exp(ln)
    keys = ("D", "D_se", "D_first", "D_second")
    out = [dict(r, **{k: r[k] * f for k in keys}) if r["eps"] == eps else r for r in rows]
    if out == rows and ln != 0:
        sys.exit(f"d_eps_scan.py fit --shift: no run at eps {eps:g} (the runs have {sorted({r['eps'] for r in rows})})")
    return out


def observations(rows):
    eps = sorted({r["eps"] for r in rows})
    obs, kinds = [], {}
    for r in rows:
        kind, lo, hi = classify(r)
        k = eps.index(r["eps"])
        obs.append((int(r["place"]), k, kind, lo, hi))
        kinds.setdefault(r["eps"], []).append(kind)
    return eps, obs, kinds


def profile(eps, obs, grid, places_effect=True):
    """ln L of the law at each a of grid (warm-started), and of the power law."""
    out, start = [], None
    for a in grid:
        xs = [e ** -a for e in eps]
        start = fit_censored(obs, xs, places_effect, start)
        out.append((a, start["loglik"], start))
    power = fit_censored(obs, [math.log(e) for e in eps], places_effect)
    return out, power


def interval(prof, best, level):
    """The a whose profile lies within level/2 of the best: its ends (grid-resolution)."""
    inside = [a for a, ll, _ in prof if 2 * (best - ll) <= level]
    return min(inside), max(inside)


def analyse(rows, grid, places_effect=True):
    eps, obs, kinds = observations(rows)
    n, nplaces = len(obs), len({o[0] for o in obs})
    # fixed place effects: ln L from tau's maximum-likelihood estimate, scaled by (n - p) / n so
    # that the likelihood ratios are not inflated by the place intercepts (incidental parameters)
    scale = (n - (nplaces + 2 if places_effect else 2)) / n
    prof, power = profile(eps, obs, grid, places_effect)
    ib = max(range(len(prof)), key=lambda i: prof[i][1])
    a_best, ll_best, par = prof[ib]
    prof_s = [(a, ll_best - (ll_best - ll) * scale, p) for a, ll, p in prof]
    i68, i95 = interval(prof_s, ll_best, 1.0), interval(prof_s, ll_best, 3.84)
    lr_power = 2 * (ll_best - power["loglik"]) * scale
    return {"eps": eps, "kinds": kinds, "n": n, "places": nplaces, "a": a_best, "par": par,
            "i68": i68, "i95": i95, "sigma_a": (i68[1] - i68[0]) / 2, "power": power,
            "lr_power": lr_power, "profile": prof_s, "edge": ib in (0, len(prof) - 1)}


def correlated(res, rho):
    """The intervals and the power law's ratio with the places counted as effective ones.

    Neighbouring places' residuals that correlate at rho > 0 carry the information of about
    places (1 - rho) / (1 + rho) independent ones (an AR(1) chain along I1 = I2): the
    log-likelihood's curvature, hence every -2 ln L difference, shrinks by that fraction."""
    f = (1 - rho) / (1 + rho) if rho == rho and rho > 0 else 1.0
    prof = res["profile"]
    best = max(ll for _, ll, _ in prof)
    i68, i95 = interval(prof, best, 1.0 / f), interval(prof, best, 3.84 / f)
    return {"places": res["places"] * f, "i68": i68, "i95": i95,
            "sigma_a": (i68[1] - i68[0]) / 2, "lr_power": res["lr_power"] * f}


def neighbour_correlation(rows, res):
    """Correlation of the residuals of neighbouring places (resolved points), over every eps."""
    par, eps = res["par"], res["eps"]
    by = {}
    for r in rows:
        kind, lo, _ = classify(r)
        if kind == "point":
            k = eps.index(r["eps"])
            mu = par["b0"] + par["b1"] * eps[k] ** -res["a"] + par["u"][int(r["place"])]
            by[(k, int(r["place"]))] = lo - mu
    pairs = [(v, by[(k, p + 1)]) for (k, p), v in by.items() if (k, p + 1) in by]
    if len(pairs) < 3:
        return float("nan")
    mx = sum(a for a, _ in pairs) / len(pairs)
    my = sum(b for _, b in pairs) / len(pairs)
    sxy = sum((a - mx) * (b - my) for a, b in pairs)
    sxx = sum((a - mx) ** 2 for a, _ in pairs)
    syy = sum((b - my) ** 2 for _, b in pairs)
    return sxy / math.sqrt(sxx * syy)


def step_check(main, step, t_lo, t_hi):
    """ln(D at h/2 / D at h) per place, both fitted over [t_lo, t_hi] from curves.csv.gz."""
    def curves(d):
        out = {}
        with gzip.open(os.path.join(d, "curves.csv.gz"), "rt") as f:
            for r in csv.DictReader(f):
                t = float(r["t"])
                if t_lo <= t <= t_hi:
                    out.setdefault(int(r["place"]), []).append((t, float(r["var_along"])))
        return out
    a, b = curves(main), curves(step)
    ratios = []
    for p in sorted(set(a) & set(b)):
        da = line_fit(*zip(*a[p]))[1] / 2
        db = line_fit(*zip(*b[p]))[1] / 2
        if da > 0 and db > 0:
            ratios.append(math.log(db / da))
    m = sum(ratios) / len(ratios)
    se = math.sqrt(sum((x - m) ** 2 for x in ratios) / (len(ratios) - 1) / len(ratios))
    return len(ratios), m, se


def svg(rows, res, path):
    """log10 D against eps^-a at the best a, each run less its place's offset u (so that the law is a
    line): resolved runs as dots, runs whose growth is not linear as bars between their halves, unresolved
    ones as triangles at their upper limit; the law's line and the power law's curve (both fitted)."""
    a, par, pw = res["a"], res["par"], res["power"]
    W, H, m = 640, 420, 64
    eps = res["eps"]
    X0, X1 = min(e ** -a for e in eps), max(e ** -a for e in eps)
    marks, resolved_places = [], []
    for r in rows:
        kind, lo, hi = classify(r)
        place = int(r["place"])
        u = par["u"][place]
        marks.append((r["eps"] ** -a, kind, (lo - u) / math.log(10), (hi - u) / math.log(10)))
        if kind == "point":
            resolved_places.append(place)
    # the frame holds the resolved runs and the intervals; a place whose runs are all upper limits has
    # no bounded offset, so its limits may lie far above: they are counted, not drawn
    ys = [y for _, kind, lo, hi in marks if kind != "upper" for y in (lo, hi)]
    y0, y1 = math.floor(min(ys)) - 1, math.ceil(max(ys)) + 1
    above = sum(1 for _, kind, _lo, hi in marks if kind == "upper" and hi > y1)
    X = lambda x: m + (x - X0) / (X1 - X0) * (W - 2 * m)
    Y = lambda y: H - m - (y - y0) / (y1 - y0) * (H - 2 * m)
    out = svg_axes(W, H, m, f"eps^-{a:g} (eps from {max(eps):g} to {min(eps):g}; ticks at the runs' eps)",
                   "log10 D - place offset (per T)")
    for e in eps:
        out.append(f'<text x="{X(e ** -a):.1f}" y="{H - m + 16}" text-anchor="middle" font-size="9">{e:g}</text>')
    for y in range(y0, y1 + 1, max(1, (y1 - y0) // 8)):
        out.append(f'<text x="{m - 6}" y="{Y(y) + 4:.1f}" text-anchor="end">{y}</text>')
    for x, kind, lo, hi in marks:
        x = X(x)
        if kind == "point":
            out.append(f'<circle cx="{x:.1f}" cy="{Y(lo):.1f}" r="1.8" fill="#9ab" fill-opacity="0.6"/>')
        elif kind == "interval":
            out.append(f'<line x1="{x + 3:.1f}" y1="{Y(lo):.1f}" x2="{x + 3:.1f}" y2="{Y(hi):.1f}" stroke="#d96" '
                       'stroke-opacity="0.5"/>')
        elif hi <= y1:
            out.append(f'<path d="M{x - 6:.1f},{Y(hi) - 2:.1f} l4,0 l-2,4 Z" fill="none" stroke="#aaa" '
                       'stroke-opacity="0.6"/>')
    law = [(x, (par["b0"] + par["b1"] * x) / math.log(10)) for x in (X0, X1)]
    out.append(f'<line x1="{X(law[0][0]):.1f}" y1="{Y(law[0][1]):.1f}" x2="{X(law[1][0]):.1f}" '
               f'y2="{Y(law[1][1]):.1f}" stroke="#c33" stroke-width="2"/>')
    # the power law has its own place offsets: on this picture's scale (less the law's) its curve moves
    # by their mean difference over the resolved runs
    shift = sum(pw["u"][p] - par["u"][p] for p in resolved_places) / len(resolved_places)
    curve = [X0 + (X1 - X0) * k / 60 for k in range(61)]
    out.append('<polyline fill="none" stroke="#36c" stroke-width="2" stroke-dasharray="5 4" points="' +
               " ".join(f"{X(x):.1f},{Y((pw['b0'] + shift + pw['b1'] * math.log(x ** (-1 / a))) / math.log(10)):.1f}"
                        for x in curve) + '"/>')
    out.append(f'<text x="{m + 8}" y="{m - 40}" font-size="11">dots: resolved runs; bars: growth not linear; '
               f'triangles: upper limits ({above} above the frame)</text>')
    out.append(f'<text x="{m + 8}" y="{m - 24}" fill="#c33">D0 exp(-c / eps^a): a = {a:g}, c = {-par["b1"]:.4g} '
               f'({res["n"]} runs, {res["places"]} places)</text>')
    out.append(f'<text x="{m + 8}" y="{m - 8}" fill="#36c">power law D0 eps^n: n = {pw["b1"]:.2f}</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def median(v):
    v = sorted(v)
    return (v[(len(v) - 1) // 2] + v[len(v) // 2]) / 2 if v else float("nan")


def cmd_fit(o, dirs):
    grid_step = float(o.get("grid", 0.01))
    grid = [round(0.02 + grid_step * i, 6) for i in range(int((1.5 - 0.02) / grid_step) + 1)]
    rows = load_results(dirs)
    if o.get("shift"):
        eps, ln = (float(x) for x in o["shift"])
        rows = shifted(rows, eps, ln)
        print(f"every D at eps {eps:g} times exp({ln:+g}) = {math.exp(ln):.3f} (--shift)\n")
    res = analyse(rows, grid, o.get("no-place-effects") is None)
    print("| eps | runs (places) | resolved, linear | not linear (interval) | unresolved (upper limit) | "
          "median D (per T) | median D 2nd half / 1st half |")
    print("|---|---|---|---|---|---|---|")
    for e in res["eps"]:
        k = res["kinds"][e]
        mine = [r for r in rows if r["eps"] == e]
        halves = [r["D_second"] / r["D_first"] for r in mine if r["D_first"] > 0 and r["D_second"] > 0]
        print(f"| {e:g} | {len(k)} | {k.count('point')} | {k.count('interval')} | {k.count('upper')} | "
              f"{median([r['D'] for r in mine]):.3g} | {median(halves):.2f} |")
    par = res["par"]
    print(f"\nlaw ln D = ln D0 - c eps^-a + u_place, scatter tau: a = {res['a']:.3f} "
          f"(68 %: {res['i68'][0]:.3f}-{res['i68'][1]:.3f}, sigma(a) = {res['sigma_a']:.3f}; "
          f"95 %: {res['i95'][0]:.3f}-{res['i95'][1]:.3f}), c = {-par['b1']:.4g}, D0 = {math.exp(par['b0']):.3g}, "
          f"tau = {par['tau']:.3f}; {res['n']} runs of {res['places']} places")
    if res["edge"]:
        print("the best a lies at the grid's edge: the interval is open there")
    pw = res["power"]
    rho = neighbour_correlation(rows, res)
    res["correlated"] = adj = correlated(res, rho)
    verdict = "excluded (95 %)" if res["lr_power"] > 3.84 else "not excluded"
    print(f"power law ln D = ln D0 + n ln eps: n = {pw['b1']:.3f}, tau = {pw['tau']:.3f}; "
          f"-2 ln(L_power / L_law) = {res['lr_power']:.2f}: with the places independent the power law is {verdict}")
    if rho == rho:
        print(f"neighbouring places' residuals: correlation {rho:.3f} (effective places ~{adj['places']:.0f})")
    verdict = "excluded (95 %)" if adj["lr_power"] > 3.84 else "not excluded"
    print(f"with the correlation (the places counted as ~{adj['places']:.0f}): a 68 %: "
          f"{adj['i68'][0]:.3f}-{adj['i68'][1]:.3f}, sigma(a) = {adj['sigma_a']:.3f}; 95 %: "
          f"{adj['i95'][0]:.3f}-{adj['i95'][1]:.3f}; -2 ln(L_power / L_law) = {adj['lr_power']:.2f}: "
          f"the power law is {verdict}")
    if adj["i68"][0] <= res["profile"][0][0]:
        print("  (that 68 % interval reaches the grid's smallest a: it is open there, and sigma(a) a lower bound)")
    print("\n| a | -2 ln L above the best |")
    print("|---|---|")
    best = max(ll for _, ll, _ in res["profile"])
    for a, ll, _ in res["profile"][::max(1, int(0.05 / grid_step))]:
        print(f"| {a:.2f} | {2 * (best - ll):.2f} |")
    if o.get("svg"):
        svg(rows, res, o["svg"])
    if o.get("step"):
        main, step, lo, hi = o["step"]
        n, m, se = step_check(main, step, float(lo), float(hi))
        ok = "consistent" if abs(m) <= 2 * se else "NOT consistent"
        print(f"\nstep size: ln(D(h/2) / D(h)) over {n} places, {lo}-{hi} T: {m:+.3f} +- {se:.3f} ({ok})")
    return res


# ------------------------------------------------------------------ design (Fisher) and synthetic data
def variance_components(path):
    """From the 16-place scan: ln D = m_eps + u_place + v; the sd of u and of v (two-way fit)."""
    with open(path) as f:
        cells = {(float(r["eps"]), float(r["c"])): float(r["D"]) for r in csv.DictReader(f)}
    L = {k: math.log(d) for k, d in cells.items() if d > 0}
    eps = sorted({e for e, _ in L})
    cs = sorted({c for _, c in L})
    m, u = {e: 0.0 for e in eps}, {c: 0.0 for c in cs}
    for _ in range(200):
        for e in eps:
            v = [L[(e, c)] - u[c] for c in cs if (e, c) in L]
            m[e] = sum(v) / len(v)
        for c in cs:
            v = [L[(e, c)] - m[e] for e in eps if (e, c) in L]
            u[c] = sum(v) / len(v)
        mu = sum(u.values()) / len(u)
        u = {c: x - mu for c, x in u.items()}
    res = [L[k] - m[k[0]] - u[k[1]] for k in L]
    sv = math.sqrt(sum(r * r for r in res) / (len(L) - len(eps) - len(cs) + 1))
    su = math.sqrt(sum(x * x for x in u.values()) / (len(cs) - 1))
    return sv, su, m


def fisher_sigma_a(eps, sigma, a, c):
    F = [[0.0] * 3 for _ in range(3)]
    for e in eps:
        x = e ** -a
        J = [1.0, -x, c * x * math.log(e)]
        for i in range(3):
            for j in range(3):
                F[i][j] += J[i] * J[j] / sigma ** 2
    (p, q, r), (s, t, w), (x, y, z) = F
    det = p * (t * z - w * y) - q * (s * z - w * x) + r * (s * y - t * x)
    return math.sqrt((p * t - q * s) / det)


def logspace(lo, hi, n):
    return [lo * (hi / lo) ** (k / (n - 1)) for k in range(n)]


def cmd_design(o):
    path = o.get("csv", os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                     "results", "2026-11-26-d-eps-places.csv"))
    sv, su, m = variance_components(path)
    eps16 = sorted(m)
    print(f"16-place scan ({os.path.basename(path)}): ln D = m_eps + u_place + v: sd(u) = {su:.2f}, "
          f"sd(v) = {sv:.2f}")
    laws = []
    for a in (0.1, 0.21, 0.25, 0.5):
        p, q = line_fit([e ** -a for e in eps16], [m[e] for e in eps16])
        laws.append((a, -q))
    print("c of the law fitted to the 16-place means: " + ", ".join(f"a = {a}: c = {c:.3g}" for a, c in laws))
    print("\nFisher sigma(a): places P paired over every eps (same places at each eps: the place "
          "effects cancel), noise sd(v)/sqrt(P) on each eps's mean of ln D")
    print("| design | " + " | ".join(f"a = {a}" for a, _ in laws) + " |")
    print("|---|" + "---|" * len(laws))
    designs = [("the 16-place scan: 12 eps 0.0025-0.02, 16 places (unpaired sd)", eps16, math.sqrt(sv ** 2 + su ** 2) / 4),
               ("12 eps 0.0025-0.02, 16 places", logspace(0.0025, 0.02, 12), sv / 4)]
    for lo in (0.0013, 0.0016, 0.002):
        for P in (64, 128, 256):
            designs.append((f"12 eps {lo}-0.02, {P} places", logspace(lo, 0.02, 12), sv / math.sqrt(P)))
    designs.append(("11 eps 0.00167-0.02 (no 0.0013), 128 places", logspace(0.0013, 0.02, 12)[1:], sv / math.sqrt(128)))
    for name, eps, s in designs:
        print(f"| {name} | " + " | ".join(f"{fisher_sigma_a(eps, s, a, c):.3f}" for a, c in laws) + " |")


def cmd_synthetic(o):
    """Per eps a places.csv of a known law: ln D = ln D0 - c eps^-a (or a power law n ln eps)
    + u_place + N(0, tau^2); D measured with 10 % errors plus a floor of the run's length
    (Var resolved above 1e-11: se >= 1e-11 / (2 T)); some halves apart (not linear)."""
    rng = random.Random(int(o.get("seed", 1)))
    a, c, lnd0 = float(o.get("a", 0.25)), float(o.get("c", 7.26)), float(o.get("lnD0", -2.5))
    n_pow = o.get("power")
    P, tau, su = int(o.get("places", 32)), float(o.get("tau", 2.3)), float(o.get("sd-place", 1.7))
    eps = logspace(float(o.get("eps-min", 0.0013)), 0.02, int(o.get("n-eps", 12)))
    u = [rng.gauss(0, su) for _ in range(P)]
    for e in eps:
        T = 1e6 if e >= 0.005 else (1e7 if e >= 0.0016 else 3e7)
        rows = []
        for p in range(P):
            mean = (lnd0 + float(n_pow) * math.log(e)) if n_pow else (lnd0 - c * e ** -a)
            d = math.exp(mean + u[p] + rng.gauss(0, tau))
            se = 0.1 * d + 1e-11 / (2 * T)
            dm = d + rng.gauss(0, se)
            spread = 3.0 if rng.random() < 0.15 else 1.2
            d1, d2 = dm * spread ** 0.5, dm / spread ** 0.5
            rows.append([e, T, p, 0.15 + p * 0.002, ORBITS, ORBITS, dm, se, d1, se * 1.4, d2, se * 1.4, 1e-11, 0, 0])
        d = os.path.join(o["out"], f"run-{e:.6g}")
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, "places.csv"), "w", newline="") as g:
            w = csv.writer(g)
            w.writerow(PLACE_FIELDS)
            w.writerows(rows)
    print(f"{len(eps)} eps x {P} places -> {o['out']}/run-*/places.csv")


def options(argv):
    o, rest = {}, []
    i = 0
    while i < len(argv):
        if argv[i] == "--step":
            o["step"] = argv[i + 1:i + 5]
            i += 5
        elif argv[i] == "--shift":
            o["shift"] = argv[i + 1:i + 3]
            i += 3
        elif argv[i] == "--no-place-effects":
            o["no-place-effects"] = True
            i += 1
        elif argv[i].startswith("--"):
            o[argv[i][2:]] = argv[i + 1]
            i += 2
        else:
            rest.append(argv[i])
            i += 1
    return o, rest


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    cmd = sys.argv[1]
    o, rest = options(sys.argv[2:])
    if cmd == "places":
        cs = places(int(o.get("n", 128)))
        text = ("# places c on I1 = I2 (d_eps_scan.py places): midpoints of equal parts of [0.15, 0.48] without\n"
                "# c = p/q +- 0.02 (q <= 3), 0.01 (q = 4, 5), 0.005 (q = 6, 7)\n" + "".join(f"{c!r}\n" for c in cs))
        if o.get("out"):
            with open(o["out"], "w") as f:
                f.write(text)
        else:
            sys.stdout.write(text)
    elif cmd == "campaigns":
        cmd_campaigns(o)
    elif cmd == "candidates":
        cmd_candidates(o)
    elif cmd == "select":
        cmd_select(o)
    elif cmd == "states":
        cmd_states(o)
    elif cmd == "extract":
        cmd_extract(o)
    elif cmd == "fit":
        cmd_fit(o, rest)
    elif cmd == "design":
        cmd_design(o)
    elif cmd == "synthetic":
        cmd_synthetic(o)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
