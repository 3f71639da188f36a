// arnoldweb explorer: a grid run's fields (FLI, MEGNO, the diffusion index, ...: one value per
// trajectory of the grid) as images, and the frequency map (nu_x against nu_y of the first
// window) as a scatter. The trajectory under the cursor in one of them is marked in all (and
// its initial direction on the maps, for a grid of directions).
"use strict";
var AW = window.AW || (window.AW = {});

AW.fields = (function () {
  const views = [];  // {kind: "field"|"scatter", canvas, run, f, index(x, y) -> i, mark(i), draw()}
  let marked = -1;
  const W = 300;

  function extent(values) {
    let lo = Infinity, hi = -Infinity;
    for (const v of values) if (v !== null && Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    return lo <= hi ? [lo, hi === lo ? lo + 1 : hi] : [0, 1];
  }
  // the grid cell (trajectory index) of a point of the image, and the image's point of a cell
  function layout(f) {
    if (f.grid === "healpix") {
      const H = W / 2;  // Mollweide, longitude 0 in the middle, east to the right
      const view = { proj: "mollweide", lon: 0, lat: 0, zoom: 1 };
      return {
        w: W, h: H,
        at: (x, y) => { const d = AW.geo.screenToDir(view, x + 0.5, y + 0.5, W, H); return d ? AW.geo.vec2pix(f.nside, d) : -1; },
        where: (i) => { const d = pixCentre(f.nside, i); return d ? AW.geo.dirToScreen(view, d, W, H) : null; },
        dir: (i) => pixCentre(f.nside, i),
      };
    }
    const [n2, n1] = f.shape.length === 2 ? f.shape : [1, f.shape[0]];
    const h = Math.max(60, Math.round(W * n2 / n1));
    return {
      w: W, h,
      at: (x, y) => { const c = Math.floor(x * n1 / W), r = Math.floor((h - 1 - y) * n2 / h); return c >= 0 && c < n1 && r >= 0 && r < n2 ? r * n1 + c : -1; },
      where: (i) => ({ x: ((i % n1) + 0.5) * W / n1, y: h - (Math.floor(i / n1) + 0.5) * h / n2 }),
      dir: (i) => (f.grid === "lonlat" ? AW.geo.direction(f.x[0] + ((i % n1) + 0.5) * (f.x[1] - f.x[0]) / n1,
                                                           f.y[0] + (Math.floor(i / n1) + 0.5) * (f.y[1] - f.y[0]) / n2) : null),
    };
  }
  // the unit vector to a RING pixel's centre (for marks)
  function pixCentre(nside, pix) {
    const npix = 12 * nside * nside;
    if (pix < 0 || pix >= npix) return null;
    // ring-order centre (Gorski et al. 2005, eq. 4-9)
    const ncap = 2 * nside * (nside - 1);
    let z, phi;
    if (pix < ncap) {
      const i = Math.floor((1 + Math.sqrt(1 + 2 * pix)) / 2), j = pix + 1 - 2 * i * (i - 1);
      z = 1 - i * i / (3 * nside * nside); phi = (j - 0.5) * Math.PI / (2 * i);
    } else if (pix < npix - ncap) {
      const p = pix - ncap, i = Math.floor(p / (4 * nside)) + nside, j = p % (4 * nside) + 1;
      const s = (i - nside + 1) % 2 === 0 ? 1 : 0.5;
      z = 4 / 3 - 2 * i / (3 * nside); phi = (j - s) * Math.PI / (2 * nside);
    } else {
      const p = npix - pix, i = Math.floor((1 + Math.sqrt(2 * p - 1)) / 2), j = 4 * i + 1 - (p - 2 * i * (i - 1));
      z = -1 + i * i / (3 * nside * nside); phi = (j - 0.5) * Math.PI / (2 * i);
    }
    const s = Math.sqrt(1 - z * z);
    return [s * Math.cos(phi), s * Math.sin(phi), z];
  }

  function fieldView(run, name, f) {
    const L = layout(f), c = document.createElement("canvas");
    c.className = "field";
    c.width = L.w; c.height = L.h;
    const [lo, hi] = extent(f.values);
    const img = c.getContext("2d").createImageData(L.w, L.h);
    for (let y = 0; y < L.h; ++y)
      for (let x = 0; x < L.w; ++x) {
        const i = L.at(x, y), v = i >= 0 ? f.values[i] : undefined;
        const col = v === undefined ? [0.06, 0.06, 0.08] : v === null ? [0.3, 0, 0] : AW.colour.cubehelix((v - lo) / (hi - lo));
        img.data.set([255 * col[0], 255 * col[1], 255 * col[2], 255], 4 * (y * L.w + x));
      }
    const v = { kind: "field", name, canvas: c, run, f, L, img, lo, hi };
    v.index = (x, y) => L.at(x, y);
    v.draw = () => {
      const ctx = c.getContext("2d");
      ctx.putImageData(img, 0, 0);
      if (marked >= 0 && marked < f.values.length) {
        const p = L.where(marked);
        if (p) { ctx.strokeStyle = "#0f0"; ctx.strokeRect(p.x - 4, p.y - 4, 8, 8); }
      }
    };
    return v;
  }
  function scatterView(run, fr) {
    const c = document.createElement("canvas");
    c.className = "field";
    c.width = W; c.height = W;
    const [x0, x1] = extent(fr.nu1), [y0, y1] = extent(fr.nu2), m = 24;
    const sx = (v) => m + (v - x0) / (x1 - x0) * (W - 2 * m), sy = (v) => W - m - (v - y0) / (y1 - y0) * (W - 2 * m);
    const v = { kind: "scatter", name: "frequency map", canvas: c, run, f: { values: fr.nu1 } };
    v.index = (x, y) => {
      let best = -1, bd = 36;
      for (let i = 0; i < fr.nu1.length; ++i) {
        if (fr.nu1[i] === null || fr.nu2[i] === null) continue;
        const d = (sx(fr.nu1[i]) - x) ** 2 + (sy(fr.nu2[i]) - y) ** 2;
        if (d < bd) { bd = d; best = i; }
      }
      return best;
    };
    v.draw = () => {
      const ctx = c.getContext("2d");
      ctx.fillStyle = "#101014"; ctx.fillRect(0, 0, W, W);
      ctx.fillStyle = "rgba(240, 180, 90, 0.6)";
      for (let i = 0; i < fr.nu1.length; ++i)
        if (fr.nu1[i] !== null && fr.nu2[i] !== null) ctx.fillRect(sx(fr.nu1[i]) - 0.5, sy(fr.nu2[i]) - 0.5, 1.5, 1.5);
      ctx.fillStyle = "#ccc"; ctx.font = "11px system-ui, sans-serif";
      ctx.fillText("nu_x (turns/T)", W / 2 - 30, W - 6);
      ctx.save(); ctx.translate(11, W / 2 + 30); ctx.rotate(-Math.PI / 2); ctx.fillText("nu_y (turns/T)", 0, 0); ctx.restore();
      if (marked >= 0 && fr.nu1[marked] !== null && fr.nu1[marked] !== undefined) {
        ctx.strokeStyle = "#0f0"; ctx.strokeRect(sx(fr.nu1[marked]) - 4, sy(fr.nu2[marked]) - 4, 8, 8);
      }
    };
    v.value = (i) => `nu_x ${AW.app.fmt(fr.nu1[i])}, nu_y ${AW.app.fmt(fr.nu2[i])}`;
    return v;
  }
  function mark(i, from) {
    marked = i;
    for (const v of views) v.draw();
    const out = document.getElementById("field-readout");
    if (!out) return;
    if (i < 0) { out.textContent = ""; return; }
    const parts = ["trajectory " + i];
    for (const v of views) parts.push(v.name + ": " + (v.value ? v.value(i) : AW.app.fmt(v.f.values[i] ?? NaN)));
    out.textContent = parts.join(" · ");
    // its initial direction on the maps
    const fv = views.find((x) => x.kind === "field" && x.L.dir);
    const d = fv && fv.L.dir(i);
    if (d && from !== "map") { AW.app.regions.length = 0; AW.app.regions.push({ kind: "cap", center: AW.geo.lonlat(d), radius: 0.8, colour: "#0f0" }); AW.app.redraw(); }
  }
  function init(runs) {
    const box = document.getElementById("fields");
    for (const r of runs) {
      const fs = r.fields || {};
      for (const [name, f] of Object.entries(fs)) if (name !== "frequencies") views.push(fieldView(r, name, f));
      if (fs.frequencies) views.push(scatterView(r, fs.frequencies));
    }
    if (!views.length) return;
    box.innerHTML = "<h3>Trajectories</h3><div id='field-readout'></div>";
    for (const v of views) {
      const h = document.createElement("div");
      h.textContent = v.name + (v.kind === "field" ? ` (${AW.app.fmt(v.lo)} .. ${AW.app.fmt(v.hi)}, ${v.f.grid} grid)` : "");
      box.appendChild(h);
      box.appendChild(v.canvas);
      v.canvas.dataset.field = v.name;
      v.canvas.addEventListener("mousemove", (e) => {
        const r = v.canvas.getBoundingClientRect();
        mark(v.index((e.clientX - r.left) * v.canvas.width / r.width, (e.clientY - r.top) * v.canvas.height / r.height), v.name);
      });
      v.draw();
    }
  }
  // the cursor on a map: the grid trajectory that starts in that direction (healpix grids)
  function markDirection(u) {
    const fv = views.find((x) => x.kind === "field" && x.f.grid === "healpix");
    if (fv) mark(AW.geo.vec2pix(fv.f.nside, u), "map");
  }
  return { init, markDirection, count: () => views.length };
})();
