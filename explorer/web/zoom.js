// arnoldweb explorer: zooms on demand, from a page that arnoldweb serve gave: select a cap or a
// box on the map, choose a number of trajectories (up to the server's cap) and the server runs
// the zoom's scene (same model, energy, method, step and averaging, ensemble.initial "cap" or
// "box") on its device, one at a time; progress is polled, a run can be cancelled, a failed
// one shows its error, and a finished one is drawn as a layer over its region.
"use strict";
var AW = window.AW || (window.AW = {});

// whether a unit direction lies in a region {kind: "cap", center, radius} | {kind: "box", lon, lat}
AW.zoomRegionHas = function (r, d) {
  if (r.kind === "cap") return AW.geo.dot(d, AW.geo.direction(r.center[0], r.center[1])) >= Math.cos(r.radius * AW.geo.D2R);
  const [lon, lat] = AW.geo.lonlat(d);
  const a = ((r.lon[0] % 360) + 360) % 360;
  const l = lon < a ? lon + 360 : lon;
  return l <= a + (r.lon[1] - r.lon[0]) && lat >= r.lat[0] && lat <= r.lat[1];
};

AW.zoom = (function () {
  const $ = (id) => document.getElementById(id);
  let region = null, running = null, server = null;

  function describe(r) {
    const f = (v) => (+v.toFixed(3)).toString();
    return r.kind === "cap" ? `cap at lon ${f(r.center[0])}°, lat ${f(r.center[1])}°, radius ${f(r.radius)}°`
                            : `box lon ${f(r.lon[0])}..${f(r.lon[1])}°, lat ${f(r.lat[0])}..${f(r.lat[1])}°`;
  }
  function regionFrom(kind, d0, d1) {
    if (kind === "cap") {
      const ang = Math.acos(Math.max(-1, Math.min(1, AW.geo.dot(AW.geo.unit(d0), AW.geo.unit(d1))))) / AW.geo.D2R;
      return { kind, center: AW.geo.lonlat(d0), radius: Math.max(0.05, Math.min(180, ang)) };
    }
    const [a0, b0] = AW.geo.lonlat(d0), [a1, b1] = AW.geo.lonlat(d1);
    let lo = Math.min(a0, a1), hi = Math.max(a0, a1);
    if (hi - lo > 180) [lo, hi] = [hi, lo + 360];  // the shorter way round
    return { kind, lon: [lo, Math.max(hi, lo + 0.05)], lat: [Math.min(b0, b1), Math.max(Math.max(b0, b1), Math.min(b0, b1) + 0.05)] };
  }
  function show(r) {
    region = r;
    AW.app.regions.length = 0;
    if (r) AW.app.regions.push(r);
    $("region-text").textContent = r ? describe(r) : "no region selected";
    $("zoom-run").disabled = !r || !!running;
    AW.app.redraw();
  }
  async function poll(id) {
    let s;
    try { s = await AW.data.json("api/zooms/" + encodeURIComponent(id)); } catch (e) { AW.app.error(e.message); return; }
    $("zoom-progress").value = s.total ? s.done / s.total : 0;
    $("zoom-status").textContent = `${s.state}: ${s.done} of ${s.total} trajectories` + (s.seconds ? `, ${s.seconds.toFixed(1)} s` : "");
    if (s.state === "queued" || s.state === "running") { setTimeout(() => poll(id), 300); return; }
    running = null;
    $("zoom-cancel").disabled = true;
    $("zoom-run").disabled = !region;
    list();
    if (s.state === "failed") { AW.app.error("zoom " + id + " failed: " + s.error); return; }
    if (s.state === "done") {
      const r = await AW.data.loadOne(s.run);
      AW.app.setLayer(0, { values: r.map, nside: r.meta.map.nside, region: s.region, id: s.run });
      AW.app.state.layer = s.run;
      AW.app.changed();
      document.body.dataset.zoom = s.run;
    }
  }
  async function list() {
    const { zooms } = await AW.data.json("api/zooms");
    const ul = $("zoom-runs");
    ul.innerHTML = "";
    for (const z of zooms) {
      const li = document.createElement("li");
      li.className = z.state;
      li.textContent = `${z.id}: ${describe(z.region)}, ${z.total} trajectories: ${z.state}` +
        (z.error ? ": " + z.error : "") + (z.dir ? " -> " + z.dir : "");
      if (z.state === "done") {
        li.style.cursor = "pointer";
        li.title = "show it over the map";
        li.addEventListener("click", async () => {
          const r = await AW.data.loadOne(z.run);
          AW.app.setLayer(0, { values: r.map, nside: r.meta.map.nside, region: z.region, id: z.run });
          AW.app.state.layer = z.run;
          AW.app.changed();
        });
      }
      ul.appendChild(li);
    }
  }
  // a map finer for a smaller region: about 50 pixels across it, a power of two from the run's
  // own nside up to 256 (a HEALPix map covers the whole sphere: 256 is 0.8 million pixels, 6 MB
  // in map.h5)
  function nsideFor(r, base) {
    const across = r.kind === "cap" ? 2 * r.radius : Math.max(r.lon[1] - r.lon[0], r.lat[1] - r.lat[0]);
    let n = base;
    while (n < 256 && 58.6 / n > across / 50) n *= 2;
    return n;
  }
  async function run() {
    const n = Math.round(+$("zoom-n").value);
    const base = AW.app.panels.length ? AW.app.panels[0].nside : 64;
    const source = AW.app.panels.length ? AW.app.panels[0].run.meta.id : null;
    try {
      const r = await AW.data.json("api/zooms", {
        method: "POST", headers: { "Content-Type": "application/json" },
        body: JSON.stringify({ source, region, trajectories: n, nside: nsideFor(region, base) }),
      });
      running = r.id;
      $("zoom-run").disabled = true;
      $("zoom-cancel").disabled = false;
      poll(r.id);
    } catch (e) {
      AW.app.error("zoom refused: " + e.message);
    }
  }
  async function cancel() {
    if (!running) return;
    try { await AW.data.json("api/zooms/" + encodeURIComponent(running) + "/cancel", { method: "POST" }); }
    catch (e) { AW.app.error(e.message); }
  }
  async function waitForScene(s) {
    // a scene given to serve: its run's progress, then the page again with its map
    $("zoom").hidden = false;
    $("zoom-status").textContent = `running the scene: ${s.done} of ${s.total} trajectories`;
    $("zoom-progress").value = s.total ? s.done / s.total : 0;
    if (s.state === "failed") { AW.app.error("the scene's run failed: " + s.error); return; }
    if (s.state === "done") { location.reload(); return; }
    setTimeout(async () => waitForScene(await AW.data.json("api/zooms/" + encodeURIComponent(s.id))), 400);
  }
  // Sets the zoom panel up; true while the server is still running the scene it was given
  async function init() {
    if (!AW.data.served()) return false;
    try { server = await AW.data.json("api/server"); } catch (e) { AW.app.error(e.message); return false; }
    if (server.scene_run && server.scene_run.state !== "done") { waitForScene(server.scene_run); return true; }
    // the scene's run ended between the page's reading of the runs and this answer: read them again
    // (once: a finished run without a map then shows the page's own message)
    if (AW.app.panels.length) sessionStorage.removeItem("aw-scene-reread");
    if (server.scene_run && !AW.app.panels.length && !sessionStorage.getItem("aw-scene-reread")) {
      sessionStorage.setItem("aw-scene-reread", "1");
      location.reload();
      return true;
    }
    if (!server.zoom || !AW.app.panels.length) return false;
    $("zoom").hidden = false;
    $("zoom-n").max = server.zoom.max_trajectories;
    $("zoom-cap").textContent = `at most ${server.zoom.max_trajectories} on ${server.zoom.device}`;
    $("select-region").addEventListener("click", () => {
      const kind = document.querySelector("input[name=region]:checked").value;
      AW.app.startRegion({ update: (d0, d1) => show(regionFrom(kind, d0, d1)), done: () => {} });
    });
    $("zoom-run").addEventListener("click", run);
    $("zoom-cancel").addEventListener("click", cancel);
    list();
    return false;
  }
  return { init, show };
})();
