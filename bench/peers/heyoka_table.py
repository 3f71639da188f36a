#!/usr/bin/env python3
"""arnoldweb against heyoka.py (Taylor method, LLVM-compiled, SIMD batch mode) on the same
initial states, the same CPU cores, back to back (issue 18; docs/performance.md).

    python3 bench/peers/heyoka_table.py [--energy 15] [--trajectories 20000] [--threads 2]

The model is H = |P|^2/2 + cos x cos y (1 + cos 2z); T = 2 pi. Every run integrates the
ensemble over 10 T and samples |E(t) - E(0)| every 0.5 T; the figure of merit is the wall
time to reach max |dE| (over the ensemble and the samples) <= 1e-6, 1e-8, 1e-10, 1e-12.

1. arnoldweb writes the initial states (observe.initial_states = true -> states.h5, positions
   in turns u = x / 2 pi) of the scene (E, N, seed 1, shell).
2. arnoldweb (cpu backend, portable math, double): for each candidate method a ladder of steps
   h = 0.5 T / n; the wall time is summary.json's wall_seconds (the run, not the process start).
   Per target the cheapest measured run that meets it.
3. heyoka.py: the same states in batches of the SIMD width (taylor_adaptive_batch; --batch), one
   integrator per thread (--threads, default 2, each thread a contiguous share of the batches;
   heyoka releases the GIL in propagate_grid), a ladder of tolerances; the time is the wall
   time of the propagation (the integrators are compiled before the clock starts, and the
   compile time is printed apart). Per target the fastest tolerance that meets it.

--focus: one target (--target, default 1e-8), the two configurations that meet it (--aw-runs for
arnoldweb, METHOD:n for h = T/n, the first that meets the target counts; --hk-tols for heyoka),
timed --repeat times in turn (arnoldweb, heyoka, arnoldweb, ...): arnoldweb as a WHOLE PROCESS
(wall clock around the child, and its CPU time from the OS), heyoka's integration (the
propagation's wall and CPU time, compiled beforehand); medians and the ratio (issue 29).

heyoka.py is installed on demand from PyPI into a virtual environment (--venv, default
build/heyoka-venv) with numpy and h5py; nothing of it is needed by the build or the tests.
The script re-runs itself inside that environment.
"""
import argparse
import json
import os
import platform
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
HEYOKA_VERSION = "7.13.2"
TARGETS = [1e-6, 1e-8, 1e-10, 1e-12]


def ensure_venv(venv):
    py = os.path.join(venv, "bin", "python")
    if not os.path.exists(py):
        print(f"creating {venv} and installing heyoka=={HEYOKA_VERSION}, numpy, h5py from PyPI", file=sys.stderr)
        subprocess.check_call([sys.executable, "-m", "venv", venv])
        subprocess.check_call([py, "-m", "pip", "install", "-q", f"heyoka=={HEYOKA_VERSION}", "numpy", "h5py"])
    return py


def cpu_model():
    name, flags = platform.processor(), ""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name") and not name.strip():
                    name = line.split(":", 1)[1].strip()
                if line.startswith("model name"):
                    name = line.split(":", 1)[1].strip()
                if line.startswith("flags"):
                    flags = line
                    break
    except OSError:
        pass
    width = "AVX-512 (8 doubles)" if "avx512f" in flags else "AVX2 (4 doubles)" if "avx2" in flags else "SSE2"
    return name, width


def scene_sets(a, extra):
    sets = [f"model.energy={a.energy}", f"ensemble.trajectories={a.trajectories}", "ensemble.seed=1",
            "run.duration=10", "run.average=10", "observe.velocity_map=false", "observe.energy_error.every=0.5",
            "output.images=false", "integrator.precision=\"double\"", "integrator.math=\"portable\""]
    sets += extra
    out = []
    for s in sets:
        out += ["--set", s]
    return out


def arnoldweb_run(a, out, extra, scene=os.path.join(ROOT, "scenes", "default.toml")):
    import resource
    cmd = [a.arnoldweb, "run", scene, "--device", "cpu", "-q", "-f", "-o", out]
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.check_call(cmd + scene_sets(a, extra))
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    # core-seconds of the whole process (start, scene, run, summary): an upper bound of the run's
    s["cpu_seconds"] = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    s["process_seconds"] = wall  # the whole process, start to exit
    return s


