// Tessellation of rulemesh's nine built-in primitives, ported line by line
// from src/geom/primitives.rs so that every position and normal is the same
// float32 the server computes: the geometry is built in float64 (JavaScript
// numbers, the Rust code's f64) with the same operations in the same order,
// and rounded to float32 once (Math.fround), as the Rust `to_f32` does.
// Dependency-free ES module.

/** Primitive kinds in the order of the format's kind codes. */
export const KINDS = ['box', 'sphere', 'cylinder', 'cone', 'torus', 'tetrahedron', 'octahedron', 'icosahedron', 'dodecahedron'];

export const MIN_DETAIL = 3;
export const MAX_DETAIL = 256;
const TORUS_MAJOR = 0.375;
const TORUS_MINOR = 0.125;
const PI = Math.PI;
const f32 = Math.fround;

const clampDetail = (d) => Math.min(Math.max(d, MIN_DETAIL), MAX_DETAIL);
const sphereBands = (d) => Math.max(Math.floor(d / 2), 2);
const torusTube = (d) => Math.max(Math.floor(d / 2), 3);

/** Triangle count of tessellate(kind, detail), without tessellating. */
export function triangleCount(kind, detail) {
  const d = clampDetail(detail);
  switch (kind) {
    case 0: return 12;
    case 1: return 2 * d * (sphereBands(d) - 1);
    case 2: return 4 * d;
    case 3: return 2 * d;
    case 4: return 2 * d * torusTube(d);
    case 5: return 4;
    case 6: return 8;
    case 7: return 20;
    case 8: return 36;
    default: throw new RangeError(`unknown primitive kind ${kind}`);
  }
}

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
function normalize(a) {
  const l = Math.sqrt(dot(a, a));
  return l > 0 ? [a[0] / l, a[1] / l, a[2] / l] : a;
}
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];

/** Growable builder: float32 positions and normals, uint32 indices. */
class Builder {
  constructor(v, t) {
    this.positions = new Float32Array(3 * v);
    this.normals = new Float32Array(3 * v);
    this.indices = new Uint32Array(3 * t);
    this.nv = 0;
    this.ni = 0;
  }
  // p and n are float64 triples, rounded here once.
  vertex(p, n) {
    const o = 3 * this.nv;
    this.positions[o] = p[0]; this.positions[o + 1] = p[1]; this.positions[o + 2] = p[2];
    this.normals[o] = n[0]; this.normals[o + 1] = n[1]; this.normals[o + 2] = n[2];
    return this.nv++;
  }
  tri(a, b, c) {
    this.indices[this.ni++] = a; this.indices[this.ni++] = b; this.indices[this.ni++] = c;
  }
  done() {
    return { positions: this.positions, normals: this.normals, indices: this.indices };
  }
}

function circle(d) {
  const out = [];
  for (let j = 0; j < d; j++) {
    const phi = (2.0 * PI * j) / d;
    out.push([Math.cos(phi), Math.sin(phi)]);
  }
  return out;
}
const ringPoint = ([c, s], r, y) => [r * c, y, -r * s];
// A unit normal: normalised in float64, then rounded (the Float32Array rounds).
const unit = (a) => normalize(a);
// A float32 triple as a float64 triple (so copies are bit-identical).
const round3 = (a) => [f32(a[0]), f32(a[1]), f32(a[2])];

