"""Shared by the explorer's browser tests (docs/viewer.md): headless Chromium through Debian's
Selenium and chromedriver, small runs made with the arnoldweb CLI, and what the page shows
computed independently here: each projection's inverse written from its textbook formula,
HEALPix pixels from healpy, maps from h5py. A missing tool is a skip (exit 77), a failure in
CI (ARNOLDWEB_REQUIRE_CHECKS=1)."""
import argparse
import os
import shutil
import subprocess
import sys
import time
from math import gcd

SKIP = 77


def skip(why):
    print(f"SKIPPED: {why}")
    if os.environ.get("ARNOLDWEB_REQUIRE_CHECKS") == "1":
        print("ARNOLDWEB_REQUIRE_CHECKS=1: a skipped check fails")
        sys.exit(1)
    sys.exit(SKIP)


try:
    import numpy as np
    import h5py
    import healpy
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.actions.action_builder import ActionBuilder
except ImportError as e:  # Debian: python3-numpy python3-h5py python3-healpy python3-selenium
    skip(f"{e.name} is not importable by {sys.executable} (scripts/packages.txt lists the Debian packages)")

CHROMIUM, DRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"


def arguments():
    p = argparse.ArgumentParser()
    p.add_argument("--cli", required=True, help="the arnoldweb binary")
    p.add_argument("--source", required=True, help="the repository (scenes/)")
    p.add_argument("--work", required=True, help="a scratch directory (emptied)")
    p.add_argument("--artifacts", required=True, help="where screenshots go")
    return p.parse_args()


def start():
    """The test's arguments, its scratch directory emptied, and its checks."""
    args = arguments()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    os.makedirs(args.artifacts, exist_ok=True)
    return args, Checks()


def arnoldweb(args, *words, check=True, **kw):
    r = subprocess.run([args.cli, *words], capture_output=True, text=True, **kw)
    if check and r.returncode != 0:
        raise AssertionError(f"arnoldweb {' '.join(words)} exited {r.returncode}:\n{r.stdout}\n{r.stderr}")
    return r


def small_run(args, out, trajectories=40000, extra=()):
    """The default scene at test size on the cpu backend."""
    arnoldweb(args, "run", os.path.join(args.source, "scenes", "default.toml"), "--device", "cpu", "-q",
              "--set", f"ensemble.trajectories={trajectories}", "--out", out, *extra)
    return out


def map_of(out):
    with h5py.File(os.path.join(out, "map.h5"), "r") as f:
        return f["map"][()]


def browser(width=1100, height=760):
    if not (os.path.exists(CHROMIUM) and os.path.exists(DRIVER)):
        skip("no /usr/bin/chromium and /usr/bin/chromedriver (Debian: chromium chromium-driver)")
    o = webdriver.ChromeOptions()
    # WebGL2 in software (SwiftShader through ANGLE): no GPU needed
    for a in ("--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
              f"--window-size={width},{height}", "--force-device-scale-factor=1", "--disable-extensions"):
        o.add_argument(a)
    o.binary_location = CHROMIUM
    o.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(DRIVER), options=o)


def open_page(d, url, timeout=60):
    d.get(url)
    t0 = time.time()
    while d.execute_script("return document.body && document.body.dataset.ready") != "1":
        errors = d.execute_script("return document.getElementById('errors') && document.getElementById('errors').textContent")
        if errors:
            raise AssertionError(f"the page reports: {errors}")
        if time.time() - t0 > timeout:
            raise AssertionError(f"{url} did not become ready in {timeout} s")
        time.sleep(0.05)


def console_errors(d):
    return [e for e in d.get_log("browser") if e["level"] == "SEVERE"]


def set_view(d, **view):
    """Sets the view through the URL's state (as a shared link does) and waits for a frame."""
    d.execute_script("""
      const p = new URLSearchParams(location.hash.slice(1));
      for (const [k, v] of Object.entries(arguments[0])) p.set(k, v);
      location.hash = p.toString();""", {k: str(v) for k, v in view.items()})
    time.sleep(0.3)
    d.execute_script("AW.app.redraw()")
    time.sleep(0.2)


def canvas_box(d, index=0):
    """Left, top (viewport, CSS pixels) of the index-th map canvas, and the width and height the
    page projects onto (its client size)."""
    return d.execute_script("""
      const c = AW.app.panels[arguments[0]].map, r = c.getBoundingClientRect();
      return [r.left, r.top, c.clientWidth, c.clientHeight];""", index)


