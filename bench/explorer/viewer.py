"""Benchmark of the explorer (docs/viewer.md; a benchmark, not a test): in headless Chromium,
the time to the first frame and the frames per second while turning the globe, for the
default scene's map (nside 64) and an nside 1024 map; and the click-to-map time of a zoom
asked for through `arnoldweb serve` (from the POST until its map is drawn as a layer).

    /usr/bin/python3 bench/explorer/viewer.py --cli build/arnoldweb [--gpu] [--device cuda:0]
        [--zoom 100000] [--work /tmp/aw-viewer-bench] [--no-browser]

Without --gpu the browser draws with SwiftShader (software WebGL2, the CPU machine); with
--gpu it uses the machine's GPU (--use-angle=vulkan or the default ANGLE backend). One line of
results per measurement, as docs/viewer.md quotes them."""
import argparse
import json
import os
import platform
import shutil
import socket
import subprocess
import sys
import time

CHROMIUM = "/usr/bin/chromium"

p = argparse.ArgumentParser()
p.add_argument("--cli", required=True)
p.add_argument("--source", default=os.path.join(os.path.dirname(__file__), "..", ".."))
p.add_argument("--work", default="/tmp/aw-viewer-bench")
p.add_argument("--gpu", action="store_true", help="draw with the GPU instead of SwiftShader")
p.add_argument("--device", default="cpu", help="where the zoom runs")
p.add_argument("--zoom", type=int, default=100000, help="trajectories of the zoom")
p.add_argument("--frames", type=int, default=30)
p.add_argument("--no-browser", action="store_true",
               help="only the zoom, timed over HTTP from the request to its map's bytes (a machine without Chromium)")
a = p.parse_args()
if not a.no_browser:  # the browser's tools (selenium, numpy, healpy): a machine without them can still time the zoom
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "explorer"))
    import support as S  # noqa: E402
shutil.rmtree(a.work, ignore_errors=True)
os.makedirs(a.work)
scene = os.path.join(a.source, "scenes", "default.toml")


def run(out, *sets):
    t0 = time.time()
    subprocess.run([a.cli, "run", scene, "--device", a.device, "-q", "--out", out, *sum((["--set", s] for s in sets), [])],
                   check=True)
    return time.time() - t0


def browser():
    if not a.gpu:
        return S.browser(1200, 800)
    o = S.webdriver.ChromeOptions()
    for arg in ("--headless=new", "--no-sandbox", "--enable-gpu", "--ignore-gpu-blocklist", "--use-angle=vulkan",
                "--window-size=1200,800", "--force-device-scale-factor=1"):
        o.add_argument(arg)
    o.binary_location = S.CHROMIUM
    return S.webdriver.Chrome(service=S.Service(S.DRIVER), options=o)


def measure(d, url):
    t0 = time.time()
    d.set_script_timeout(600)
    S.open_page(d, url, timeout=600)
    first = d.execute_script("return AW.app.stats().firstFrameMs")  # performance.now(): from the navigation
    renderer = d.execute_script("""const gl = AW.app.panels[0].renderer.gl;
      const e = gl.getExtension('WEBGL_debug_renderer_info'); return e ? gl.getParameter(e.UNMASKED_RENDERER_WEBGL) : '';""")
    # turn the globe: one degree of longitude a frame, each frame drawn and finished
    fps = d.execute_async_script("""
      const done = arguments[arguments.length - 1], n = arguments[0], s = AW.app.state;
      const t0 = performance.now(); let k = 0;
      function step() {
        s.lon += 1; AW.app.changed();
        requestAnimationFrame(() => { AW.app.panels[0].renderer.gl.finish(); if (++k < n) step(); else done(n * 1000 / (performance.now() - t0)); });
      }
      step();""", a.frames)
    return first, fps, renderer, time.time() - t0


cpu = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
model = next((l.split(":", 1)[1].strip() for l in cpu.splitlines() if l.startswith("Model name")), platform.processor())
chromium = (subprocess.run([CHROMIUM, "--version"], capture_output=True, text=True).stdout.strip()
            if shutil.which(CHROMIUM) else "absent")
print(f"machine: {model}, {os.cpu_count()} CPUs; chromium {chromium}")
maps = {"default scene (nside 64)": ("default", []),
        "nside 1024": ("n1024", ["observe.velocity_map.nside=1024", "ensemble.trajectories=200000"])}
for name, (out, sets) in maps.items():
    path = os.path.join(a.work, out)
    if a.no_browser:
        if out == "default":
            run(path)
        continue
    run(path, *sets)
    subprocess.run([a.cli, "view", path], check=True, capture_output=True)
    size = sum(os.path.getsize(os.path.join(path + ".view", "data", f)) for f in os.listdir(os.path.join(path + ".view", "data")))
    d = browser()
    try:
        first, fps, renderer, wall = measure(d, "file://" + os.path.abspath(path) + ".view/view.html")
    finally:
        d.quit()
    print(f"{name}: first frame {first / 1000:.2f} s after navigation (data {size / 1e6:.1f} MB), "
          f"turning the globe {fps:.1f} frames/s at 1200x800 ({renderer})")

# the click-to-map time of a zoom through serve
with socket.socket() as s:
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
srv = subprocess.Popen([a.cli, "serve", os.path.join(a.work, "default"), "--port", str(port), "--device", a.device,
                        "--max-trajectories", str(a.zoom), "--zooms", os.path.join(a.work, "zooms")],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
try:
    while True:
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.2).close()
            break
        except OSError:
            time.sleep(0.1)
    if a.no_browser:
        import http.client
        c = http.client.HTTPConnection("127.0.0.1", port, timeout=600)
        t0 = time.time()
        c.request("POST", "/api/zooms", json.dumps({"source": "r0", "trajectories": a.zoom, "nside": 256,
                                                     "region": {"kind": "cap", "center": [45, 8], "radius": 4}}))
        zid = json.loads(c.getresponse().read())["id"]
        while True:
            c.request("GET", f"/api/zooms/{zid}")
            st = json.loads(c.getresponse().read())
            if st["state"] not in ("queued", "running"):
                break
            time.sleep(0.02)
        c.request("GET", f"/api/runs/{zid}/map")
        size = len(c.getresponse().read())
        print(f"zoom of {a.zoom} trajectories on {a.device}: request to map bytes {time.time() - t0:.2f} s "
              f"({st['state']}, run {st['seconds']:.2f} s, map {size / 1e6:.1f} MB)")
        sys.exit(0)
    d = browser()
    try:
        S.open_page(d, f"http://127.0.0.1:{port}/")
        d.execute_script(f"AW.zoom.show({{kind: 'cap', center: [45, 8], radius: 4}}); document.getElementById('zoom-n').value = {a.zoom};")
        t0 = time.time()
        d.find_element("id", "zoom-run").click()
        while d.execute_script("return document.body.dataset.zoom") is None:
            time.sleep(0.05)
        took = time.time() - t0
    finally:
        d.quit()
    print(f"zoom of {a.zoom} trajectories on {a.device}: click to map {took:.2f} s")
finally:
    srv.send_signal(2)
    srv.wait(60)
