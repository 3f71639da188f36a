// arnoldweb explorer: directions, the view's frame, the three projections and
// HEALPix RING pixels, in double precision. The fragment shader (render.js)
// draws with the same formulas in single precision; everything the page reports
// (the readout, the overlay) comes from here.
"use strict";
var AW = window.AW || (window.AW = {});

AW.geo = (function () {
  const D2R = Math.PI / 180;
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const norm = (a) => Math.sqrt(dot(a, a));
  const unit = (a) => { const n = norm(a); return [a[0] / n, a[1] / n, a[2] / n]; };

  // P along (cos lat cos lon, cos lat sin lon, sin lat), as the scenes write directions
  function direction(lonDeg, latDeg) {
    const lo = lonDeg * D2R, la = latDeg * D2R;
    return [Math.cos(la) * Math.cos(lo), Math.cos(la) * Math.sin(lo), Math.sin(la)];
  }
  function lonlat(v) {
    const u = unit(v);
    let lon = Math.atan2(u[1], u[0]) / D2R;
    if (lon < 0) lon += 360;
    return [lon, Math.asin(Math.max(-1, Math.min(1, u[2]))) / D2R];
  }
  // the view's frame: c towards the viewer (centre of the picture), east to the right, north up
  // (arnoldweb::tangent_frame)
  function frame(lonDeg, latDeg) {
    const lo = lonDeg * D2R, la = latDeg * D2R;
    return {
      c: [Math.cos(la) * Math.cos(lo), Math.cos(la) * Math.sin(lo), Math.sin(la)],
      e: [-Math.sin(lo), Math.cos(lo), 0],
      n: [-Math.sin(la) * Math.cos(lo), -Math.sin(la) * Math.sin(lo), Math.cos(la)],
    };
  }
  const fromLocal = (f, x, y, z) => [
    x * f.e[0] + y * f.n[0] + z * f.c[0],
    x * f.e[1] + y * f.n[1] + z * f.c[1],
    x * f.e[2] + y * f.n[2] + z * f.c[2],
  ];
  const toLocal = (f, v) => [dot(v, f.e), dot(v, f.n), dot(v, f.c)];

  const SQRT2 = Math.SQRT2;
  // The scale of a projection: plane units per CSS pixel. Orthographic: the globe's radius is
  // 0.45 of the smaller side at zoom 1; gnomonic: tan 45 degrees at 0.45 of it; Mollweide: the
  // ellipse's half width (2 sqrt 2) is 0.47 of the width (or its half height sqrt 2 of 0.47 of
  // the height, whichever is smaller).
  function unitsPerPixel(view, w, h) {
    if (view.proj === "mollweide") return 1 / (Math.min(0.47 * w / (2 * SQRT2), 0.47 * h / SQRT2) * view.zoom);
    return 1 / (0.45 * Math.min(w, h) * view.zoom);
  }
  // The direction under the CSS pixel position (sx, sy) of a w x h picture, or null where the
  // projection shows nothing (off the globe, off the ellipse).
  function screenToDir(view, sx, sy, w, h) {
    const s = unitsPerPixel(view, w, h);
    const x = (sx - w / 2) * s, y = (h / 2 - sy) * s;
    const f = frame(view.lon, view.lat);
    if (view.proj === "ortho") {
      const r2 = x * x + y * y;
      if (r2 > 1) return null;
      return fromLocal(f, x, y, Math.sqrt(1 - r2));
    }
    if (view.proj === "gnomonic") return unit(fromLocal(f, x, y, 1));
    // Mollweide
    if (x * x / 8 + y * y / 2 > 1) return null;
    const t = Math.asin(Math.max(-1, Math.min(1, y / SQRT2)));
    const sinLat = (2 * t + Math.sin(2 * t)) / Math.PI;
    const cosT = Math.cos(t);
    const lon = cosT > 0 ? Math.PI * x / (2 * SQRT2 * cosT) : 0;
    if (Math.abs(lon) > Math.PI) return null;
    const cl = Math.sqrt(Math.max(0, 1 - sinLat * sinLat));
    return fromLocal(f, cl * Math.sin(lon), sinLat, cl * Math.cos(lon));
  }
  // The CSS pixel position of a unit direction, or null where it is not drawn (the far side of
  // the globe, behind the gnomonic plane). Mollweide also returns the local longitude (radians)
  // so that a polyline can break where it wraps.
  function dirToScreen(view, v, w, h) {
    const s = unitsPerPixel(view, w, h);
    const f = frame(view.lon, view.lat);
    const [x, y, z] = toLocal(f, v);
    let px, py, lon = 0;
    if (view.proj === "ortho") {
      if (z < 0) return null;
      px = x; py = y;
    } else if (view.proj === "gnomonic") {
      if (z <= 1e-6) return null;
      px = x / z; py = y / z;
    } else {
      lon = Math.atan2(x, z);
      const lat = Math.asin(Math.max(-1, Math.min(1, y)));
      // 2t + sin 2t = pi sin lat, by Newton
      let t = lat;
      for (let i = 0; i < 50; ++i) {
        const g = 2 * t + Math.sin(2 * t) - Math.PI * Math.sin(lat);
        const d = 2 + 2 * Math.cos(2 * t);
        if (Math.abs(d) < 1e-15) break;
        const step = g / d;
        t -= step;
        if (Math.abs(step) < 1e-15) break;
      }
      px = 2 * SQRT2 / Math.PI * lon * Math.cos(t);
      py = SQRT2 * Math.sin(t);
    }
    return { x: w / 2 + px / s, y: h / 2 - py / s, lon: lon };
  }

  // HEALPix RING pixel of a direction: Gorski et al. (2005), written as lib/device/aw_healpix.h
  function vec2pix(nside, v) {
    const [x, y, z] = v;
    const rxy = Math.sqrt(x * x + y * y);
    const nrm = Math.sqrt(x * x + y * y + z * z);
    const cz = z / nrm, za = Math.abs(cz);
    let tt = Math.atan2(y, x) * (2 / Math.PI);
    if (tt < 0) tt += 4;
    if (tt >= 4) tt -= 4;
    const n = nside;
    if (za <= 2 / 3) {
      const nl4 = 4 * nside;
      const t1 = n * (0.5 + tt), t2 = n * (cz * 0.75);
      const jp = Math.trunc(t1 - t2), jm = Math.trunc(t1 + t2);
      const ir = nside + 1 + jp - jm;
      const kshift = 1 - (ir & 1);
      const ip = Math.trunc((jp + jm - nside + kshift + 1 + 2 * nl4) / 2) % nl4;
      return 2 * nside * (nside - 1) + (ir - 1) * nl4 + ip;
    }
    const tp = tt - Math.trunc(tt);
    const sth = rxy / nrm;
    const tmp = n * (sth / Math.sqrt((1 + za) / 3));
    const jp = Math.trunc(tp * tmp), jm = Math.trunc((1 - tp) * tmp);
    const ir = jp + jm + 1;
    let ip = Math.trunc(tt * ir);
    if (ip >= 4 * ir) ip = 4 * ir - 1;
    return cz > 0 ? 2 * ir * (ir - 1) + ip : 12 * nside * nside - 2 * ir * (ir + 1) + ip;
  }

  return { D2R, dot, norm, unit, direction, lonlat, frame, fromLocal, toLocal, unitsPerPixel, screenToDir, dirToScreen, vec2pix };
})();
