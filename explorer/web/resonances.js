// arnoldweb explorer: the resonances m.P = 0 (great circles of the momentum sphere), as
// arnoldweb::resonances lists them: m coprime, its first non-zero component positive, order
// max |m_i|; their angular distance from a direction and their points for drawing.
"use strict";
var AW = window.AW || (window.AW = {});

AW.res = (function () {
  const gcd = (a, b) => { a = Math.abs(a); b = Math.abs(b); while (b) [a, b] = [b, a % b]; return a; };
  const label = (m) => "(" + m.join(",") + ")";
  const order = (m) => Math.max(Math.abs(m[0]), Math.abs(m[1]), Math.abs(m[2]));
  function canonical(m) {
    const g = gcd(gcd(m[0], m[1]), m[2]);
    if (!g) return null;
    let r = m.map((x) => x / g);
    const first = r.find((x) => x !== 0);
    if (first < 0) r = r.map((x) => -x);
    return r.map((x) => x + 0);  // no -0
  }
  const cache = new Map();
  // every resonance with order <= k, lowest order first
  function upTo(k) {
    if (cache.has(k)) return cache.get(k);
    const out = [];
    for (let o = 1; o <= k; ++o)
      for (let a = 0; a <= o; ++a)
        for (let b = -o; b <= o; ++b)
          for (let c = -o; c <= o; ++c) {
            const m = [a, b, c];
            if (order(m) !== o || gcd(gcd(a, b), c) !== 1) continue;
            const first = m.find((x) => x !== 0);
            if (first < 0) continue;
            out.push({ m, order: o, label: label(m) });
          }
    cache.set(k, out);
    return out;
  }
  // the resonances of wave vectors a model declares (lists of [m1, m2, m3])
  function fromVectors(vs) {
    const seen = new Set(), out = [];
    for (const v of vs) {
      const m = canonical(v);
      if (!m || seen.has(label(m))) continue;
      seen.add(label(m));
      out.push({ m, order: order(m), label: label(m) });
    }
    return out.sort((a, b) => a.order - b.order);
  }
  // angular distance (radians) of a unit direction from the circle m.P = 0
  function distance(r, u) {
    const n = Math.hypot(r.m[0], r.m[1], r.m[2]);
    const s = (r.m[0] * u[0] + r.m[1] * u[1] + r.m[2] * u[2]) / n;
    return Math.abs(Math.asin(Math.max(-1, Math.min(1, s))));
  }
  function nearest(list, u, count) {
    return list.map((r) => ({ r, d: distance(r, u) })).sort((a, b) => a.d - b.d).slice(0, count);
  }
  // `n` points of the great circle m.P = 0 (unit vectors)
  function circle(r, n) {
    const m = AW.geo.unit(r.m);
    // a unit vector a perpendicular to m, and b = m x a
    const t = Math.abs(m[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
    const a = AW.geo.unit([m[1] * t[2] - m[2] * t[1], m[2] * t[0] - m[0] * t[2], m[0] * t[1] - m[1] * t[0]]);
    const b = [m[1] * a[2] - m[2] * a[1], m[2] * a[0] - m[0] * a[2], m[0] * a[1] - m[1] * a[0]];
    const pts = [];
    for (let i = 0; i <= n; ++i) {
      const w = 2 * Math.PI * i / n, c = Math.cos(w), s = Math.sin(w);
      pts.push([c * a[0] + s * b[0], c * a[1] + s * b[1], c * a[2] + s * b[2]]);
    }
    return pts;
  }
  return { upTo, fromVectors, distance, nearest, circle, label, order, canonical };
})();
