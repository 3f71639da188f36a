"""arnoldweb view in a real browser (headless Chromium, WebGL2 in software), from file://:
the page loads with no console error; at 100 random screen points of each projection the value
it reports is map.h5's value at the HEALPix pixel (healpy) of the direction this test computes
for that point; hovering the primary resonance (1,-1,0) names it; the overlay's circles lie on
m.P = 0; a click picks a circle; the view's state lives in the URL; PNG and SVG come out; two
runs are shown side by side with their difference and chi-square test. Screenshots of each view
go to the artifacts directory (docs/viewer.md uses them)."""
import base64
import os
import re
import sys

sys.path.insert(0, os.path.dirname(__file__))
import support as S  # noqa: E402
from support import np, healpy  # noqa: E402

args, check = S.start()

run_a = S.small_run(args, os.path.join(args.work, "a"))
run_b = S.small_run(args, os.path.join(args.work, "b"), extra=("--set", "ensemble.seed=2"))
counts = S.map_of(run_a)
nside = healpy.npix2nside(counts.size)

r = S.arnoldweb(args, "view", run_a)
page = os.path.join(args.work, "a.view", "view.html")
check(os.path.isfile(page), f"arnoldweb view wrote {page}")
check("file://" in r.stdout, "arnoldweb view says how to open it")
# nothing was written into the run's directory (its summary.json still lists all it holds)
check(not os.path.exists(os.path.join(run_a, "view.html")), "the run's directory is left as it was")
# a directory that view did not write is refused
os.makedirs(os.path.join(args.work, "mine"))
open(os.path.join(args.work, "mine", "notes.txt"), "w").write("mine")
bad = S.arnoldweb(args, "view", run_a, "--to", os.path.join(args.work, "mine"), check=False)
check(bad.returncode == 3 and "notes.txt" in bad.stderr, f"view refuses a directory of the user's: {bad.returncode} {bad.stderr}")
check(open(os.path.join(args.work, "mine", "notes.txt")).read() == "mine", "and leaves it alone")
bad = S.arnoldweb(args, "view", os.path.join(args.work, "nothing"), check=False)
check(bad.returncode == 2 and "summary.json" in bad.stderr, f"view of no run: exit 2 naming summary.json: {bad.stderr}")

