#!/usr/bin/env python3
"""Draws the Arnold web of a scene (by default scenes/default.toml, the regime of the
paper's Figure 3) from Python: run it with arnoldweb, then plot the velocity map in a
Mollweide projection, with healpy when it is installed, else with matplotlib alone,
with the low-order resonance circles m.P = 0 drawn over it.

    python examples/web.py                          # 1.5e6 trajectories, about a minute on 2 cores
    python examples/web.py --trajectories 20000 --out web.png
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only: runs without a display (CI)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import arnoldweb as aw  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def lon_lat(v):
    """Longitude in [-pi, pi] and latitude of unit vectors (rows)."""
    return np.arctan2(v[..., 1], v[..., 0]), np.arcsin(np.clip(v[..., 2], -1, 1))


def circle(m, n=721):
    """Points of the great circle m.P = 0, as (lon, lat) pieces that do not cross lon = +-pi."""
    m = np.asarray(m, float) / np.linalg.norm(m)
    a = np.cross(m, [1.0, 0, 0] if abs(m[0]) < 0.9 else [0, 1.0, 0])
    a /= np.linalg.norm(a)
    b = np.cross(m, a)
    t = np.linspace(0, 2 * np.pi, n)
    lon, lat = lon_lat(np.outer(np.cos(t), a) + np.outer(np.sin(t), b))
    cuts = np.where(np.abs(np.diff(lon)) > np.pi)[0] + 1
    return zip(np.split(lon, cuts), np.split(lat, cuts))


def draw(result, title, path, order=1, use_healpy=True):
    shade = np.log10(1.0 + result.map.astype(np.float64))
    hp = None
    if use_healpy:
        try:
            import healpy as hp
        except ImportError:
            pass
    if hp is not None:
        hp.mollview(shade, nest=False, title=title, cmap="inferno", unit="log10(1 + count)")
        for r in aw.resonances(order):
            for lon, lat in circle(r["m"]):
                hp.projplot(np.degrees(lon), np.degrees(lat), lonlat=True, color="cyan", lw=0.3, alpha=0.35)
        fig = plt.gcf()
    else:
        fig = plt.figure(figsize=(10, 5.6))
        ax = fig.add_subplot(projection="mollweide")
        lon, lat = lon_lat(aw.pixel_directions(result.nside))
        dots = ax.scatter(-lon, lat, c=shade, s=4.0 * (64.0 / result.nside) ** 2, cmap="inferno",
                          marker="h", linewidths=0)
        for r in aw.resonances(order):
            for lo, la in circle(r["m"]):
                ax.plot(-lo, la, color="cyan", lw=0.3, alpha=0.35)
        ax.set_xticklabels([])
        ax.grid(alpha=0.3)
        ax.set_title(title)
        fig.colorbar(dots, ax=ax, orientation="horizontal", shrink=0.6, label="log10(1 + count)")
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--scene", default=os.path.join(HERE, "..", "scenes", "default.toml"))
    p.add_argument("--trajectories", type=int, help="override ensemble.trajectories")
    p.add_argument("--device", help="cpu, opencl:N, cuda:N (default: the scene's run.device)")
    p.add_argument("--out", default="web.png", help="the figure to write (PNG)")
    p.add_argument("--no-healpy", action="store_true", help="draw with matplotlib alone")
    a = p.parse_args(argv)

    scene = aw.Scene.from_file(a.scene)
    if a.trajectories:
        scene = scene.set("ensemble.trajectories", a.trajectories)
    result = aw.run(scene, device=a.device, progress=sys.stderr.isatty())
    title = (f"Arnold web, E = {scene['model.energy']:g}: {result.binned} trajectories "
             f"(nside {result.nside}, {result.device['id']})")
    draw(result, title, a.out, use_healpy=not a.no_healpy)
    print(f"wrote {a.out}: {result.binned} of {result.completed} trajectories binned, map digest "
          f"{result.digests['map']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