def arnoldweb_ladder(a, work):
    # steps h = 0.5 T / n within the guard (h k |p|max < pi/2 advised; pi refused)
    import math
    pmax = math.sqrt(2 * (a.energy + 2))
    h_largest = 1 / (4 * pmax) / 2  # h k |p|max = pi/2 with k = 2, h in T
    ladder = [n for n in (12, 16, 20, 25, 32, 40, 50, 64, 80, 100, 128, 160, 200, 256, 320, 400, 512, 640,
                        800, 1024, 1280, 1600, 2048)
              if 0.5 / n <= h_largest * 1.0001]
    rows = []
    for method in a.methods.split(","):
        previous = float("inf")
        for n in ladder:
            step = 0.5 / n
            s = arnoldweb_run(a, os.path.join(work, "aw"),
                              [f"integrator.method=\"{method}\"", f"integrator.step={step!r}"])
            e = s["energy_error"]["max"]
            rows.append({"method": method, "step": step, "max_dE": e, "seconds": s["wall_seconds"],
                         "cpu_seconds": s["cpu_seconds"], "forces_per_T": s["method"]["stages"] / step})
            print(f"  arnoldweb {method:9s} h = T/{2 * n:<5d} max|dE| {e:.2e}  {s['wall_seconds']:.3f} s "
                  f"(process cpu {s['cpu_seconds']:.2f} s)", file=sys.stderr, flush=True)
            # done below the smallest target, or where round-off stops the error falling
            if e <= min(TARGETS) or e > 0.7 * previous:
                break
            previous = e
    return rows


def energy(q, p):
    import numpy as np
    return 0.5 * np.sum(p * p, axis=-1) + np.cos(q[..., 0]) * np.cos(q[..., 1]) * (1 + np.cos(2 * q[..., 2]))


def heyoka_problem(a, states):
    """The ensemble in heyoka's terms: positions in radians, padded to whole batches (the last
    state repeated), the sample grid per batch lane, the initial energies."""
    import types
    import numpy as np
    q0 = states[:, :3] * 2 * np.pi
    p0 = states[:, 3:]
    n = len(states)
    nb = (n + a.batch - 1) // a.batch
    pad = nb * a.batch - n
    q0p = np.vstack([q0, np.repeat(q0[-1:], pad, axis=0)])
    p0p = np.vstack([p0, np.repeat(p0[-1:], pad, axis=0)])
    grid = np.arange(21) * np.pi  # every 0.5 T over 10 T (T = 2 pi)
    return types.SimpleNamespace(n=n, batches=nb, q0=q0p, p0=p0p, e0=energy(q0p, p0p),
                                 grid=np.repeat(grid, a.batch).reshape(-1, a.batch))


def heyoka_integrators(a, tol):
    """One compiled batch integrator per thread, and the seconds the compilation took."""
    import heyoka as hy
    import numpy as np
    x, y, z, px, py, pz = hy.make_vars("x", "y", "z", "px", "py", "pz")
    V = hy.cos(x) * hy.cos(y) * (1.0 + hy.cos(2.0 * z))
    sys_ = [(x, px), (y, py), (z, pz), (px, -hy.diff(V, x)), (py, -hy.diff(V, y)), (pz, -hy.diff(V, z))]
    t0 = time.time()
    tas = [hy.taylor_adaptive_batch(sys_, np.zeros((6, a.batch)), tol=tol) for _ in range(a.threads)]
    return tas, time.time() - t0


