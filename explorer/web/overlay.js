// arnoldweb explorer: what is drawn over the map: the resonance circles m.P = 0 (all up to
// order k, or the model's), the ones the user picked, labelled "(m1,m2,m3)" with their order,
// regions (a zoom's cap or box) and the cursor's mark. The same polylines give the SVG.
"use strict";
var AW = window.AW || (window.AW = {});

AW.overlay = (function () {
  // the visible pieces of a circle through `pts` (unit vectors) as screen polylines
  function polylines(view, pts, w, h) {
    const lines = [];
    let cur = [], prev = null;
    for (const p of pts) {
      const s = AW.geo.dirToScreen(view, p, w, h);
      const jump = s && prev && (view.proj === "mollweide" ? Math.abs(s.lon - prev.lon) > Math.PI / 2
                                                           : Math.hypot(s.x - prev.x, s.y - prev.y) > 4 * (w + h));
      if (!s || jump) {
        if (cur.length > 1) lines.push(cur);
        cur = [];
      }
      if (s) cur.push(s);
      prev = s;
    }
    if (cur.length > 1) lines.push(cur);
    return lines;
  }
  // where a circle's label goes: its visible point nearest to 0.8 of the way from the
  // picture's centre to its edge (labels of circles through the centre then part)
  function labelPoint(lines, w, h) {
    let best = null, bd = Infinity;
    const ring = 0.8 * Math.min(w, h) / 2;
    for (const l of lines)
      for (const p of l) {
        if (p.x < 20 || p.y < 20 || p.x > w - 60 || p.y > h - 10) continue;
        const d = Math.abs(Math.hypot(p.x - w / 2, p.y - h / 2) - ring) - 1e-3 * p.y;
        if (d < bd) { bd = d; best = p; }
      }
    return best;
  }
  const SAMPLES = 720;
  // Every circle to draw in a panel: [{r, lines, label, picked}]; the last answer is kept, so
  // that moving the cursor redraws without projecting the circles again
  let memo = { key: null, list: null, out: null };
  function circles(state, list, w, h) {
    const key = [state.proj, state.lon, state.lat, state.zoom, state.circles, state.picked.join(";"), w, h].join("|");
    if (memo.key === key && memo.list === list) return memo.out;
    const out = [];
    memo = { key, list, out };
    const picked = new Set(state.picked);
    const shown = state.circles ? list.slice() : [];
    for (const lab of state.picked)
      if (!shown.some((r) => r.label === lab)) {
        const m = lab.replace(/[()]/g, "").split(",").map(Number);
        if (m.length === 3 && m.every(Number.isInteger)) shown.push({ m, order: AW.res.order(m), label: lab });
      }
    for (const r of shown) {
      const lines = polylines(state, AW.res.circle(r, SAMPLES), w, h);
      if (lines.length) out.push({ r, lines, picked: picked.has(r.label), at: labelPoint(lines, w, h) });
    }
    return out;
  }
  function regionLines(state, region, w, h) {
    const pts = [];
    if (region.kind === "cap") {
      const f = AW.geo.frame(region.center[0], region.center[1]);
      const a = region.radius * AW.geo.D2R;
      for (let i = 0; i <= 360; ++i) {
        const t = i * AW.geo.D2R;
        pts.push(AW.geo.fromLocal(f, Math.sin(a) * Math.cos(t), Math.sin(a) * Math.sin(t), Math.cos(a)));
      }
    } else {
      const [l0, l1] = region.lon, [b0, b1] = region.lat;
      for (let i = 0; i <= 60; ++i) pts.push(AW.geo.direction(l0 + (l1 - l0) * i / 60, b0));
      for (let i = 0; i <= 60; ++i) pts.push(AW.geo.direction(l1, b0 + (b1 - b0) * i / 60));
      for (let i = 0; i <= 60; ++i) pts.push(AW.geo.direction(l1 - (l1 - l0) * i / 60, b1));
      for (let i = 0; i <= 60; ++i) pts.push(AW.geo.direction(l0, b1 - (b1 - b0) * i / 60));
    }
    return polylines(state, pts, w, h);
  }
  // a picked circle says its order too
  const text = (c) => (c.picked ? c.r.label + " order " + c.r.order : c.r.label);
  function draw(ctx, state, list, regions, cursor, w, h) {
    ctx.clearRect(0, 0, w, h);
    const stroke = (lines) => {
      ctx.beginPath();
      for (const l of lines) { ctx.moveTo(l[0].x, l[0].y); for (const p of l.slice(1)) ctx.lineTo(p.x, p.y); }
      ctx.stroke();
    };
    ctx.font = "12px system-ui, sans-serif";
    for (const c of circles(state, list, w, h)) {
      ctx.strokeStyle = c.picked ? "rgba(80, 255, 120, 0.95)" : "rgba(120, 200, 255, 0.55)";
      ctx.lineWidth = c.picked ? 2 : 1;
      stroke(c.lines);
      if (c.at) {
        ctx.fillStyle = c.picked ? "#7f7" : "rgba(170, 220, 255, 0.9)";
        ctx.fillText(text(c), c.at.x + 4, c.at.y - 4);
      }
    }
    for (const g of regions) {
      ctx.strokeStyle = g.colour || "rgba(255, 210, 60, 0.95)";
      ctx.lineWidth = 1.5;
      stroke(regionLines(state, g, w, h));
    }
    if (cursor) {
      const s = AW.geo.dirToScreen(state, cursor, w, h);
      if (s) {
        ctx.strokeStyle = "#fff";
        ctx.lineWidth = 1;
        ctx.strokeRect(s.x - 4, s.y - 4, 8, 8);
      }
    }
  }
  // The circles as an SVG document of the panel's size: one <g> per circle, with its label
  // and order in data- attributes and polylines in CSS pixels.
  function svg(state, list, w, h) {
    const esc = (s) => String(s).replace(/[<>&"]/g, (c) => ({ "<": "&lt;", ">": "&gt;", "&": "&amp;", '"': "&quot;" }[c]));
    let out = `<svg xmlns="http://www.w3.org/2000/svg" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}">\n`;
    out += `<desc>arnoldweb explorer: resonance circles m.P = 0, ${esc(state.proj)} projection centred on lon ${state.lon}, lat ${state.lat}, zoom ${state.zoom}</desc>\n`;
    for (const c of circles(state, list, w, h)) {
      out += `<g class="resonance" data-m="${c.r.m.join(",")}" data-order="${c.r.order}" stroke="${c.picked ? "#3c3" : "#48c"}" fill="none">\n`;
      for (const l of c.lines) out += `<polyline points="${l.map((p) => p.x.toFixed(3) + "," + p.y.toFixed(3)).join(" ")}"/>\n`;
      if (c.at) out += `<text x="${(c.at.x + 4).toFixed(1)}" y="${(c.at.y - 4).toFixed(1)}" fill="#000" stroke="none" font-size="12">${esc(text(c))}</text>\n`;
      out += `</g>\n`;
    }
    return out + "</svg>\n";
  }
  return { draw, svg, circles, polylines };
})();
