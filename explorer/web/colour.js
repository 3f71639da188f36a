// arnoldweb explorer: colour maps and scales. The maps are tables of 256 colours that the
// shader reads as a texture and the colour bar draws; "paper" is the colouring of every
// picture arnoldweb draws (lib/src/pictures/colormap.cpp: cubehelix, start 3, +0.5 rotations,
// saturation 2.2; with the log scale, positive counts start at 0.08 above black).
"use strict";
var AW = window.AW || (window.AW = {});

AW.colour = (function () {
  function cubehelix(t) {
    const start = 3.0, rotations = 0.5, hue = 2.2;
    t = Math.min(1, Math.max(0, t));
    const phi = 2 * Math.PI * (start / 3 + 1 + rotations * t);
    const amp = hue * t * (1 - t) / 2, c = Math.cos(phi), s = Math.sin(phi);
    return [t + amp * (-0.14861 * c + 1.78277 * s), t + amp * (-0.29227 * c - 0.90649 * s), t + amp * (1.97294 * c)]
      .map((v) => Math.min(1, Math.max(0, v)));
  }
  const maps = {
    paper: cubehelix,
    grey: (t) => [t, t, t],
    // blue - white - red, for signed values (the difference of two maps)
    diverging: (t) => (t < 0.5 ? [2 * t, 2 * t, 1] : [1, 2 * (1 - t), 2 * (1 - t)]).map((v) => 0.15 + 0.85 * v),
  };
  function table(name) {
    const f = maps[name] || maps.paper, out = new Uint8Array(256 * 4);
    for (let i = 0; i < 256; ++i) {
      const c = f(i / 255);
      out.set([Math.round(255 * c[0]), Math.round(255 * c[1]), Math.round(255 * c[2]), 255], 4 * i);
    }
    return out;
  }
  // 257 edges of equal numbers of the non-zero values: t = (bin of v) / 256
  function quantileEdges(values) {
    const nz = [];
    for (let i = 0; i < values.length; ++i) if (values[i] !== 0) nz.push(values[i]);
    const edges = new Float32Array(257);
    if (!nz.length) return edges;
    const sorted = Float64Array.from(nz).sort();
    for (let i = 0; i <= 256; ++i) edges[i] = sorted[Math.min(sorted.length - 1, Math.floor(i * (sorted.length - 1) / 256))];
    return edges;
  }
  // Where a value falls on the colour scale, in [0, 1]; -1: an empty pixel (drawn dark), for
  // the scales of count maps. The shader computes the same (render.js).
  function position(scale, v) {
    const { mode, lo, hi, signed } = scale;
    if (signed) return Math.min(1, Math.max(0, 0.5 + 0.5 * v / Math.max(Math.abs(lo), Math.abs(hi))));
    if (v === 0) return -1;
    if (mode === "log") {
      if (v <= 0 || lo <= 0) return -1;
      const t = (Math.log10(v) - Math.log10(lo)) / Math.max(1e-12, Math.log10(hi) - Math.log10(lo));
      return 0.08 + 0.92 * Math.min(1, Math.max(0, t));
    }
    if (mode === "histeq") {
      const e = scale.edges;
      let a = 0, b = 256;
      while (b - a > 1) { const m = (a + b) >> 1; if (v >= e[m]) a = m; else b = m; }
      return 0.08 + 0.92 * (a / 256);
    }
    return Math.min(1, Math.max(0, (v - lo) / Math.max(1e-300, hi - lo)));
  }
  return { maps, table, quantileEdges, position, cubehelix };
})();