def heyoka_propagate(a, tas, pb):
    """The whole ensemble over the grid, each thread a contiguous share of the batches (heyoka
    releases the GIL in propagate_grid): wall and CPU time of the propagation, max |dE|."""
    import threading
    import numpy as np
    batch = a.batch
    de = np.zeros(pb.batches * batch)
    bounds = np.linspace(0, pb.batches, a.threads + 1).astype(int)

    def work(k):
        ta = tas[k]
        for b in range(bounds[k], bounds[k + 1]):
            sl = slice(b * batch, (b + 1) * batch)
            ta.set_time(0.0)
            ta.state[:3] = pb.q0[sl].T
            ta.state[3:] = pb.p0[sl].T
            out = ta.propagate_grid(pb.grid)[-1]  # (len(grid), 6, batch)
            e = energy(np.moveaxis(out[:, :3, :], 1, 2), np.moveaxis(out[:, 3:, :], 1, 2))
            de[sl] = np.max(np.abs(e - pb.e0[sl]), axis=0)

    t0 = time.time()
    c0 = time.process_time()
    threads = [threading.Thread(target=work, args=(k,)) for k in range(a.threads)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return {"order": tas[0].order, "max_dE": float(np.max(de[:pb.n])), "seconds": time.time() - t0,
            "cpu_seconds": time.process_time() - c0}


def heyoka_ladder(a, states):
    pb = heyoka_problem(a, states)
    rows = []
    for tol in a.tolerances:
        tas, compile_s = heyoka_integrators(a, tol)
        row = heyoka_propagate(a, tas, pb)
        row.update({"tol": tol, "compile_seconds": compile_s})
        rows.append(row)
        print(f"  heyoka tol {tol:.0e} (order {row['order']}) max|dE| {row['max_dE']:.2e}  {row['seconds']:.3f} s "
              f"(cpu {row['cpu_seconds']:.2f} s, compile {compile_s:.1f} s)", file=sys.stderr, flush=True)
    return rows


def focus(a, states):
    """--focus: each configuration of each side timed a.repeat times, in turn, and the ratio at the
    target of the cheapest of each side that meets it (medians; pairs taken in the same round)."""
    import statistics
    pb = heyoka_problem(a, states)
    hk = {}
    for tol in [float(t) for t in a.hk_tols.split(",")]:
        tas, compile_s = heyoka_integrators(a, tol)
        hk[tol] = {"tas": tas, "compile_seconds": compile_s, "rows": []}
    aw = {c: [] for c in a.aw_runs.split(",")}
    # "auto" chooses the method too where the scene names none: the default scene without its method
    unnamed = os.path.join(a.work, "no_method.toml")
    with open(os.path.join(ROOT, "scenes", "default.toml")) as f, open(unnamed, "w") as g:
        g.writelines(line for line in f if not line.startswith("method"))

    def aw_sets(c):
        if c == "auto":  # the method and step integrator.step = "auto" chooses for the target
            return ["integrator.step=\"auto\"", f"integrator.tolerance={a.target!r}"]
        method, n = c.split(":")
        return [f"integrator.method=\"{method}\"", f"integrator.step={1 / int(n)!r}"]

    for r in range(a.repeat):
        for c, rows in aw.items():
            s = arnoldweb_run(a, os.path.join(a.work, "aw"), aw_sets(c), unnamed)
            rows.append({"max_dE": s["energy_error"]["max"], "seconds": s["process_seconds"],
                         "cpu_seconds": s["cpu_seconds"], "run_seconds": s["wall_seconds"],
                         "method": s["method"]["name"], "step": s["scene"]["integrator"]["step"]})
        for tol, h in hk.items():
            h["rows"].append(heyoka_propagate(a, h["tas"], pb))
    med = lambda rows, k: statistics.median(x[k] for x in rows)
    print(f"\nmax|dE| <= {a.target:g}: {a.repeat} rounds, medians (min-max); arnoldweb: whole process "
          f"(start to exit), heyoka.py: the propagation (compiled before)")
    print("| side | configuration | max abs(dE) | wall s | core-s | meets |")
    print("|---|---|---|---|---|---|")
    spread = lambda rows, k: f"{med(rows, k):.3f} ({min(x[k] for x in rows):.3f}-{max(x[k] for x in rows):.3f})"
    for c, rows in aw.items():
        what = f"{rows[0]['method']}, h = T/{round(1 / rows[0]['step'])}" + (" (auto)" if c == "auto" else "")
        print(f"| arnoldweb | {what} | {rows[0]['max_dE']:.2e} | {spread(rows, 'seconds')} | "
              f"{spread(rows, 'cpu_seconds')} | {'yes' if rows[0]['max_dE'] <= a.target else 'no'} |")
    for tol, h in hk.items():
        rows = h["rows"]
        print(f"| heyoka.py | tol {tol:.0e}, order {rows[0]['order']} (compile {h['compile_seconds']:.2f} s) | "
              f"{rows[0]['max_dE']:.2e} | {spread(rows, 'seconds')} | {spread(rows, 'cpu_seconds')} | "
              f"{'yes' if rows[0]['max_dE'] <= a.target else 'no'} |")
    hk_ok = [h["rows"] for h in hk.values() if h["rows"][0]["max_dE"] <= a.target]
    out = {"target": a.target, "repeat": a.repeat, "arnoldweb": aw,
           "heyoka": {str(t): {"compile_seconds": h["compile_seconds"], "rows": h["rows"]} for t, h in hk.items()}}
    if not hk_ok:
        print("heyoka.py met the target with none of --hk-tols")
        return out
    for key, what in (("seconds", "wall"), ("cpu_seconds", "core-seconds")):
        hrows = min(hk_ok, key=lambda rows: med(rows, key))
        for c, rows in aw.items():
            if rows[0]["max_dE"] <= a.target:
                pairs = [h[key] / w[key] for h, w in zip(hrows, rows)]
                print(f"lead of arnoldweb {c} in {what}: {med(hrows, key) / med(rows, key):.2f}x "
                      f"(ratio of medians; pairs {min(pairs):.2f}-{max(pairs):.2f})")
    return out


def best(rows, target, key):
    ok = [r for r in rows if r["max_dE"] <= target]
    return min(ok, key=lambda r: r[key]) if ok else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--energy", type=float, default=15.0)
    ap.add_argument("--trajectories", type=int, default=20000)
    ap.add_argument("--threads", type=int, default=2, help="heyoka threads (arnoldweb's cpu backend uses OpenMP)")
    ap.add_argument("--methods", default="srkn11b,aba864,aba1064,sbab3c,sbab4c,saba4c,chin4a")
    ap.add_argument("--batch", type=int, default=0,
                    help="heyoka batch size (default: heyoka's recommended SIMD size on this CPU)")
    ap.add_argument("--tolerances", default="1e-6,3e-7,1e-7,3e-8,1e-8,3e-9,1e-9,3e-10,1e-10,3e-11,1e-11,3e-12,1e-12,"
                    "3e-13,1e-13,3e-14,1e-14,3e-15,1e-15,3e-16,1e-16")
    ap.add_argument("--arnoldweb", default=os.path.join(ROOT, "build", "arnoldweb"))
    ap.add_argument("--venv", default=os.path.join(ROOT, "build", "heyoka-venv"))
    ap.add_argument("--work", default="/tmp/arnoldweb-heyoka")
    ap.add_argument("--json", help="write every measured row here")
    ap.add_argument("--focus", action="store_true",
                    help="time one target's configurations of both sides --repeat times in turn (issue 29)")
    ap.add_argument("--target", type=float, default=1e-8, help="--focus: the target max |dE|")
    ap.add_argument("--aw-runs", default="aba864:128,auto",
                    help="--focus: arnoldweb's configurations, METHOD:n (h = T/n) or auto (integrator.step = "
                         "\"auto\" with integrator.tolerance = the target)")
    ap.add_argument("--hk-tols", default="3e-11", help="--focus: heyoka's tolerances")
    ap.add_argument("--repeat", type=int, default=5, help="--focus: rounds")
    a = ap.parse_args()
    if os.environ.get("ARNOLDWEB_HEYOKA_VENV") != "1":
        py = ensure_venv(a.venv)
        env = dict(os.environ, ARNOLDWEB_HEYOKA_VENV="1")
        os.execve(py, [py, os.path.abspath(__file__)] + sys.argv[1:], env)
    a.tolerances = [float(t) for t in a.tolerances.split(",")]
    import h5py
    import heyoka as hy
    import numpy as np

    os.makedirs(a.work, exist_ok=True)
    # 1. the initial states, as arnoldweb draws them
    s = arnoldweb_run(a, os.path.join(a.work, "states"), ["observe.initial_states=true", "integrator.step=0.01",
                                                           "integrator.allow_unsafe_step=true"])
    with h5py.File(os.path.join(a.work, "states", "states.h5")) as f:
        states = np.hstack([f["initial/position_turns"][:], f["initial/momentum"][:]])
    assert len(states) == a.trajectories
    model, width = cpu_model()
    a.batch = a.batch or hy.recommended_simd_size()  # 8 doubles with AVX-512, 4 with AVX2
    print(f"E = {a.energy:g}, {a.trajectories} trajectories x 10 T, |dE| every 0.5 T; {model}, "
          f"{os.cpu_count()} cores, {width}; heyoka.py {hy.__version__}, batch {a.batch}, {a.threads} threads; "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}", flush=True)
    if a.focus:
        out = focus(a, states)
        if a.json:
            out.update({"energy": a.energy, "trajectories": a.trajectories, "cpu": model, "vector": width,
                        "heyoka": hy.__version__, "batch": a.batch, "date": time.strftime('%Y-%m-%d', time.gmtime())})
            with open(a.json, "w") as f:
                json.dump(out, f, indent=1)
        return
    # 2. and 3. back to back
    aw = arnoldweb_ladder(a, a.work)
    hk = heyoka_ladder(a, states)
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"energy": a.energy, "trajectories": a.trajectories, "cpu": model, "vector": width,
                       "heyoka": hy.__version__, "batch": a.batch, "arnoldweb": aw, "heyoka_rows": hk,
                       "date": time.strftime('%Y-%m-%d', time.gmtime())}, f, indent=1)
    for key, what in (("seconds", "wall seconds"), ("cpu_seconds", "core-seconds (CPU time of all threads)")):
        print()
        print(f"cheapest in {what}:")
        print("| target max abs(dE) | heyoka.py (batch %d, %d threads): tol, order | its max abs(dE) | time | "
              "arnoldweb cpu: cheapest method, step | its max abs(dE) | time | arnoldweb's lead |" % (a.batch, a.threads))
        print("|---|---|---|---|---|---|---|---|")
        for t in TARGETS:
            h, w = best(hk, t, key), best(aw, t, key)
            hs = f"{h['tol']:.0e}, order {h['order']} | {h['max_dE']:.1e} | {h[key]:.2f} s" if h else "- | - | -"
            ws = (f"{w['method']}, h = T/{round(1 / w['step'])} | {w['max_dE']:.1e} | {w[key]:.2f} s" if w
                  else "- | - | -")
            lead = f"**{h[key] / w[key]:.1f}x**" if h and w else "-"
            print(f"| {t:.0e} | {hs} | {ws} | {lead} |")


if __name__ == "__main__":
    main()