function boxProto() {
  const b = new Builder(24, 12);
  const faces = [
    [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
    [[-1, 0, 0], [0, 0, 1], [0, 1, 0]],
    [[0, 1, 0], [0, 0, 1], [1, 0, 0]],
    [[0, -1, 0], [1, 0, 0], [0, 0, 1]],
    [[0, 0, 1], [1, 0, 0], [0, 1, 0]],
    [[0, 0, -1], [0, 1, 0], [1, 0, 0]],
  ];
  for (const [n, u, v] of faces) {
    const base = b.nv;
    for (const [su, sv] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
      b.vertex([0.5 * (n[0] + su * u[0] + sv * v[0]), 0.5 * (n[1] + su * u[1] + sv * v[1]), 0.5 * (n[2] + su * u[2] + sv * v[2])], n);
    }
    b.tri(base, base + 1, base + 2);
    b.tri(base, base + 2, base + 3);
  }
  return b.done();
}

function sphere(d) {
  const bands = sphereBands(d);
  const rings = bands - 1;
  const b = new Builder(2 + d * rings, 2 * d * rings);
  const around = circle(d);
  const north = b.vertex([0, 0.5, 0], [0, 1, 0]);
  for (let i = 1; i < bands; i++) {
    const theta = (PI * i) / bands;
    const rho = Math.sin(theta), y = Math.cos(theta);
    for (const cs of around) {
      const n = ringPoint(cs, rho, y);
      b.vertex(scale(n, 0.5), unit(n));
    }
  }
  const south = b.vertex([0, -0.5, 0], [0, -1, 0]);
  const ring = (i, j) => 1 + i * d + (j % d);
  for (let j = 0; j < d; j++) b.tri(north, ring(0, j), ring(0, j + 1));
  for (let i = 0; i < rings - 1; i++) {
    for (let j = 0; j < d; j++) {
      const a0 = ring(i, j), a1 = ring(i, j + 1), b0 = ring(i + 1, j), b1 = ring(i + 1, j + 1);
      b.tri(a0, b0, b1);
      b.tri(a0, b1, a1);
    }
  }
  for (let j = 0; j < d; j++) b.tri(ring(rings - 1, j), south, ring(rings - 1, j + 1));
  return b.done();
}

function bottomCap(b, ring) {
  const d = ring.length;
  const c = b.vertex([0, -0.5, 0], [0, -1, 0]);
  for (const p of ring) b.vertex(p, [0, -1, 0]);
  for (let j = 0; j < d; j++) b.tri(c, c + 1 + ((j + 1) % d), c + 1 + (j % d));
}

function cylinder(d) {
  const b = new Builder(4 * d + 2, 4 * d);
  const around = circle(d);
  const top = around.map((cs) => round3(ringPoint(cs, 0.5, 0.5)));
  const bottom = around.map((cs) => round3(ringPoint(cs, 0.5, -0.5)));
  around.forEach((cs, j) => b.vertex(top[j], unit(ringPoint(cs, 1.0, 0.0))));
  around.forEach((cs, j) => b.vertex(bottom[j], unit(ringPoint(cs, 1.0, 0.0))));
  const t = (j) => j % d;
  const bo = (j) => d + (j % d);
  for (let j = 0; j < d; j++) {
    b.tri(t(j), bo(j), bo(j + 1));
    b.tri(t(j), bo(j + 1), t(j + 1));
  }
  const c = b.vertex([0, 0.5, 0], [0, 1, 0]);
  for (const p of top) b.vertex(p, [0, 1, 0]);
  for (let j = 0; j < d; j++) b.tri(c, c + 1 + (j % d), c + 1 + ((j + 1) % d));
  bottomCap(b, bottom);
  return b.done();
}

function cone(d) {
  const b = new Builder(3 * d + 1, 2 * d);
  const around = circle(d);
  const base = around.map((cs) => round3(ringPoint(cs, 0.5, -0.5)));
  around.forEach((cs, j) => b.vertex(base[j], unit(ringPoint(cs, 1.0, 0.5))));
  for (let j = 0; j < d; j++) {
    const mid = (2.0 * PI * (j + 0.5)) / d;
    b.vertex([0, 0.5, 0], unit(ringPoint([Math.cos(mid), Math.sin(mid)], 1.0, 0.5)));
  }
  for (let j = 0; j < d; j++) b.tri(d + j, j, (j + 1) % d);
  bottomCap(b, base);
  return b.done();
}

function torus(d) {
  const m = torusTube(d);
  const b = new Builder(d * m, 2 * d * m);
  const around = circle(d);
  const tube = circle(m);
  for (const [cp, sp] of around) {
    for (const [ct, st] of tube) {
      const n = [ct * cp, st, -ct * sp];
      const p = [(TORUS_MAJOR + TORUS_MINOR * ct) * cp, TORUS_MINOR * st, -(TORUS_MAJOR + TORUS_MINOR * ct) * sp];
      b.vertex(p, unit(n));
    }
  }
  const v = (i, k) => (i % d) * m + (k % m);
  for (let i = 0; i < d; i++) {
    for (let k = 0; k < m; k++) {
      b.tri(v(i, k), v(i + 1, k), v(i + 1, k + 1));
      b.tri(v(i, k), v(i + 1, k + 1), v(i, k + 1));
    }
  }
  return b.done();
}

const toCircumradius = (v) => v.map((p) => scale(normalize(p), 0.5));
const golden = () => (1.0 + Math.sqrt(5)) / 2.0;

function tetrahedronVertices() {
  return toCircumradius([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]);
}
function octahedronVertices() {
  return toCircumradius([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]);
}
function icosahedronVertices() {
  const g = golden();
  const v = [];
  for (const a of [-1.0, 1.0]) {
    for (const b of [-g, g]) {
      v.push([0, a, b], [a, b, 0], [b, 0, a]);
    }
  }
  return toCircumradius(v);
}
function dodecahedronVertices() {
  const g = golden();
  const ig = 1.0 / g;
  const v = [];
  for (const x of [-1.0, 1.0]) for (const y of [-1.0, 1.0]) for (const z of [-1.0, 1.0]) v.push([x, y, z]);
  for (const a of [-ig, ig]) {
    for (const b of [-g, g]) {
      v.push([0, a, b], [a, b, 0], [b, 0, a]);
    }
  }
  return toCircumradius(v);
}

function triangleFaces(v) {
  let edge = Infinity;
  for (let i = 0; i < v.length; i++) {
    for (let j = i + 1; j < v.length; j++) {
      const d = sub(v[i], v[j]);
      edge = Math.min(edge, dot(d, d));
    }
  }
  const adjacent = (i, j) => {
    const d = sub(v[i], v[j]);
    return Math.abs(dot(d, d) - edge) < 1e-9;
  };
  const faces = [];
  for (let i = 0; i < v.length; i++) {
    for (let j = i + 1; j < v.length; j++) {
      for (let k = j + 1; k < v.length; k++) {
        if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k)) faces.push([i, j, k]);
      }
    }
  }
  return faces;
}

