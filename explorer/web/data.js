// arnoldweb explorer: the runs the page shows. From file:// (arnoldweb view) each run is a
// script beside view.html that calls AW.addRun(meta, base64 of the map); from a server
// (arnoldweb serve) the same meta comes from api/runs and the map's bytes from
// api/runs/<id>/map. A map is little-endian u8, u16, u32 or f64 (meta.map.dtype), RING order.
"use strict";
var AW = window.AW || (window.AW = {});

AW.data = (function () {
  const pending = [];
  function decode(dtype, buffer) {
    // kept as they are (exact counts for the readout); render.js makes the float texture
    const T = { u8: Uint8Array, u16: Uint16Array, u32: Uint32Array, f32: Float32Array, f64: Float64Array }[dtype];
    if (!T) throw new Error("unknown map type " + dtype);
    return new T(buffer);
  }
  function fromBase64(text) {
    const bin = atob(text), bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) bytes[i] = bin.charCodeAt(i);
    return bytes.buffer;
  }
  // called by the data scripts of arnoldweb view
  AW.addRun = function (meta, map64, more) {
    pending.push({ meta, map: map64 ? decode(meta.map.dtype, fromBase64(map64)) : null, fields: more || {} });
  };
  const served = () => location.protocol === "http:" || location.protocol === "https:";
  async function json(url, options) {
    const r = await fetch(url, options);
    const text = await r.text();
    let body;
    try { body = JSON.parse(text); } catch (e) { body = { error: text }; }
    if (!r.ok) throw new Error(body.error || r.status + " " + r.statusText);
    return body;
  }
  async function mapOf(meta) {
    if (!meta.map) return null;
    const r = await fetch("api/runs/" + encodeURIComponent(meta.id) + "/map");
    if (!r.ok) throw new Error("map of " + meta.id + ": " + (await r.text()));
    return decode(meta.map.dtype, await r.arrayBuffer());
  }
  async function fieldsOf(meta) {
    if (!meta.fields || !meta.fields.length) return {};
    return json("api/runs/" + encodeURIComponent(meta.id) + "/fields");
  }
  // every run: [{meta, map, fields}]
  async function load() {
    if (pending.length || !served()) return pending.splice(0);
    const { runs } = await json("api/runs");
    const out = [];
    for (const meta of runs) out.push({ meta, map: await mapOf(meta), fields: await fieldsOf(meta) });
    return out;
  }
  async function loadOne(id) {
    const meta = await json("api/runs/" + encodeURIComponent(id));
    return { meta, map: await mapOf(meta), fields: await fieldsOf(meta) };
  }
  return { load, loadOne, json, served, decode };
})();
