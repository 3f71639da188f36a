"""arnoldweb serve: the same page over HTTP (no console error; the values it reports are
map.h5's); the server under load and attack (1,000 concurrent requests and 200 malformed or
hostile ones: path traversal, huge bodies, bad JSON, unknown runs, bad methods), all answered in
bounded time with 4xx and a message, nothing outside the runs read or written; 50 slow clients
(slowloris) hold up no other request and are closed; the program links no TLS library; a zoom asked
for through the page runs, appears as a layer, and its directory's scene, run again with
arnoldweb run, gives the same digests; a cancelled zoom leaves no directory; a refused one
changes nothing; Ctrl-C stops the server with a zoom running, checkpointed for arnoldweb resume;
a scene given to serve is run first."""
import concurrent.futures as cf
import glob
import http.client
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
import support as S  # noqa: E402
from support import np, healpy  # noqa: E402

args, check = S.start()
run_a = S.small_run(args, os.path.join(args.work, "runs", "a"))
secret = os.path.join(args.work, "secret.txt")
open(secret, "w").write("not for the server")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start(*words, env=None):
    port = free_port()
    p = subprocess.Popen([args.cli, "serve", *words, "--port", str(port), "--device", "cpu"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=env)
    t0 = time.time()
    while time.time() - t0 < 120:
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.2).close()
            return p, port
        except OSError:
            if p.poll() is not None:
                raise AssertionError(f"serve exited {p.returncode}: {p.stderr.read()}")
            time.sleep(0.1)
    raise AssertionError("serve did not listen in 120 s")


def request(port, method, path, body=None, headers=None, timeout=30):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    try:
        c.request(method, path, body=body, headers=headers or {})
        r = c.getresponse()
        return r.status, r.read()
    finally:
        c.close()


def stop(p, sig=signal.SIGINT, timeout=120):
    p.send_signal(sig)
    out, err = p.communicate(timeout=timeout)
    return p.returncode, out, err


def tree(root):
    """Every file under root with its size and modification time."""
    out = {}
    for d, _, files in os.walk(root):
        for f in files:
            st = os.stat(os.path.join(d, f))
            out[os.path.join(d, f)] = (st.st_size, st.st_mtime_ns)
    return out


def wait_zoom(port, zid, timeout=300):
    t0 = time.time()
    while time.time() - t0 < timeout:
        s = json.loads(request(port, "GET", f"/api/zooms/{zid}")[1])
        if s["state"] not in ("queued", "running"):
            return s
        time.sleep(0.2)
    raise AssertionError(f"zoom {zid} did not finish in {timeout} s")


# the server is plain HTTP on Boost.Beast: the program links no TLS or crypto library itself
# (a library's own dependencies, libhdf5's, are not the server's)
if shutil.which("readelf"):
    elf = subprocess.run(["readelf", "-d", args.cli], capture_output=True, text=True, check=True).stdout
    needed = re.findall(r"\(NEEDED\)\s+Shared library: \[([^]]+)\]", elf)
    check(needed and not [n for n in needed if n.startswith(("libssl", "libcrypto", "libcurl", "libcpp-httplib", "libgnutls"))],
          f"arnoldweb links no TLS or HTTP client library: {needed}")