d = S.browser()
try:
    S.open_page(d, "file://" + page + "#circles=0")
    errors = S.console_errors(d)
    check(not errors, f"no console error on load: {errors}")

    # ---------------------------------------------------------------- values under the cursor
    rng = np.random.default_rng(7)
    for proj, lon, lat, zoom in (("ortho", 45, 30, 1.0), ("mollweide", 20, 0, 1.0), ("gnomonic", 45, 10, 2.5)):
        S.set_view(d, proj=proj, lon=lon, lat=lat, zoom=zoom, circles=1, k=2)
        d.save_screenshot(os.path.join(args.artifacts, f"view_{proj}.png"))
        left, top, w, h = S.canvas_box(d)
        tested = outside = 0
        points = [(int(rng.integers(int(left) + 1, int(left + w) - 1)), int(rng.integers(int(top) + 1, int(top + h) - 1)))
                  for _ in range(400)]
        for (x, y), ro in zip(points, S.hover_many(d, points)):
            if tested == 100:
                break
            check(ro["element"] == "map", f"{proj} ({x}, {y}): the pointer is over the map, not {ro['element']}")
            v = S.direction_at(proj, lon, lat, zoom, w, h, np.floor(x - left) + 0.5, np.floor(y - top) + 0.5)
            if v is None:
                outside += 1
                check(ro["value"] == "–", f"{proj} ({x}, {y}) is off the projection but the page shows {ro}")
                continue
            tested += 1
            pix = int(healpy.vec2pix(nside, *v))
            theta, phi = np.degrees(healpy.vec2ang(v))
            want = str(int(counts[pix]))
            check(ro["pix"] == str(pix) and ro["value"] == want,
                  f"{proj} ({x}, {y}): page says pixel {ro['pix']} value {ro['value']}, map.h5 pixel {pix} holds {want}")
            check(abs(float(ro["theta"]) - theta[0]) < 2e-4 and abs((float(ro["phi"]) - phi[0] + 180) % 360 - 180) < 2e-4 or
                  abs(theta[0]) < 1e-3, f"{proj} ({x}, {y}): theta, phi {ro['theta']}, {ro['phi']} against {theta}, {phi}")
        check(tested == 100, f"{proj}: 100 points on the projection ({tested})")
        print(f"{proj}: 100 points agree with map.h5 ({outside} off the projection)")

    # ---------------------------------------------------------------- the primary resonance
    S.set_view(d, proj="ortho", lon=45, lat=30, zoom=1, circles=0, k=2)
    left, top, w, h = S.canvas_box(d)
    on_line = np.array([np.cos(np.radians(8)) * np.sqrt(0.5), np.cos(np.radians(8)) * np.sqrt(0.5), np.sin(np.radians(8))])
    sx, sy = S.screen_of("ortho", 45, 30, 1, w, h, on_line)
    ro = S.hover(d, left + sx, top + sy)
    check(ro["res"] and ro["res"][0] == "(1,-1,0)", f"hovering the line x = y names (1,-1,0) first: {ro['res']}")
    S.click(d, left + sx, top + sy)
    state = d.execute_script("return [AW.app.state.picked, location.hash]")
    check("(1,-1,0)" in state[0] and "pick=" in state[1], f"a click picks (1,-1,0), kept in the URL: {state}")

    # ---------------------------------------------------------------- the overlay's circles
    S.set_view(d, circles=1, k=2)
    svg = d.execute_script("return AW.app.overlaySVG()")
    groups = re.findall(r'<g class="resonance" data-m="([-0-9,]+)" data-order="(\d)" stroke="([#0-9a-z]+)"[^>]*>(.*?)</g>', svg, re.S)
    want = {S.label(m) for m in S.resonances(2)}
    got = {"(" + m + ")" for m, _, _, _ in groups}
    check(got == want, f"the overlay draws every circle of order <= 2: missing {want - got}, extra {got - want}")
    worst = 0.0
    for m, order, stroke, body in groups:
        mv = np.array([int(t) for t in m.split(",")], dtype=float)
        check(int(order) == int(max(abs(mv))), f"circle {m}: order {order}")
        for pts in re.findall(r'points="([^"]+)"', body):
            for p in pts.split():
                px, py = (float(t) for t in p.split(","))
                v = S.direction_at("ortho", 45, 30, 1, w, h, px, py)
                if v is not None and np.hypot(px - w / 2, py - h / 2) < 0.95 * 0.45 * min(w, h):  # not at the limb
                    worst = max(worst, abs(mv @ v) / np.linalg.norm(mv))
    check(worst < 1e-4, f"every overlay point lies on its circle m.P = 0 (worst |m.P|/|m| {worst:.2e})")
    check(any(m == "1,-1,0" and s == "#3c3" for m, _, s, _ in groups), "the picked circle is drawn as picked")
    check("(1,-1,0) order 1" in svg, "the picked circle is labelled with its order")
    open(os.path.join(args.artifacts, "circles.svg"), "w").write(svg)
    d.save_screenshot(os.path.join(args.artifacts, "view_circles.png"))

    # ---------------------------------------------------------------- state in the URL, PNG
    S.set_view(d, proj="mollweide", lon=10, lat=0, zoom=1.5, scale="histeq", cmap="grey", k=3)
    got = d.execute_script("return [document.getElementById('proj').value, document.getElementById('scale').value, "
                           "document.getElementById('cmap').value, document.getElementById('k').value]")
    check(got == ["mollweide", "histeq", "grey", "3"], f"the URL's state sets the controls: {got}")
    url = d.current_url
    d.get("about:blank")
    S.open_page(d, url)
    again = d.execute_script("const s = AW.app.state; return [s.proj, s.lon, s.zoom, s.scale, s.picked]")
    check(again == ["mollweide", 10, 1.5, "histeq", ["(1,-1,0)"]], f"a reopened link shows the same view: {again}")
    png = d.execute_script("return AW.app.viewPNG()")
    raw = base64.b64decode(png.split(",", 1)[1])
    check(raw[:8] == b"\x89PNG\r\n\x1a\n" and len(raw) > 10000, "the PNG button's image is a PNG")
    open(os.path.join(args.artifacts, "view_saved.png"), "wb").write(raw)
    errors = S.console_errors(d)
    check(not errors, f"no console error after all that: {errors}")
finally:
    d.quit()