function dodecahedronFaces(v) {
  const g = golden();
  const axes = [];
  for (const a of [-1.0, 1.0]) {
    for (const b of [-g, g]) {
      axes.push([0, b, a], [b, a, 0], [a, 0, b]);
    }
  }
  return axes.map((axis) => {
    const best = v.reduce((m, p) => Math.max(m, dot(p, axis)), -Infinity);
    const face = [];
    for (let i = 0; i < v.length; i++) if (dot(v[i], axis) > best - 1e-9) face.push(i);
    return face;
  });
}

function flatPolyhedron(v, faces) {
  const nv = faces.reduce((s, f) => s + f.length, 0);
  const nt = faces.reduce((s, f) => s + f.length - 2, 0);
  const b = new Builder(nv, nt);
  for (const face of faces) {
    const k = face.length;
    let centre = [0, 0, 0];
    for (const i of face) centre = [centre[0] + v[i][0] / k, centre[1] + v[i][1] / k, centre[2] + v[i][2] / k];
    const n = normalize(centre);
    const u = normalize(sub(v[face[0]], centre));
    const w = cross(n, u);
    const order = face.map((i) => {
      const r = sub(v[i], centre);
      return [Math.atan2(dot(r, w), dot(r, u)), i];
    });
    order.sort((a, c) => a[0] - c[0]);
    const normal = unit(n);
    const base = b.nv;
    for (const [, i] of order) b.vertex(v[i], normal);
    for (let t = 1; t < order.length - 1; t++) b.tri(base, base + t, base + t + 1);
  }
  return b.done();
}

/**
 * Tessellates primitive `kind` (0–8, KINDS order) at `detail` (clamped to
 * 3..256; polyhedra ignore it): { positions, normals (Float32Array, 3 per
 * vertex), indices (Uint32Array, counter-clockwise outward) }, identical to
 * rulemesh's geom::primitives::tessellate.
 */
export function tessellate(kind, detail) {
  const d = clampDetail(detail);
  switch (kind) {
    case 0: return boxProto();
    case 1: return sphere(d);
    case 2: return cylinder(d);
    case 3: return cone(d);
    case 4: return torus(d);
    case 5: { const v = tetrahedronVertices(); return flatPolyhedron(v, triangleFaces(v)); }
    case 6: { const v = octahedronVertices(); return flatPolyhedron(v, triangleFaces(v)); }
    case 7: { const v = icosahedronVertices(); return flatPolyhedron(v, triangleFaces(v)); }
    case 8: { const v = dodecahedronVertices(); return flatPolyhedron(v, dodecahedronFaces(v)); }
    default: throw new RangeError(`unknown primitive kind ${kind}`);
  }
}

const cache = new Map();
/** tessellate(), memoised per (kind, detail): prototypes are read-only. */
export function prototype(kind, detail) {
  const key = kind * 1024 + clampDetail(detail);
  let p = cache.get(key);
  if (!p) {
    p = tessellate(kind, detail);
    cache.set(key, p);
  }
  return p;
}