zooms = os.path.join(args.work, "zooms")
p, port = start(run_a, "--zooms", zooms, "--max-trajectories", "200000")
try:
    # ---------------------------------------------------------------- the page over HTTP
    counts = S.map_of(run_a)
    nside = healpy.npix2nside(counts.size)
    d = S.browser()
    try:
        S.open_page(d, f"http://127.0.0.1:{port}/#circles=1")
        errors = S.console_errors(d)
        check(not errors, f"no console error from serve: {errors}")
        left, top, w, h = S.canvas_box(d)
        rng = np.random.default_rng(3)
        for _ in range(20):
            x, y = int(rng.integers(int(left) + 1, int(left + w) - 1)), int(rng.integers(int(top) + 1, int(top + h) - 1))
            v = S.direction_at("ortho", 45, 30, 1, w, h, np.floor(x - left) + 0.5, np.floor(y - top) + 0.5)
            ro = S.hover(d, x, y)
            if v is not None:
                pix = int(healpy.vec2pix(nside, *v))
                check(ro["value"] == str(int(counts[pix])), f"served page at ({x}, {y}): {ro} vs pixel {pix} = {counts[pix]}")
        d.save_screenshot(os.path.join(args.artifacts, "serve.png"))
        print("served page: 20 points agree with map.h5", flush=True)

        # ------------------------------------------------------------ a zoom through the page
        d.execute_script("AW.zoom.show({kind: 'cap', center: [45, 8], radius: 4}); document.getElementById('zoom-n').value = 20000;")
        d.find_element("id", "zoom-run").click()
        t0 = time.time()
        while d.execute_script("return document.body.dataset.zoom") is None:
            check(time.time() - t0 < 300, "the zoom's layer appears within 300 s") or sys.exit(1)
            errors = d.execute_script("return document.getElementById('errors').textContent")
            check(not errors, f"no error in the page while zooming: {errors}") or sys.exit(1)
            time.sleep(0.3)
        print(f"click to layer: {time.time() - t0:.1f} s for 20000 trajectories")
        zid = d.execute_script("return document.body.dataset.zoom")
        S.set_view(d, lon=45, lat=8, zoom=6)
        d.save_screenshot(os.path.join(args.artifacts, "serve_zoom.png"))
        # a cap selected by dragging on the map: its centre where the drag starts (after the zoom: a
        # click right after such a drag missed the run button in chromedriver)
        d.find_element("id", "select-region").click()
        x0, y0 = int(left + w / 2 + 20), int(top + h / 2 + 40)
        b = S.ActionBuilder(d, duration=0)
        b.pointer_action.move_to_location(x0, y0).pointer_down().move_to_location(x0 + 30, y0).pointer_up()
        b.perform()
        text = d.execute_script("return document.getElementById('region-text').textContent")
        v0 = S.direction_at("ortho", 45, 8, 6, w, h, np.floor(x0 - left) + 0.5, np.floor(y0 - top) + 0.5)
        lon0, lat0 = np.degrees(np.arctan2(v0[1], v0[0])) % 360, np.degrees(np.arcsin(v0[2]))
        m = re.search(r"cap at lon (\S+)°, lat (\S+)°, radius (\S+)°", text)
        check(m and abs(float(m.group(1)) - lon0) < 1e-2 and abs(float(m.group(2)) - lat0) < 1e-2 and
              0.01 < float(m.group(3)) < 5, f"dragging selects a cap centred where it starts ({lon0:.3f}, {lat0:.3f}): {text}")
        print("a cap selected by dragging:", text, flush=True)
        errors = S.console_errors(d)
        check(not errors, f"no console error after the zoom: {errors}")
    finally:
        d.quit()
    st = json.loads(request(port, "GET", f"/api/zooms/{zid}")[1])
    zdir = st["dir"]
    summary = json.load(open(os.path.join(zdir, "summary.json")))
    check(summary["scene"]["ensemble"]["initial"] == "cap" and summary["trajectories"] == 20000,
          f"the zoom is a cap of 20000 trajectories: {summary['scene']['ensemble']}")
    src = json.load(open(os.path.join(run_a, "summary.json")))["scene"]
    for key in ("model", "integrator"):
        check(summary["scene"][key] == src[key], f"the zoom keeps the run's [{key}]")
    check(summary["scene"]["run"]["average"] == src["run"]["average"], "the zoom keeps the averaging window")
    scene_file = os.path.join(args.work, "zoom_scene.toml")
    open(scene_file, "w").write(summary["scene_toml"])
    again = os.path.join(args.work, "zoom_again")
    S.arnoldweb(args, "run", scene_file, "--device", "cpu", "-q", "--out", again)
    digests = json.load(open(os.path.join(again, "summary.json")))["digests"]
    check(digests == summary["digests"], f"arnoldweb run of the zoom's scene gives its digests: {digests} vs {summary['digests']}")

    # ---------------------------------------------------------------- refused and cancelled zooms
    before = sorted(os.listdir(zooms))
    for body, want in ((b'{"source": "r0", "region": {"kind": "cap", "center": [0, 0], "radius": 5}, "trajectories": 300000}', 400),
                       (b'{"source": "r0", "region": {"kind": "cap", "center": [0, 0], "radius": 500}, "trajectories": 1000}', 400),
                       (b'{"source": "r0", "region": {"kind": "ring"}, "trajectories": 1000}', 400),
                       (b'{"source": "r9", "region": {"kind": "cap", "center": [0, 0], "radius": 5}, "trajectories": 1000}', 404),
                       (b'{"source": "../a", "region": {}, "trajectories": 1}', 404)):
        status, text = request(port, "POST", "/api/zooms", body, {"Content-Type": "application/json"})
        check(status == want and b"error" in text, f"refused zoom {body[:60]}: {status} {text[:200]}")
    check(sorted(os.listdir(zooms)) == before, "a refused zoom makes no directory")
    status, text = request(port, "POST", "/api/zooms",
                           b'{"source": "r0", "region": {"kind": "box", "lon": [40, 50], "lat": [0, 10]}, "trajectories": 200000}')
    check(status == 202, f"a zoom of 200000 is queued: {status} {text}")
    z = json.loads(text)
    t0 = time.time()
    while json.loads(request(port, "GET", f"/api/zooms/{z['id']}")[1])["state"] == "queued" and time.time() - t0 < 60:
        time.sleep(0.1)
    status, text = request(port, "POST", f"/api/zooms/{z['id']}/cancel")
    check(status == 202, f"cancel: {status} {text}")
    s = wait_zoom(port, z["id"])
    check(s["state"] == "cancelled", f"the zoom is cancelled: {s}")
    time.sleep(0.5)
    left = [n for n in os.listdir(zooms) if n.startswith(os.path.basename(z["dir"]))]
    check(not left, f"a cancelled zoom leaves no directory: {left}")

    # ---------------------------------------------------------------- load and attack
    outside = tree(os.path.join(args.work))
    t0 = time.time()
    paths = ["/", "/app.js", "/api/runs", "/api/runs/r0", "/api/runs/r0/map", "/api/zooms", "/api/server", "/explorer.css"]
    with cf.ThreadPoolExecutor(max_workers=100) as pool:
        answers = list(pool.map(lambda i: request(port, "GET", paths[i % len(paths)])[0], range(1000)))
    took = time.time() - t0
    check(answers.count(200) == 1000, f"1000 concurrent requests all answered 200 ({answers.count(200)}) in {took:.1f} s")
    check(took < 120, f"... within 120 s ({took:.1f} s)")

    def raw(data, timeout=20):
        """Sends bytes as they are; the status code of the answer (0: none)."""
        with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
            s.sendall(data)
            got = b""
            try:
                while b"\r\n" not in got:
                    chunk = s.recv(4096)
                    if not chunk:
                        break
                    got += chunk
            except socket.timeout:
                return 0, got
            parts = got.split(b" ", 2)
            return (int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else 0), got

    hostile = []
    for target in ("/../secret.txt", "/..%2fsecret.txt", "/%2e%2e/%2e%2e/secret.txt", "/api/runs/../../secret.txt",
                   "/api/runs/r0/../../../secret.txt", "/etc/passwd", "/api/runs/r0%2f..%2f..", "//etc/passwd",
                   "/api/runs/" + secret, "/api/runs/x" + "9" * 30, "/" + "a" * 9000, "/api/runs/r99", "/api/zooms/z999",
                   "/api/compare/r0/r7", "/api/runs/r0/fields/../../secret.txt", "/app.js/../../secret.txt",
                   "/api/runs/R0", "/api/runs/r0/map%00", "/index.html%00.js", "/.git/config"):
        hostile.append(("GET", target, None))
    for body in (b"{", b"[]", b"null", b'{"source": 5}', b'{"source": "r0"}', b'{"source": "r0", "region": "cap"}',
                 b'{"source": "r0", "region": {"kind": "cap", "center": [0], "radius": 1}, "trajectories": 10}',
                 b'{"source": "r0", "region": {"kind": "cap", "center": [0, 0], "radius": 1}, "trajectories": -1}',
                 b'{"source": "r0", "region": {"kind": "cap", "center": [0, 0], "radius": 1}, "trajectories": 1.5}',
                 b'{"source": "r0", "region": {"kind": "cap", "center": ["a", 0], "radius": 1}, "trajectories": 10}',
                 b'{"source": "r0", "region": {"kind": "box", "lon": [0, 1e999], "lat": [0, 1]}, "trajectories": 10}',
                 b"\xff\xfe\x00garbage"):
        hostile.append(("POST", "/api/zooms", body))
    hostile.append(("POST", "/api/zooms", b"x" * (1 << 20)))  # a huge body
    hostile.append(("POST", "/api/zooms/z999/cancel", None))
    hostile.append(("DELETE", "/api/runs/r0", None))
    hostile.append(("PUT", "/app.js", b"overwritten"))
    hostile.append(("POST", "/app.js", b"x"))
    hostile.append(("GET", "/api/runs?dir=" + secret, None))
    hostile.append(("TRACE", "/", None))
    cases = [hostile[i % len(hostile)] for i in range(190)]
    t0 = time.time()

    def attack(case):
        method, target, body = case
        try:
            status, text = request(port, method, target, body, {"Content-Type": "application/json"})
        except Exception as e:  # the server may close a connection it refuses (a huge body)
            return method, target, -1, str(e).encode()
        return method, target, status, text

    with cf.ThreadPoolExecutor(max_workers=50) as pool:
        results = list(pool.map(attack, cases))
    # malformed HTTP itself
    for data in (b"GARBAGE\r\n\r\n", b"GET /" + b"a" * 20000 + b" HTTP/1.1\r\n\r\n",
                 b"GET / HTTP/1.1\r\nHost: x\r\n" + b"X-Big: " + b"y" * 20000 + b"\r\n\r\n",
                 b"POST /api/zooms HTTP/1.1\r\nHost: x\r\nContent-Length: 99999999999\r\n\r\n{",
                 b"POST /api/zooms HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\nzz\r\n",
                 b"GET /../secret.txt HTTP/1.1\r\nHost: x\r\n\r\n",
                 b"GET /api/runs/r0/../../secret.txt HTTP/1.1\r\nHost: x\r\n\r\n",
                 b"\x00\x01\x02\x03\r\n\r\n", b"GET / HTTP/9.9\r\n\r\n", b"GET\r\n\r\n"):
        status, text = raw(data)
        results.append(("RAW", data[:40], status, text))
    took = time.time() - t0
    check(len(results) == 200, f"200 hostile requests ({len(results)})")
    for method, target, status, text in results:
        ok = 400 <= status < 500 or (status == -1 and method == "POST") or (method == "RAW" and status in (0, 400, 404, 413, 414, 431))
        check(ok, f"{method} {target!r:.80}: answered {status} {text[:120]!r}")
        check(b"not for the server" not in text, f"{method} {target!r:.80} got the secret file")
    check(took < 120, f"the hostile requests are answered within 120 s ({took:.1f} s)")
    after = tree(os.path.join(args.work))
    check({k: v for k, v in after.items() if k in outside} == outside and set(after) == set(outside),
          f"nothing outside the zooms was written: {set(after) ^ set(outside)}")
    status, text = request(port, "GET", "/api/runs")
    check(status == 200 and len(json.loads(text)["runs"]) == 1, "the server still serves after all that")
    status, text = request(port, "HEAD", "/api/runs/r0/map")
    check(status == 200 and text == b"", f"HEAD is answered without the body: {status} {len(text)} bytes")

    # ---------------------------------------------------------------- slow clients (slowloris)
    # 50 connections that each send a header line a second hold nothing up: other requests are
    # answered meanwhile, and the server closes each slow one when its time for a request is up
    slow = []
    for _ in range(50):
        s = socket.create_connection(("127.0.0.1", port), timeout=10)
        s.sendall(b"GET / HTTP/1.1\r\nHost: x\r\n")
        slow.append(s)
    closed_after = {}

    def trickle(i):
        t0 = time.time()
        try:
            while time.time() - t0 < 30:
                slow[i].sendall(b"X-Slow: 1\r\n")
                slow[i].settimeout(1.0)
                try:
                    if slow[i].recv(4096) == b"":
                        break
                except socket.timeout:
                    pass
        except OSError:  # reset by the server
            pass
        closed_after[i] = time.time() - t0
        slow[i].close()

    with cf.ThreadPoolExecutor(max_workers=50) as pool:
        waiting = [pool.submit(trickle, i) for i in range(50)]
        worst = 0.0
        for _ in range(20):
            t0 = time.time()
            status, _ = request(port, "GET", "/api/runs", timeout=20)
            worst = max(worst, time.time() - t0)
            check(status == 200, f"a request among slow clients is answered: {status}")
            time.sleep(0.2)
        cf.wait(waiting)
    check(worst < 5, f"requests among 50 slow clients are answered at once (slowest {worst:.2f} s)")
    check(max(closed_after.values()) < 15, f"the slow clients are closed within 15 s ({max(closed_after.values()):.1f} s)")
    print(f"slowloris: 50 slow clients closed after {min(closed_after.values()):.1f}-{max(closed_after.values()):.1f} s; "
          f"other requests meanwhile at most {worst:.3f} s", flush=True)

    # ---------------------------------------------------------------- Ctrl-C with a zoom running
    status, text = request(port, "POST", "/api/zooms",
                           b'{"source": "r0", "region": {"kind": "cap", "center": [45, 8], "radius": 3}, "trajectories": 200000}')
    z = json.loads(text)
    t0 = time.time()
    while json.loads(request(port, "GET", f"/api/zooms/{z['id']}")[1])["done"] == 0 and time.time() - t0 < 120:
        time.sleep(0.1)
    rc, out, err = stop(p)
    check("checkpoint written to" in err and "arnoldweb resume" in err, f"Ctrl-C checkpoints the running zoom: rc {rc}: {err}")
    check(not os.path.exists(z["dir"]), "and leaves no half-written zoom directory")
    parts = glob.glob(z["dir"] + ".partial-*")
    check(len(parts) == 1, f"its checkpoint waits beside it: {parts}")
    r = S.arnoldweb(args, "resume", z["dir"], "-q", check=False)
    check(r.returncode == 0 and os.path.isfile(os.path.join(z["dir"], "summary.json")),
          f"arnoldweb resume finishes the zoom: {r.returncode} {r.stderr}")