def hover(d, x, y):
    """Moves the mouse to viewport position (x, y) (integers) and returns the readout."""
    b = ActionBuilder(d, duration=0)
    b.pointer_action.move_to_location(int(x), int(y))
    b.perform()
    return d.execute_script("""
      const t = (id) => document.getElementById(id).textContent;
      return {theta: t('ro-theta'), phi: t('ro-phi'), pix: t('ro-pix'), value: t('ro-value'),
              res: [...document.querySelectorAll('#ro-res li')].map((li) => li.dataset.label)};""")


def hover_many(d, points):
    """The readout at each viewport position of `points`, in one call: a pointer move is sent
    to the element at that position (as the browser would) and the readout read back."""
    return d.execute_script("""
      const t = (id) => document.getElementById(id).textContent;
      return arguments[0].map(([x, y]) => {
        const el = document.elementFromPoint(x, y);
        el.dispatchEvent(new PointerEvent('pointermove', {clientX: x, clientY: y, bubbles: true, pointerId: 1}));
        return {element: el.className, theta: t('ro-theta'), phi: t('ro-phi'), pix: t('ro-pix'), value: t('ro-value'),
                res: [...document.querySelectorAll('#ro-res li')].map((li) => li.dataset.label)};
      });""", [[int(x), int(y)] for x, y in points])


def click(d, x, y):
    b = ActionBuilder(d, duration=0)
    b.pointer_action.move_to_location(int(x), int(y))
    b.pointer_action.click()
    b.perform()


# ---------------------------------------------------------------- the projections, independently
def frame(lon, lat):
    lo, la = np.radians(lon), np.radians(lat)
    c = np.array([np.cos(la) * np.cos(lo), np.cos(la) * np.sin(lo), np.sin(la)])
    e = np.array([-np.sin(lo), np.cos(lo), 0.0])
    n = np.cross(c, e)
    return c, e, n


def plane_scale(proj, zoom, w, h):
    """Plane units per CSS pixel (docs/viewer.md: the globe's radius is 0.45 of the smaller side
    at zoom 1, the gnomonic plane's unit too, the Mollweide ellipse fills 0.47 of the panel)."""
    if proj == "mollweide":
        return 1.0 / (min(0.47 * w / (2 * np.sqrt(2)), 0.47 * h / np.sqrt(2)) * zoom)
    return 1.0 / (0.45 * min(w, h) * zoom)


def direction_at(proj, lon, lat, zoom, w, h, sx, sy):
    """The unit direction shown at CSS position (sx, sy) of a w x h panel, or None."""
    s = plane_scale(proj, zoom, w, h)
    x, y = (sx - w / 2) * s, (h / 2 - sy) * s
    c, e, n = frame(lon, lat)
    if proj == "ortho":
        if x * x + y * y >= 1:
            return None
        return x * e + y * n + np.sqrt(1 - x * x - y * y) * c
    if proj == "gnomonic":
        v = x * e + y * n + c
        return v / np.linalg.norm(v)
    # Mollweide: x = 2 sqrt2/pi lam cos t, y = sqrt2 sin t, 2t + sin 2t = pi sin phi
    if x * x / 8 + y * y / 2 >= 1:
        return None
    t = np.arcsin(y / np.sqrt(2))
    phi = np.arcsin((2 * t + np.sin(2 * t)) / np.pi)
    lam = np.pi * x / (2 * np.sqrt(2) * np.cos(t))
    if abs(lam) > np.pi:
        return None
    return np.cos(phi) * np.sin(lam) * e + np.sin(phi) * n + np.cos(phi) * np.cos(lam) * c


def screen_of(proj, lon, lat, zoom, w, h, v):
    """CSS position of a direction (orthographic and gnomonic), or None where not drawn."""
    c, e, n = frame(lon, lat)
    x, y, z = v @ e, v @ n, v @ c
    if z <= 0:
        return None
    if proj == "gnomonic":
        x, y = x / z, y / z
    s = plane_scale(proj, zoom, w, h)
    return w / 2 + x / s, h / 2 - y / s


def resonances(k):
    """Every m with max |m_i| <= k, coprime, first non-zero component positive."""
    out = []
    for a in range(0, k + 1):
        for b in range(-k, k + 1):
            for c in range(-k, k + 1):
                m = (a, b, c)
                if m == (0, 0, 0) or gcd(gcd(a, abs(b)), abs(c)) != 1:
                    continue
                if next(x for x in m if x) < 0:
                    continue
                out.append(m)
    return out


def label(m):
    return "(" + ",".join(str(x) for x in m) + ")"


class Checks:
    """Counts failed assertions and reports them all."""

    def __init__(self):
        self.failed = []

    def __call__(self, ok, what):
        if not ok:
            self.failed.append(what)
            print("FAILED:", what)
        return ok

    def finish(self, name):
        if self.failed:
            print(f"{name}: {len(self.failed)} check(s) failed")
            sys.exit(1)
        print(f"{name}: passed")
