// arnoldweb explorer: the page. One panel per run with a map (two runs of one resolution get a
// third: their difference), one view shared by all (projection, centre, zoom), the readout of
// the cursor's direction, the resonance circles, the colour scale and bar, the view's state in
// the URL, PNG and SVG. fields.js adds a grid run's fields, zoom.js the zooms of a server.
"use strict";
var AW = window.AW || (window.AW = {});

AW.app = (function () {
  const $ = (id) => document.getElementById(id);
  const defaults = { proj: "ortho", lon: 45, lat: 30, zoom: 1, scale: "log", cmap: "paper", lo: null, hi: null,
                     k: 2, circles: false, model: false, picked: [], layer: null };
  const state = Object.assign({}, defaults, { picked: [] });
  const panels = [];
  let runs = [], compareInfo = null, cursor = null, dirty = false, frames = 0, firstFrameMs = null;
  const regions = [];  // extra outlines: {kind, center, radius | lon, lat, colour}

  function error(text) {
    $("errors").textContent += text + "\n";
    console.warn("arnoldweb explorer: " + text);
  }
  const fmt = (v) => (Number.isInteger(v) ? String(v) : Math.abs(v) >= 1e-3 && Math.abs(v) < 1e6 ? v.toPrecision(6) : v.toExponential(5));

  // ------------------------------------------------------------ the view's state in the URL
  function readHash() {
    const p = new URLSearchParams(location.hash.slice(1));
    const num = (k, lo, hi) => {
      if (!p.has(k) || p.get(k) === "") return undefined;
      const v = Number(p.get(k));
      return Number.isFinite(v) ? Math.min(hi, Math.max(lo, v)) : undefined;
    };
    const pick = (k, allowed) => (allowed.includes(p.get(k)) ? p.get(k) : undefined);
    const set = (k, v) => { if (v !== undefined) state[k] = v; };
    set("proj", pick("proj", ["ortho", "mollweide", "gnomonic"]));
    set("lon", num("lon", -1e6, 1e6));
    set("lat", num("lat", -90, 90));
    set("zoom", num("zoom", 0.2, 1e5));
    set("scale", pick("scale", ["log", "linear", "histeq"]));
    set("cmap", pick("cmap", Object.keys(AW.colour.maps)));
    state.lo = num("lo", -1e300, 1e300) ?? null;
    state.hi = num("hi", -1e300, 1e300) ?? null;
    set("k", num("k", 1, 12));
    state.k = Math.round(state.k);
    if (p.has("circles")) state.circles = p.get("circles") === "1";
    if (p.has("model")) state.model = p.get("model") === "1";
    if (p.has("pick")) state.picked = p.get("pick").split(";").filter((s) => /^\(-?\d+,-?\d+,-?\d+\)$/.test(s));
    if (p.has("layer")) state.layer = p.get("layer") || null;
  }
  function writeHash() {
    const p = new URLSearchParams();
    p.set("proj", state.proj);
    p.set("lon", +state.lon.toFixed(4));
    p.set("lat", +state.lat.toFixed(4));
    p.set("zoom", +state.zoom.toPrecision(6));
    p.set("scale", state.scale);
    p.set("cmap", state.cmap);
    if (state.lo !== null) p.set("lo", state.lo);
    if (state.hi !== null) p.set("hi", state.hi);
    p.set("k", state.k);
    p.set("circles", state.circles ? "1" : "0");
    p.set("model", state.model ? "1" : "0");
    if (state.picked.length) p.set("pick", state.picked.join(";"));
    if (state.layer) p.set("layer", state.layer);
    history.replaceState(null, "", "#" + p.toString());
  }
  function syncControls() {
    $("proj").value = state.proj;
    $("scale").value = state.scale;
    $("cmap").value = state.cmap;
    $("lo").value = state.lo === null ? "" : state.lo;
    $("hi").value = state.hi === null ? "" : state.hi;
    $("k").value = state.k;
    $("ro-k").textContent = state.k;
    $("circles").checked = state.circles;
    $("model").checked = state.model;
  }
  function changed() {
    writeHash();
    syncControls();
    redraw();
  }

  // ------------------------------------------------------------ the resonances the page lists
  let modelMemo;
  function modelList() {
    if (modelMemo === undefined && panels.length) {
      const m = panels[0].run.meta.model;
      modelMemo = m && m.resonances ? AW.res.fromVectors(m.resonances) : null;
    }
    return modelMemo || null;
  }
  function resonanceList() {
    const model = modelList();
    return state.model && model ? model : AW.res.upTo(state.k);
  }

  // ------------------------------------------------------------ scales
  function stats(p) {
    if (p.stats) return p.stats;
    let minPos = Infinity, max = -Infinity, min = Infinity;
    for (const v of p.values) {
      if (v > 0 && v < minPos) minPos = v;
      if (v > max) max = v;
      if (v < min) min = v;
    }
    return (p.stats = { minPos: minPos === Infinity ? 1 : minPos, max: max === -Infinity ? 1 : max, min });
  }
  function scaleOf(p) {
    const s = stats(p);
    if (p.signed) {
      const a = Math.max(Math.abs(s.min), Math.abs(s.max)) || 1;
      return { signed: true, mode: "linear", lo: -a, hi: a };
    }
    const mode = state.scale;
    let lo = state.lo, hi = state.hi;
    if (lo === null) lo = mode === "log" ? s.minPos : mode === "linear" ? 0 : s.minPos;
    if (hi === null) hi = s.max;
    const sc = { mode, lo, hi };
    if (mode === "histeq") {
      if (!p.edges) p.edges = AW.colour.quantileEdges(p.values);
      sc.edges = p.edges;
    }
    return sc;
  }
  function drawColourBar() {
    const c = $("colourbar"), ctx = c.getContext("2d");
    ctx.clearRect(0, 0, c.width, c.height);
    if (!panels.length) return;
    const p = panels[0], sc = scaleOf(p), cmap = p.signed ? "diverging" : state.cmap;
    const f = AW.colour.maps[cmap], x0 = 10, x1 = c.width - 10, y0 = 4, hgt = 16;
    for (let x = x0; x < x1; ++x) {
      const col = f((x - x0) / (x1 - x0));
      ctx.fillStyle = `rgb(${col.map((v) => Math.round(255 * v)).join(",")})`;
      ctx.fillRect(x, y0, 1, hgt);
    }
    ctx.fillStyle = "#ccc";
    ctx.font = "11px system-ui, sans-serif";
    const ticks = [];
    if (sc.mode === "log" && !sc.signed && sc.lo > 0) {
      for (let e = Math.ceil(Math.log10(sc.lo)); e <= Math.floor(Math.log10(sc.hi)); ++e) ticks.push(Math.pow(10, e));
      if (!ticks.length) ticks.push(sc.lo, sc.hi);
    } else if (sc.mode === "histeq" && !sc.signed) {
      for (const q of [0, 64, 128, 192, 256]) ticks.push(sc.edges[q]);
    } else {
      for (let i = 0; i <= 4; ++i) ticks.push(sc.lo + (sc.hi - sc.lo) * i / 4);
    }
    for (const v of ticks) {
      const t = AW.colour.position(sc, v);
      if (t < 0) continue;
      const x = x0 + t * (x1 - x0);
      ctx.fillRect(x, y0 + hgt, 1, 4);
      const s = fmt(+v.toPrecision(3));
      ctx.fillText(s, Math.min(c.width - ctx.measureText(s).width, Math.max(0, x - ctx.measureText(s).width / 2)), y0 + hgt + 16);
    }
    const what = p.signed ? "signed chi-square residual (A - B)" : (p.run.meta.quantity || "counts") + " (" + { log: "log", linear: "linear", histeq: "equalised" }[state.scale] + ")";
    ctx.fillText(what, x0, c.height - 1);
  }

  // ------------------------------------------------------------ drawing
  function redraw() {
    if (!dirty) { dirty = true; requestAnimationFrame(frame); }
  }
  function layerOf(p) {
    if (!p.layer) return null;
    const s = stats(p.layer);
    const mode = state.scale === "linear" ? "linear" : "log";
    return { region: p.layer.region, scale: { mode, lo: mode === "log" ? s.minPos : 0, hi: s.max } };
  }
  function frame() {
    dirty = false;
    const list = resonanceList();
    for (const p of panels) {
      const sc = scaleOf(p);
      // the map is drawn again only when what it shows changed (not for the cursor's mark)
      const layer = layerOf(p);
      const key = JSON.stringify([state.proj, state.lon, state.lat, state.zoom, state.cmap, sc.mode, sc.lo, sc.hi,
                                  layer && [layer.region, layer.scale, p.layer.id], p.map.clientWidth, p.map.clientHeight]);
      if (key !== p.drawn) {
        p.renderer.setColours(p.signed ? "diverging" : state.cmap);
        if (sc.edges) p.renderer.setEdges(sc.edges);
        p.renderer.draw(state, sc, layer);
        p.drawn = key;
      }
      const w = p.map.clientWidth, h = p.map.clientHeight, dpr = window.devicePixelRatio || 1;
      if (p.overlay.width !== Math.round(w * dpr)) { p.overlay.width = Math.round(w * dpr); p.overlay.height = Math.round(h * dpr); }
      const ctx = p.overlay.getContext("2d");
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      const rs = regions.concat(p.layer ? [Object.assign({ colour: "rgba(255,160,40,0.9)" }, p.layer.region)] : []);
      AW.overlay.draw(ctx, state, list, rs, cursor, w, h);
    }
    drawColourBar();
    frames += 1;
    if (firstFrameMs === null && panels.length) {
      panels[0].renderer.gl.finish();
      firstFrameMs = performance.now();
    }
  }

  // ------------------------------------------------------------ the cursor
  const pos = (p, e) => { const r = p.map.getBoundingClientRect(); return [e.clientX - r.left, e.clientY - r.top]; };
  // the direction under CSS position (x, y) of a panel: the centre of the pixel there
  const dirAt = (p, x, y) => AW.geo.screenToDir(state, Math.floor(x) + 0.5, Math.floor(y) + 0.5, p.map.clientWidth, p.map.clientHeight);
  function valueOf(p, d) {
    if (p.layer && AW.zoomRegionHas && AW.zoomRegionHas(p.layer.region, d)) {
      const pix = AW.geo.vec2pix(p.layer.nside, d);
      return { pix, nside: p.layer.nside, value: p.layer.values[pix], where: "zoom" };
    }
    const pix = AW.geo.vec2pix(p.nside, d);
    return { pix, nside: p.nside, value: p.values[pix], where: "" };
  }
  function showReadout(p, d) {
    cursor = d;
    if (!d) {
      for (const id of ["ro-theta", "ro-phi", "ro-vec", "ro-pix", "ro-value"]) $(id).textContent = "–";
      $("ro-nside").textContent = "";
      $("ro-res").innerHTML = "";
      $("ro-values").textContent = "";
      redraw();
      return;
    }
    const u = AW.geo.unit(d);
    const theta = Math.acos(Math.max(-1, Math.min(1, u[2]))) / AW.geo.D2R;
    let phi = Math.atan2(u[1], u[0]) / AW.geo.D2R;
    if (phi < 0) phi += 360;
    $("ro-theta").textContent = theta.toFixed(4);
    $("ro-phi").textContent = phi.toFixed(4);
    $("ro-vec").textContent = "(" + u.map((x) => x.toFixed(4)).join(", ") + ")";
    const v = valueOf(p, u);
    $("ro-pix").textContent = v.pix;
    $("ro-nside").textContent = "(nside " + v.nside + (v.where ? ", the zoom's map" : "") + ")";
    $("ro-value").textContent = fmt(v.value);
    $("ro-values").textContent = panels.length > 1
      ? panels.map((q) => q.short + ": " + fmt(valueOf(q, u).value)).join(" · ") : "";
    const ol = $("ro-res");
    ol.innerHTML = "";
    for (const { r, d: dist } of AW.res.nearest(resonanceList(), u, 5)) {
      const li = document.createElement("li");
      li.dataset.label = r.label;
      li.textContent = r.label + " order " + r.order + ", " + (dist / AW.geo.D2R).toFixed(3) + "°";
      ol.appendChild(li);
    }
    if (AW.fields) AW.fields.markDirection(u);
    redraw();
  }
  function pick(p, x, y) {
    const d = dirAt(p, x, y);
    if (!d) return;
    const tol = 6 * AW.geo.unitsPerPixel(state, p.map.clientWidth, p.map.clientHeight);
    const [near] = AW.res.nearest(resonanceList(), AW.geo.unit(d), 1);
    if (!near || near.d > tol) return;
    const i = state.picked.indexOf(near.r.label);
    if (i >= 0) state.picked.splice(i, 1); else state.picked.push(near.r.label);
    showPicked();
    changed();
  }
  function showPicked() {
    $("selected").textContent = state.picked.length ? "picked: " + state.picked.map((l) => l + " order " + AW.res.order(l.replace(/[()]/g, "").split(",").map(Number))).join(", ") : "";
  }

  // ------------------------------------------------------------ turning, zooming
  let regionTool = null;  // (kind, onDone) while selecting a region on the map
  function attach(p) {
    const pointers = new Map();
    let drag = null, pinch = null;
    p.map.addEventListener("pointerdown", (e) => {
      p.map.setPointerCapture(e.pointerId);
      pointers.set(e.pointerId, pos(p, e));
      const [x, y] = pos(p, e);
      if (pointers.size === 2) {
        const [a, b] = [...pointers.values()];
        pinch = { dist: Math.hypot(a[0] - b[0], a[1] - b[1]), zoom: state.zoom };
        drag = null;
      } else if (regionTool) {
        drag = { region: true, x, y, d0: dirAt(p, x, y) };
      } else {
        drag = { x, y, lon: state.lon, lat: state.lat, moved: false };
      }
    });
    p.map.addEventListener("pointermove", (e) => {
      const [x, y] = pos(p, e);
      if (pointers.has(e.pointerId)) pointers.set(e.pointerId, [x, y]);
      if (pinch && pointers.size === 2) {
        const [a, b] = [...pointers.values()];
        state.zoom = Math.min(1e5, Math.max(0.2, pinch.zoom * Math.hypot(a[0] - b[0], a[1] - b[1]) / pinch.dist));
        changed();
        return;
      }
      if (drag && drag.region) {
        const d1 = dirAt(p, x, y);
        if (drag.d0 && d1) regionTool.update(drag.d0, d1);
        redraw();
      } else if (drag) {
        if (Math.hypot(x - drag.x, y - drag.y) > 3) drag.moved = true;
        if (drag.moved) {
          const deg = AW.geo.unitsPerPixel(state, p.map.clientWidth, p.map.clientHeight) / AW.geo.D2R;
          state.lon = drag.lon - (x - drag.x) * deg;
          state.lat = Math.max(-90, Math.min(90, drag.lat + (y - drag.y) * deg));
          changed();
        }
      }
      showReadout(p, dirAt(p, x, y));
    });
    const end = (e) => {
      pointers.delete(e.pointerId);
      if (pointers.size < 2) pinch = null;
      if (drag && drag.region) { regionTool.done(); regionTool = null; p.map.style.cursor = ""; }
      else if (drag && !drag.moved && e.type === "pointerup") pick(p, ...pos(p, e));
      drag = null;
    };
    p.map.addEventListener("pointerup", end);
    p.map.addEventListener("pointercancel", end);
    p.map.addEventListener("pointerleave", () => { if (!drag) showReadout(p, null); });
    p.map.addEventListener("wheel", (e) => {
      e.preventDefault();
      state.zoom = Math.min(1e5, Math.max(0.2, state.zoom * Math.exp(-e.deltaY * 0.0015)));
      changed();
    }, { passive: false });
  }

  // ------------------------------------------------------------ panels
  function addPanel(run, short, label, values, nside, signed) {
    const div = document.createElement("div");
    div.className = "panel";
    div.innerHTML = '<div class="title"></div><canvas class="map"></canvas><canvas class="overlay"></canvas>';
    div.querySelector(".title").textContent = label;
    $("panels").appendChild(div);
    const p = { run, short, label, values, nside, signed, div, map: div.querySelector(".map"), overlay: div.querySelector(".overlay") };
    p.renderer = new AW.Renderer(p.map);
    p.renderer.setMap("base", values, nside);
    attach(p);
    panels.push(p);
    return p;
  }
  // the signed terms of the two-sample chi-square sum (arnoldweb compare): their squares add up
  // to chi2 (before pooling the bins with few counts)
  function residuals(a, b) {
    let A = 0, B = 0;
    for (let i = 0; i < a.length; ++i) { A += a[i]; B += b[i]; }
    const ka = Math.sqrt(B / A), kb = Math.sqrt(A / B), out = new Float32Array(a.length);
    for (let i = 0; i < a.length; ++i) {
      const n = a[i] + b[i];
      out[i] = n > 0 ? (ka * a[i] - kb * b[i]) / Math.sqrt(n) : 0;
    }
    return out;
  }
  function showCompare() {
    if (!compareInfo) return;
    const c = compareInfo, div = $("compare");
    div.hidden = false;
    div.innerHTML = "";
    const add = (t) => { const e = document.createElement("div"); e.textContent = t; div.appendChild(e); };
    add("A - B, the two-sample chi-square test (arnoldweb compare):");
    add(`chi2 ${fmt(c.chi2)}, dof ${c.dof}, chi2/dof ${fmt(c.chi2 / Math.max(1, c.dof))}, p ${c.p_value > 0 ? c.p_value.toPrecision(4) : "< 1e-307"}`);
    add(c.p_value >= 1e-3 ? "statistically consistent at alpha = 0.001" : "different at alpha = 0.001");
    if (c.note) add(c.note);
  }
  function showRuns() {
    const div = $("runs");
    div.innerHTML = "<h3>Runs</h3>";
    for (const r of runs) {
      const m = r.meta, e = document.createElement("div");
      e.textContent = `${m.label || ""} ${m.title}: ${m.description || ""}`;
      div.appendChild(e);
    }
  }
  function setLayer(panelIndex, layer) {
    const p = panels[panelIndex];
    if (!p) return;
    p.layer = layer;
    if (layer) {
      p.renderer.setMap("layer", layer.values, layer.nside);
      layer.stats = null;
    } else p.renderer.clearLayer();
    p.drawn = null;
    redraw();
  }

  async function start() {
    readHash();
    window.addEventListener("error", (e) => error(e.message));
    window.addEventListener("unhandledrejection", (e) => error(String(e.reason && e.reason.message || e.reason)));
    try {
      runs = await AW.data.load();
    } catch (e) {
      error("could not load the runs: " + e.message);
      return;
    }
    if (AW.compareData) compareInfo = AW.compareData;
    const withMaps = runs.filter((r) => r.map);
    withMaps.forEach((r, i) => { r.meta.label = withMaps.length > 1 ? "ABCDEFGH"[i] || String(i) : ""; });
    for (const r of withMaps) addPanel(r, r.meta.label, (r.meta.label ? r.meta.label + ": " : "") + r.meta.title, r.map, r.meta.map.nside, false);
    if (withMaps.length === 2 && withMaps[0].meta.map.nside === withMaps[1].meta.map.nside) {
      addPanel(withMaps[0], "A - B", "A - B: signed chi-square residual", residuals(withMaps[0].map, withMaps[1].map), withMaps[0].meta.map.nside, true);
      if (!compareInfo && AW.data.served())
        compareInfo = await AW.data.json("api/compare/" + encodeURIComponent(withMaps[0].meta.id) + "/" + encodeURIComponent(withMaps[1].meta.id)).catch((e) => { error(e.message); return null; });
      showCompare();
    }
    if (modelList()) $("model-label").hidden = false;
    if (AW.fields) AW.fields.init(runs);
    const waiting = AW.zoom ? await AW.zoom.init() : false;  // true: the server is still running the scene
    showRuns();
    showPicked();
    const on = (id, ev, f) => $(id).addEventListener(ev, f);
    on("proj", "change", () => { state.proj = $("proj").value; changed(); });
    on("scale", "change", () => { state.scale = $("scale").value; state.lo = state.hi = null; changed(); });
    on("cmap", "change", () => { state.cmap = $("cmap").value; changed(); });
    const limit = (id, key) => on(id, "change", () => { const v = $(id).value.trim(); state[key] = v === "" || !Number.isFinite(+v) ? null : +v; changed(); });
    limit("lo", "lo");
    limit("hi", "hi");
    on("k", "change", () => { state.k = Math.max(1, Math.min(12, Math.round(+$("k").value) || 2)); changed(); });
    on("circles", "change", () => { state.circles = $("circles").checked; changed(); });
    on("model", "change", () => { state.model = $("model").checked; changed(); });
    on("reset", "click", () => { Object.assign(state, { proj: state.proj, lon: defaults.lon, lat: defaults.lat, zoom: 1 }); changed(); });
    on("png", "click", () => download("arnoldweb-view.png", viewPNG()));
    on("svg", "click", () => download("arnoldweb-circles.svg", URL.createObjectURL(new Blob([overlaySVG()], { type: "image/svg+xml" }))));
    window.addEventListener("resize", redraw);
    window.addEventListener("hashchange", () => { readHash(); syncControls(); redraw(); });
    if (!waiting && !panels.length && !(AW.fields && AW.fields.count())) error("none of the runs has a velocity map or fields to show");
    changed();
    document.body.dataset.ready = "1";
  }
  function download(name, url) {
    const a = document.createElement("a");
    a.href = url;
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
  }
  // every panel with its circles, side by side, as a PNG data URL
  function viewPNG() {
    frame();
    const dpr = window.devicePixelRatio || 1;
    const w = panels.reduce((s, p) => s + p.map.width, 0), h = Math.max(...panels.map((p) => p.map.height));
    const c = document.createElement("canvas");
    c.width = w; c.height = h;
    const ctx = c.getContext("2d");
    let x = 0;
    for (const p of panels) {
      ctx.drawImage(p.map, x, 0);
      ctx.drawImage(p.overlay, x, 0);
      ctx.fillStyle = "#ccc";
      ctx.font = `${12 * dpr}px system-ui, sans-serif`;
      ctx.fillText(p.label, x + 8 * dpr, 16 * dpr);
      x += p.map.width;
    }
    return c.toDataURL("image/png");
  }
  function overlaySVG(i = 0) {
    const p = panels[i];
    return AW.overlay.svg(state, resonanceList(), p.map.clientWidth, p.map.clientHeight);
  }
  document.addEventListener("DOMContentLoaded", start);
  return {
    state, panels, regions, redraw, changed, error, viewPNG, overlaySVG, setLayer, resonanceList, fmt,
    startRegion: (tool) => { regionTool = tool; for (const p of panels) p.map.style.cursor = "crosshair"; },
    stats: () => ({ frames, firstFrameMs }),  // for bench/explorer/viewer.py
  };
})();