# ---------------------------------------------------------------- two runs: side by side, A - B
S.arnoldweb(args, "view", run_a, run_b, "--to", os.path.join(args.work, "ab"))
compare = S.arnoldweb(args, "compare", run_a, run_b, check=False).stdout
chi2 = float(re.search(r"^chi2\s+(\S+)", compare, re.M).group(1))
d = S.browser(1500, 700)
try:
    S.open_page(d, "file://" + os.path.join(args.work, "ab", "view.html"))
    n = d.execute_script("return AW.app.panels.length")
    check(n == 3, f"two runs of one resolution: A, B and A - B ({n} panels)")
    text = d.execute_script("return document.getElementById('compare').textContent")
    m = re.search(r"chi2 (\S+),", text)
    check(m and abs(float(m.group(1)) - chi2) <= 1e-4 * chi2, f"the page's chi2 is arnoldweb compare's {chi2}: {text}")
    b = S.map_of(run_b)
    A, B = counts.sum(), b.sum()
    left, top, w, h = S.canvas_box(d, 2)
    ro = S.hover(d, left + w / 2, top + h / 2)
    pix = int(ro["pix"])
    want = (np.sqrt(B / A) * counts[pix] - np.sqrt(A / B) * b[pix]) / np.sqrt(counts[pix] + b[pix]) if counts[pix] + b[pix] else 0
    vals = d.execute_script("return document.getElementById('ro-values').textContent")
    check(f"A: {counts[pix]}" in vals and f"B: {b[pix]}" in vals, f"the readout gives both runs' counts: {vals}")
    check(abs(float(ro["value"]) - want) < 1e-4 * max(1, abs(want)), f"A - B is the signed chi-square term: {ro['value']} vs {want}")
    errors = S.console_errors(d)
    check(not errors, f"no console error: {errors}")
    d.save_screenshot(os.path.join(args.artifacts, "view_compare.png"))
finally:
    d.quit()

# ---------------------------------------------------------------- a grid run's outputs, linked
grid = os.path.join(args.work, "grid")
S.arnoldweb(args, "run", os.path.join(args.source, "scenes", "fgl_frequency_map.toml"), "--device", "cpu", "-q",
            "--out", grid, "--set", "ensemble.grid.resolution=[16,12]", "--set", "observe.frequencies.samples=64",
            "--set", "run.average=20.48", "--set", "run.duration=20.48", "--set", "observe.velocity_map={nside=16}")
S.arnoldweb(args, "view", grid)
with S.h5py.File(os.path.join(grid, "indicators.h5"), "r") as f:
    fli = f["fli"][()]
with S.h5py.File(os.path.join(grid, "frequencies.h5"), "r") as f:
    dindex = f["diffusion_index"][()]
d = S.browser(1200, 900)
try:
    S.open_page(d, "file://" + os.path.join(args.work, "grid.view", "view.html") + "#model=1&circles=1")
    names = d.execute_script("return [...document.querySelectorAll('canvas.field')].map((c) => c.dataset.field)")
    check(names == ["diffusion_index", "fli", "frequency map"], f"the grid run's outputs are shown: {names}")
    check(d.execute_script("return !document.getElementById('model-label').hidden"), "the model's resonances can be chosen (fgl)")
    svg = d.execute_script("return AW.app.overlaySVG()")
    drawn = set(re.findall(r'data-m="([-0-9,]+)"', svg))
    # fgl: its 13 unit harmonics (docs/models.md), as map_resonances.png draws them
    check(len(drawn) == 13 and all(max(abs(int(t)) for t in m.split(",")) == 1 for m in drawn),
          f"with the model's resonances the overlay draws the model's circles, not all 49: {sorted(drawn)}")
    box = d.execute_script("""const c = document.querySelector('canvas.field[data-field="fli"]');
                               c.scrollIntoView({block: "center"}); const r = c.getBoundingClientRect();
                               return [r.left, r.top, r.width, r.height, c.width, c.height]""")
    n2, n1 = fli.shape
    for col, row in ((3, 4), (10, 0), (15, 11)):
        # the centre of cell (col, row); rows go up from the bottom, as the grid's second axis
        x = box[0] + (col + 0.5) * box[2] / n1
        y = box[1] + box[3] - (row + 0.5) * box[3] / n2
        b = S.ActionBuilder(d, duration=0)
        b.pointer_action.move_to_location(int(x), int(y))
        b.perform()
        text = d.execute_script("return document.getElementById('field-readout').textContent")
        i = row * n1 + col
        m = re.search(r"trajectory (\d+) · diffusion_index: (\S+) · fli: (\S+)", text)
        check(m and int(m.group(1)) == i, f"cell ({col}, {row}) is trajectory {i}: {text}")
        if m:
            check(abs(float(m.group(3)) - fli.flat[i]) < 1e-5 * abs(fli.flat[i]), f"its FLI is indicators.h5's {fli.flat[i]}: {text}")
            check(abs(float(m.group(2)) - dindex.flat[i]) < 1e-5 * abs(dindex.flat[i]),
                  f"and the linked diffusion index frequencies.h5's {dindex.flat[i]}: {text}")
    errors = S.console_errors(d)
    check(not errors, f"no console error: {errors}")
    d.save_screenshot(os.path.join(args.artifacts, "view_grid.png"))
finally:
    d.quit()
check.finish("explorer.view")
