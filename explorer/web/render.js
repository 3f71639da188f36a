// arnoldweb explorer: the map drawn per screen pixel by a WebGL2 fragment shader: the
// direction under the pixel (the projection's inverse, geometry.js), its HEALPix RING pixel
// (lib/device/aw_healpix.h in single precision), the map's value there, its place on the
// colour scale (colour.js) and the colour map's colour. A zoom run's map is a layer drawn
// over its region.
"use strict";
var AW = window.AW || (window.AW = {});

AW.Renderer = (function () {
  const VERT = `#version 300 es
in vec2 aPos;
void main() { gl_Position = vec4(aPos, 0.0, 1.0); }`;

  const FRAG = `#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
uniform int uProj;          // 0 orthographic, 1 gnomonic, 2 Mollweide
uniform mat3 uFrame;        // columns: east, north, centre
uniform float uUnits;       // plane units per CSS pixel
uniform vec2 uSize;         // CSS pixels
uniform float uDpr;
uniform sampler2D uLut;     // 256 x 1 colours
uniform sampler2D uEdges;   // 257 x 1 quantile edges (histogram-equalised scale)
struct Layer { sampler2D map; int nside; int texW; int mode; float lo; float hi; };
uniform Layer uBase;
uniform bool uLayerOn;
uniform Layer uLayer;
uniform int uRegion;        // 0 cap, 1 box
uniform vec4 uCap;          // centre (unit vector), cos(radius)
uniform vec4 uBox;          // lon from, lon to, lat from, lat to (radians; lon from in [0, 2 pi))
out vec4 outColour;
const float PI = 3.141592653589793;
const float SQRT2 = 1.4142135623730951;

bool screenToDir(vec2 s, out vec3 d) {
  vec2 p = vec2(s.x - 0.5 * uSize.x, 0.5 * uSize.y - s.y) * uUnits;
  if (uProj == 0) {
    float r2 = dot(p, p);
    if (r2 > 1.0) return false;
    d = uFrame * vec3(p, sqrt(1.0 - r2));
    return true;
  }
  if (uProj == 1) { d = normalize(uFrame * vec3(p, 1.0)); return true; }
  if (p.x * p.x / 8.0 + p.y * p.y / 2.0 > 1.0) return false;
  float t = asin(clamp(p.y / SQRT2, -1.0, 1.0));
  float sl = (2.0 * t + sin(2.0 * t)) / PI;
  float ct = cos(t);
  float lon = ct > 0.0 ? PI * p.x / (2.0 * SQRT2 * ct) : 0.0;
  if (abs(lon) > PI) return false;
  float cl = sqrt(max(0.0, 1.0 - sl * sl));
  d = uFrame * vec3(cl * sin(lon), sl, cl * cos(lon));
  return true;
}

int vec2pix(int nside, vec3 v) {
  float rxy = sqrt(v.x * v.x + v.y * v.y);
  float nrm = length(v);
  float cz = v.z / nrm, za = abs(cz);
  float tt = atan(v.y, v.x) * (2.0 / PI);
  if (tt < 0.0) tt += 4.0;
  if (tt >= 4.0) tt -= 4.0;
  float n = float(nside);
  if (za <= 2.0 / 3.0) {
    int nl4 = 4 * nside;
    float t1 = n * (0.5 + tt), t2 = n * (cz * 0.75);
    int jp = int(t1 - t2), jm = int(t1 + t2);
    int ir = nside + 1 + jp - jm;
    int kshift = 1 - (ir & 1);
    int ip = ((jp + jm - nside + kshift + 1 + 2 * nl4) / 2) % nl4;
    return 2 * nside * (nside - 1) + (ir - 1) * nl4 + ip;
  }
  float tp = tt - float(int(tt));
  float tmp = n * ((rxy / nrm) / sqrt((1.0 + za) / 3.0));
  int jp = int(tp * tmp), jm = int((1.0 - tp) * tmp);
  int ir = jp + jm + 1;
  int ip = int(tt * float(ir));
  if (ip >= 4 * ir) ip = 4 * ir - 1;
  return cz > 0.0 ? 2 * ir * (ir - 1) + ip : 12 * nside * nside - 2 * ir * (ir + 1) + ip;
}

float valueAt(Layer L, vec3 d) {
  int p = vec2pix(L.nside, d);
  return texelFetch(L.map, ivec2(p % L.texW, p / L.texW), 0).r;
}

// colour.js: position()
float position(Layer L, float v) {
  if (L.mode == 3) return clamp(0.5 + 0.5 * v / max(abs(L.lo), abs(L.hi)), 0.0, 1.0);
  if (v == 0.0) return -1.0;
  if (L.mode == 1) {
    if (v <= 0.0 || L.lo <= 0.0) return -1.0;
    float t = (log(v) - log(L.lo)) / max(1e-12, log(L.hi) - log(L.lo));
    return 0.08 + 0.92 * clamp(t, 0.0, 1.0);
  }
  if (L.mode == 2) {
    int a = 0, b = 256;
    for (int i = 0; i < 9; ++i) {
      int m = (a + b) / 2;
      if (v >= texelFetch(uEdges, ivec2(m, 0), 0).r) a = m; else b = m;
    }
    return 0.08 + 0.92 * (float(a) / 256.0);
  }
  return clamp((v - L.lo) / max(1e-30, L.hi - L.lo), 0.0, 1.0);
}

bool inRegion(vec3 d) {
  if (uRegion == 0) return dot(d, uCap.xyz) >= uCap.w;
  float lon = atan(d.y, d.x);
  if (lon < 0.0) lon += 2.0 * PI;
  if (lon < uBox.x) lon += 2.0 * PI;
  float lat = asin(clamp(d.z, -1.0, 1.0));
  return lon <= uBox.y && lat >= uBox.z && lat <= uBox.w;
}

void main() {
  vec2 s = gl_FragCoord.xy / uDpr;
  s.y = uSize.y - s.y;
  vec3 d;
  if (!screenToDir(s, d)) { outColour = vec4(0.06, 0.06, 0.08, 1.0); return; }
  float t;
  if (uLayerOn && inRegion(d)) t = position(uLayer, valueAt(uLayer, d));
  else t = position(uBase, valueAt(uBase, d));
  outColour = texelFetch(uLut, ivec2(int(clamp(t, 0.0, 1.0) * 255.0 + 0.5), 0), 0);
}`;

  const TEX_WIDTH = 4096;

  class Renderer {
    constructor(canvas) {
      this.canvas = canvas;
      const gl = canvas.getContext("webgl2", { preserveDrawingBuffer: true, antialias: false });
      if (!gl) throw new Error("this browser gives no WebGL2 context (needed to draw the map)");
      this.gl = gl;
      this.prog = this.program(VERT, FRAG);
      const buf = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, buf);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
      this.vao = gl.createVertexArray();
      gl.bindVertexArray(this.vao);
      const loc = gl.getAttribLocation(this.prog, "aPos");
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, 2, gl.FLOAT, false, 0, 0);
      this.u = {};
      const n = gl.getProgramParameter(this.prog, gl.ACTIVE_UNIFORMS);
      for (let i = 0; i < n; ++i) {
        const name = gl.getActiveUniform(this.prog, i).name;
        this.u[name] = gl.getUniformLocation(this.prog, name);
      }
      this.textures = {};
      this.lutName = null;
    }
    program(vs, fs) {
      const gl = this.gl;
      const compile = (type, src) => {
        const s = gl.createShader(type);
        gl.shaderSource(s, src);
        gl.compileShader(s);
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error("shader: " + gl.getShaderInfoLog(s));
        return s;
      };
      const p = gl.createProgram();
      gl.attachShader(p, compile(gl.VERTEX_SHADER, vs));
      gl.attachShader(p, compile(gl.FRAGMENT_SHADER, fs));
      gl.linkProgram(p);
      if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error("shader link: " + gl.getProgramInfoLog(p));
      return p;
    }
    floatTexture(unit, name, values, width) {
      const gl = this.gl;
      const w = Math.min(width, values.length), h = Math.ceil(values.length / w);
      let data = values;
      if (!(values instanceof Float32Array) || values.length !== w * h) {
        data = new Float32Array(w * h);
        data.set(values);
      }
      let tex = this.textures[name];
      if (!tex) tex = this.textures[name] = gl.createTexture();
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, tex);
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.R32F, w, h, 0, gl.RED, gl.FLOAT, data);
      for (const p of [gl.TEXTURE_MIN_FILTER, gl.TEXTURE_MAG_FILTER]) gl.texParameteri(gl.TEXTURE_2D, p, gl.NEAREST);
      return w;
    }
    // the map of a layer ("base" or "layer"): a Float32Array in RING order
    setMap(which, values, nside) {
      const unit = which === "base" ? 0 : 1;
      this[which] = { nside, texW: this.floatTexture(unit, which, values, TEX_WIDTH), values };
    }
    clearLayer() { this.layer = null; }
    setColours(name) {
      if (name === this.lutName) return;
      const gl = this.gl;
      this.lutName = name;
      if (!this.textures.lut) this.textures.lut = gl.createTexture();
      gl.activeTexture(gl.TEXTURE2);
      gl.bindTexture(gl.TEXTURE_2D, this.textures.lut);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 256, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, AW.colour.table(name));
      for (const p of [gl.TEXTURE_MIN_FILTER, gl.TEXTURE_MAG_FILTER]) gl.texParameteri(gl.TEXTURE_2D, p, gl.NEAREST);
    }
    setEdges(edges) { this.floatTexture(3, "edges", edges, 257); }
    resize() {
      const dpr = window.devicePixelRatio || 1;
      const w = Math.max(1, Math.round(this.canvas.clientWidth * dpr)), h = Math.max(1, Math.round(this.canvas.clientHeight * dpr));
      if (this.canvas.width !== w || this.canvas.height !== h) { this.canvas.width = w; this.canvas.height = h; }
      return dpr;
    }
    static modeOf(scale) { return scale.signed ? 3 : { linear: 0, log: 1, histeq: 2 }[scale.mode] ?? 1; }
    // view: {proj, lon, lat, zoom}; scale: the base map's; layer: {scale, region} or null
    draw(view, scale, layer) {
      const gl = this.gl, u = this.u;
      const dpr = this.resize();
      const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
      gl.viewport(0, 0, this.canvas.width, this.canvas.height);
      gl.useProgram(this.prog);
      gl.bindVertexArray(this.vao);
      const f = AW.geo.frame(view.lon, view.lat);
      gl.uniform1i(u.uProj, { ortho: 0, gnomonic: 1, mollweide: 2 }[view.proj]);
      gl.uniformMatrix3fv(u.uFrame, false, new Float32Array([...f.e, ...f.n, ...f.c]));
      gl.uniform1f(u.uUnits, AW.geo.unitsPerPixel(view, w, h));
      gl.uniform2f(u.uSize, w, h);
      gl.uniform1f(u.uDpr, dpr);
      gl.uniform1i(u.uLut, 2);
      gl.uniform1i(u.uEdges, 3);
      const setLayer = (prefix, unit, L, sc) => {
        gl.uniform1i(u[prefix + ".map"], unit);
        gl.uniform1i(u[prefix + ".nside"], L.nside);
        gl.uniform1i(u[prefix + ".texW"], L.texW);
        gl.uniform1i(u[prefix + ".mode"], Renderer.modeOf(sc));
        gl.uniform1f(u[prefix + ".lo"], sc.lo);
        gl.uniform1f(u[prefix + ".hi"], sc.hi);
      };
      setLayer("uBase", 0, this.base, scale);
      const on = !!(layer && this.layer);
      gl.uniform1i(u.uLayerOn, on ? 1 : 0);
      // a sampler must name a texture of its type even when unused
      setLayer("uLayer", on ? 1 : 0, on ? this.layer : this.base, on ? layer.scale : scale);
      if (on) {
        const r = layer.region;
        if (r.kind === "cap") {
          const c = AW.geo.direction(r.center[0], r.center[1]);
          gl.uniform1i(u.uRegion, 0);
          gl.uniform4f(u.uCap, c[0], c[1], c[2], Math.cos(r.radius * AW.geo.D2R));
        } else {
          let a = ((r.lon[0] % 360) + 360) % 360;
          gl.uniform1i(u.uRegion, 1);
          gl.uniform4f(u.uBox, a * AW.geo.D2R, (a + r.lon[1] - r.lon[0]) * AW.geo.D2R, r.lat[0] * AW.geo.D2R, r.lat[1] * AW.geo.D2R);
        }
      }
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }
  }
  return Renderer;
})();