finally:
    if p.poll() is None:
        p.kill()

# ---------------------------------------------------------------- a scene given to serve
scene_out = os.path.join(args.work, "scene_run")
p, port = start(os.path.join(args.source, "scenes", "default.toml"), "--set", "ensemble.trajectories=20000",
                "--set", f"output.dir=\"{scene_out}\"")
try:
    d = S.browser()
    try:
        d.get(f"http://127.0.0.1:{port}/")
        t0 = time.time()
        while time.time() - t0 < 300:
            shown = d.execute_script("const e = document.getElementById('errors'); return e ? e.textContent : ''")
            if not check(not shown, f"the page waits for the scene's run without an error: {shown}"):
                break
            if d.execute_script("return document.body && document.body.dataset.ready") == "1" and \
               d.execute_script("return AW.app.panels.length") == 1:
                break
            time.sleep(0.3)
        check(d.execute_script("return AW.app.panels.length") == 1, "the scene's map appears once its run is done")
        check(os.path.isfile(os.path.join(scene_out, "summary.json")), "the scene's run wrote its directory")
        errors = S.console_errors(d)
        check(not errors, f"no console error: {errors}")
    finally:
        d.quit()
finally:
    stop(p)
# a scene whose output directory exists is refused before the server starts (exit 3)
r = subprocess.run([args.cli, "serve", os.path.join(args.source, "scenes", "default.toml"), "--set",
                    f"output.dir=\"{scene_out}\"", "--port", "0"], capture_output=True, text=True, timeout=120)
check(r.returncode == 3 and scene_out in r.stderr, f"serve of a scene whose output exists: exit {r.returncode}: {r.stderr}")
check.finish("explorer.serve")
