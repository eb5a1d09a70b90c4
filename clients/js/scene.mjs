// Decoder for rulemesh's `scene` format (application/vnd.rulemesh.scene,
// .rmscene), specified byte by byte in docs/scene-format.md. Reads versions
// 1 and 2. Dependency-free ES module.
//
// The decoder tessellates every primitive instance (primitives.mjs) and
// places it with the arithmetic of rulemesh's mesher (src/mesh/mod.rs,
// glam's f32 Mat3 and Quat, f64 DQuat for hierarchies), each float32
// operation emulated with Math.fround, so the meshes it returns are the
// flat glTF's meshes bit for bit: same positions, normals, colours and
// indices, in the same order.
//
// Every length and offset is checked; damaged input throws a SceneError,
// never reads out of bounds, and never allocates more than the payload's
// size (or the caller's triangle limit) justifies.

import { prototype, triangleCount, MIN_DETAIL, MAX_DETAIL } from './primitives.mjs';

/** Thrown for any payload that is not a valid scene file. */
export class SceneError extends Error {
  constructor(message) {
    super(message);
    this.name = 'SceneError';
  }
}

const FLAG_TRUNCATED = 1;
const FLAG_PROVENANCE = 2;
const FLAG_SCALED = 4; // version 2: hierarchy entries carry an f64 uniform scale (MDG)
const SHAPE_BIT = 0x80000000;
const RUN_PRIMITIVES = 1, RUN_AFFINE = 2, RUN_PLACED = 3, RUN_MESH = 4, RUN_HIERARCHY = 5;
const PARITY_BIT = 0x80;
const f = Math.fround;

/** Little-endian cursor; every read is bounds-checked. */
class Reader {
  constructor(bytes) {
    this.b = bytes;
    this.v = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    this.at = 0;
  }
  need(n) {
    if (n < 0 || this.at + n > this.b.length) throw new SceneError('scene file is truncated');
  }
  room(count, each) {
    if (count * Math.max(each, 1) > this.b.length - this.at) throw new SceneError('scene file is truncated');
  }
  u8() { this.need(1); return this.b[this.at++]; }
  u16() { this.need(2); const x = this.v.getUint16(this.at, true); this.at += 2; return x; }
  u32() { this.need(4); const x = this.v.getUint32(this.at, true); this.at += 4; return x; }
  f32() { this.need(4); const x = this.v.getFloat32(this.at, true); this.at += 4; return x; }
  f64() { this.need(8); const x = this.v.getFloat64(this.at, true); this.at += 8; return x; }
  bytes(n) { this.need(n); const s = this.b.subarray(this.at, this.at + n); this.at += n; return s; }
  f32s(n) { const a = new Array(n); for (let i = 0; i < n; i++) a[i] = this.f32(); return a; }
}

const decoder = new TextDecoder('utf-8', { fatal: true });
/** Strict UTF-8 (a SceneError on malformed text). */
function utf8(b) {
  try {
    return decoder.decode(b);
  } catch {
    throw new SceneError('text is not UTF-8');
  }
}

function finite(a) {
  for (const x of a) if (!Number.isFinite(x)) throw new SceneError('non-finite number in scene');
  return a;
}

// ---- glam's f32 arithmetic, emulated ----

/** glam Mat3::from_quat in f32: columns as one 9-array (x, y, z axes). */
function matFromQuat(x, y, z, w) {
  const x2 = f(x + x), y2 = f(y + y), z2 = f(z + z);
  const xx = f(x * x2), xy = f(x * y2), xz = f(x * z2);
  const yy = f(y * y2), yz = f(y * z2), zz = f(z * z2);
  const wx = f(w * x2), wy = f(w * y2), wz = f(w * z2);
  return [
    f(1 - f(yy + zz)), f(xy + wz), f(xz - wy),
    f(xy - wz), f(1 - f(xx + zz)), f(yz + wx),
    f(xz + wy), f(yz - wx), f(1 - f(xx + yy)),
  ];
}

/** The (linear, normal matrix, translation) of a similarity placement, as mesh::instance_map. */
function similarityMap(t, q, s, parity) {
  const r = matFromQuat(q[0], q[1], q[2], q[3]);
  const sign = parity ? -1 : 1;
  const k = f(sign * s);
  return { linear: r.map((m) => f(m * k)), normal: r.map((m) => f(m * sign)), t, flip: parity };
}

/** The (linear, cofactor normal matrix, translation) of an affine placement, as AffineInstance. */
function affineMap(m, t) {
  const [ax, ay, az, bx, by, bz, cx, cy, cz] = m;
  const crossf = (px, py, pz, qx, qy, qz) => [f(f(py * qz) - f(qy * pz)), f(f(pz * qx) - f(qz * px)), f(f(px * qy) - f(qx * py))];
  const bc = crossf(bx, by, bz, cx, cy, cz);
  const ca = crossf(cx, cy, cz, ax, ay, az);
  const ab = crossf(ax, ay, az, bx, by, bz);
  const det = f(f(f(ax * bc[0]) + f(ay * bc[1])) + f(az * bc[2]));
  const parity = det < 0;
  let normal = [...bc, ...ca, ...ab];
  if (parity) normal = normal.map((x) => f(x * -1));
  return { linear: m, normal, t, flip: parity };
}

/** Growable output mesh with typed arrays. */
class MeshOut {
  constructor(name, vertices, triangles) {
    this.name = name;
    this.positions = new Float32Array(3 * vertices);
    this.normals = new Float32Array(3 * vertices);
    this.colours = new Uint8Array(4 * vertices);
    this.indices = new Uint32Array(3 * triangles);
    this.nv = 0;
    this.ni = 0;
  }
  finish() {
    const { name, nv, ni } = this;
    return { name, positions: this.positions.subarray(0, 3 * nv), normals: this.normals.subarray(0, 3 * nv), colours: this.colours.subarray(0, 4 * nv), indices: this.indices.subarray(0, ni) };
  }
}

/** mesh::append_mapped: the prototype through the map, glam's operation order. */
function appendMapped(out, proto, map, colour) {
  const { linear: L, normal: N, t, flip } = map;
  const P = proto.positions, Q = proto.normals, I = proto.indices;
  const base = out.nv;
  const op = out.positions, on = out.normals, oc = out.colours;
  const n = P.length / 3;
  for (let k = 0; k < n; k++) {
    const px = P[3 * k], py = P[3 * k + 1], pz = P[3 * k + 2];
    const o = 3 * (base + k);
    // Mat3 * Vec3: x_axis·px, + y_axis·py, + z_axis·pz; then + translation.
    op[o] = f(f(f(f(L[0] * px) + f(L[3] * py)) + f(L[6] * pz)) + t[0]);
    op[o + 1] = f(f(f(f(L[1] * px) + f(L[4] * py)) + f(L[7] * pz)) + t[1]);
    op[o + 2] = f(f(f(f(L[2] * px) + f(L[5] * py)) + f(L[8] * pz)) + t[2]);
    const nx = Q[3 * k], ny = Q[3 * k + 1], nz = Q[3 * k + 2];
    const mx = f(f(f(N[0] * nx) + f(N[3] * ny)) + f(N[6] * nz));
    const my = f(f(f(N[1] * nx) + f(N[4] * ny)) + f(N[7] * nz));
    const mz = f(f(f(N[2] * nx) + f(N[5] * ny)) + f(N[8] * nz));
    // Vec3::try_normalize, else +Z.
    const rcp = f(1 / f(Math.sqrt(f(f(f(mx * mx) + f(my * my)) + f(mz * mz)))));
    if (Number.isFinite(rcp) && rcp > 0) {
      on[o] = f(mx * rcp); on[o + 1] = f(my * rcp); on[o + 2] = f(mz * rcp);
    } else {
      on[o] = 0; on[o + 1] = 0; on[o + 2] = 1;
    }
    const c = 4 * (base + k);
    oc[c] = colour[0]; oc[c + 1] = colour[1]; oc[c + 2] = colour[2]; oc[c + 3] = colour[3];
  }
  const oi = out.indices;
  let w = out.ni;
  for (let k = 0; k < I.length; k += 3) {
    oi[w++] = base + I[k];
    if (flip) { oi[w++] = base + I[k + 2]; oi[w++] = base + I[k + 1]; } else { oi[w++] = base + I[k + 1]; oi[w++] = base + I[k + 2]; }
  }
  out.nv = base + n;
  out.ni = w;
}

// ---- hierarchies (f64, glam's DQuat) ----

function quatMulVec(r, v) {
  const [bx, by, bz, w] = r;
  const b2 = bx * bx + by * by + bz * bz;
  const k1 = w * w - b2;
  const k2 = (v[0] * bx + v[1] * by + v[2] * bz) * 2.0;
  const k3 = w * 2.0;
  const cx = by * v[2] - v[1] * bz, cy = bz * v[0] - v[2] * bx, cz = bx * v[1] - v[0] * by;
  return [v[0] * k1 + bx * k2 + cx * k3, v[1] * k1 + by * k2 + cy * k3, v[2] * k1 + bz * k2 + cz * k3];
}

function quatMul(a, b) {
  const [x0, y0, z0, w0] = a, [x1, y1, z1, w1] = b;
  return [
    w0 * x1 + x0 * w1 + y0 * z1 - z0 * y1,
    w0 * y1 - x0 * z1 + y0 * w1 + z0 * x1,
    w0 * z1 + x0 * y1 - y0 * x1 + z0 * w1,
    w0 * w1 - x0 * x1 - y0 * y1 - z0 * z1,
  ];
}

function quatNormalize(q) {
  const r = 1.0 / Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return [q[0] * r, q[1] * r, q[2] * r, q[3] * r];
}

/** glam Quat::normalize in f32. */
function quatNormalizeF32(q) {
  const d = f(f(f(f(q[0] * q[0]) + f(q[1] * q[1])) + f(q[2] * q[2])) + f(q[3] * q[3]));
  const r = f(1 / f(Math.sqrt(d)));
  return [f(q[0] * r), f(q[1] * r), f(q[2] * r), f(q[3] * r)];
}

/** A leaf shape's prototype: the primitive scaled and offset in f32, normals by the inverse scale (LeafShape::prototype). */
function leafPrototype(shape, detail) {
  const d = shape.tube ? Math.max(Math.floor(detail / 2), 4) : detail;
  const p = prototype(shape.kind, d);
  // A bare primitive (MDG's leaves, LeafShape::is_bare) is used untouched.
  const bare = !shape.tube && shape.scale.every((x) => x === 1) && shape.offset.every((x) => x === 0);
  if (bare) return p;
  const [sx, sy, sz] = shape.scale, [ox, oy, oz] = shape.offset;
  const positions = new Float32Array(p.positions.length);
  const normals = new Float32Array(p.normals.length);
  const inv = (s) => (s === 0 ? 0 : f(1 / s));
  const ix = inv(sx), iy = inv(sy), iz = inv(sz);
  for (let k = 0; k < positions.length; k += 3) {
    positions[k] = f(f(p.positions[k] * sx) + ox);
    positions[k + 1] = f(f(p.positions[k + 1] * sy) + oy);
    positions[k + 2] = f(f(p.positions[k + 2] * sz) + oz);
    const mx = f(p.normals[k] * ix), my = f(p.normals[k + 1] * iy), mz = f(p.normals[k + 2] * iz);
    const rcp = f(1 / f(Math.sqrt(f(f(f(mx * mx) + f(my * my)) + f(mz * mz)))));
    const ok = Number.isFinite(rcp) && rcp > 0;
    normals[k] = ok ? f(mx * rcp) : 0;
    normals[k + 1] = ok ? f(my * rcp) : 0;
    normals[k + 2] = ok ? f(mz * rcp) : 0;
  }
  return { positions, normals, indices: p.indices };
}

/** Leaves of the hierarchy's expansion, in drawing order (Hierarchy::walk). */
function walk(h, leaf) {
  const root = h.objects.length - 1;
  if (root < 0) return;
  // Frame::then: t + s·(r·t'), (r·r')‾, s·s' (s = 1 in rigid hierarchies: exact).
  const stack = [[root, 0, [0, 0, 0], [0, 0, 0, 1], 1]];
  while (stack.length) {
    const top = stack[stack.length - 1];
    const [object, next, t, r, s] = top;
    const entries = h.objects[object];
    if (next >= entries.length) { stack.pop(); continue; }
    top[1]++;
    const e = entries[next];
    const rv = quatMulVec(r, e.t);
    const translation = [t[0] + s * rv[0], t[1] + s * rv[1], t[2] + s * rv[2]];
    const rotation = quatNormalize(quatMul(r, e.q));
    const scale = s * e.s;
    if (e.shape >= 0) leaf(e.shape, translation, rotation, e.colour, scale);
    else if (e.object < object) stack.push([e.object, 0, translation, rotation, scale]);
  }
}

/** Leaves and triangles of the expansion (saturating at 2^53). */
function expansionTriangles(h, detail) {
  const leaves = new Array(h.objects.length).fill(null);
  let total = 0;
  const shapeTris = h.shapes.map((s) => triangleCount(s.kind, s.tube ? Math.max(Math.floor(detail / 2), 4) : detail));
  for (let o = 0; o < h.objects.length; o++) {
    let t = 0;
    for (const e of h.objects[o]) t += e.shape >= 0 ? shapeTris[e.shape] : leaves[e.object];
    leaves[o] = t;
    total = t;
  }
  return total;
}

/** Leaves of the root's expansion (Hierarchy::leaves). */
function leafCount(h) {
  const leaves = [];
  for (const entries of h.objects) leaves.push(entries.reduce((n, e) => n + (e.shape >= 0 ? 1 : leaves[e.object]), 0));
  return leaves.length ? leaves[leaves.length - 1] : 0;
}

function readHierarchy(r, nshapes, nobjects, wide, scaled = false) {
  r.room(nshapes, 28);
  r.room(nobjects, 4);
  const shapes = [];
  for (let i = 0; i < nshapes; i++) {
    const kind = r.u8(), flags = r.u8();
    r.u16();
    if (kind > 8) throw new SceneError(`unknown primitive kind ${kind}`);
    shapes.push({ kind, tube: (flags & 1) !== 0, scale: finite(r.f32s(3)), offset: finite(r.f32s(3)) });
  }
  const objects = [];
  for (let o = 0; o < nobjects; o++) {
    const n = r.u32();
    r.room(n, wide ? (scaled ? 72 : 64) : 36);
    const entries = [];
    for (let k = 0; k < n; k++) {
      const raw = r.u32();
      const t = finite(wide ? [r.f64(), r.f64(), r.f64()] : r.f32s(3));
      const q = finite(wide ? [r.f64(), r.f64(), r.f64(), r.f64()] : r.f32s(4));
      const s = scaled ? r.f64() : 1;
      if (!(Number.isFinite(s) && s > 0)) throw new SceneError('non-finite number in scene');
      const colour = r.bytes(4);
      const isShape = raw >= SHAPE_BIT;
      const idx = isShape ? raw - SHAPE_BIT : raw;
      if (isShape ? idx >= nshapes : idx >= o) throw new SceneError(`object ${o} refers to ${raw}, which is not an earlier object or a known shape`);
      entries.push({ shape: isShape ? idx : -1, object: isShape ? -1 : idx, t, q, s, colour });
    }
    objects.push(entries);
  }
  return { shapes, objects };
}

function readHeader(r) {
  const m = r.bytes(4);
  if (m[0] !== 0x52 || m[1] !== 0x4d || m[2] !== 0x53 || m[3] !== 0x43) throw new SceneError('not a rulemesh scene file');
  const version = r.u16();
  if (version !== 1 && version !== 2) throw new SceneError(`unknown scene version ${version}`);
  const flags = r.u16();
  if (flags & ~(FLAG_TRUNCATED | FLAG_PROVENANCE | (version === 2 ? FLAG_SCALED : 0))) throw new SceneError('unknown flag bits');
  let detail = null, counts;
  if (version === 1) {
    counts = [r.u32(), r.u32()];
    r.bytes(8);
  } else {
    detail = r.u16();
    if (detail < MIN_DETAIL || detail > MAX_DETAIL) throw new SceneError('detail out of range');
    if (r.u16() !== 0) throw new SceneError('reserved bytes are not zero');
    counts = [r.u32(), r.u32()];
  }
  let provenance = null;
  if (flags & FLAG_PROVENANCE) {
    try {
      provenance = JSON.parse(utf8(r.bytes(r.u32())));
    } catch (e) {
      if (e instanceof SceneError) throw e;
      throw new SceneError('provenance is not UTF-8 JSON');
    }
    if (provenance === null || typeof provenance !== 'object' || Array.isArray(provenance)) throw new SceneError('provenance is not a JSON object');
  }
  return { version, flags, detail, counts, provenance };
}

function readMesh(r, withColours) {
  const v = r.u32(), t = r.u32();
  r.room(v, withColours ? 28 : 24);
  r.room(t, 12);
  const positions = new Float32Array(3 * v), normals = new Float32Array(3 * v);
  for (let k = 0; k < 3 * v; k++) positions[k] = r.f32();
  finite(positions);
  for (let k = 0; k < 3 * v; k++) normals[k] = r.f32();
  const colours = withColours ? r.bytes(4 * v).slice() : null;
  const indices = new Uint32Array(3 * t);
  for (let k = 0; k < 3 * t; k++) {
    const i = r.u32();
    if (i >= v) throw new SceneError('index beyond the vertices');
    indices[k] = i;
  }
  return { positions, normals, colours, indices };
}

/** Parses version 2 after the header: palette, prototypes, hierarchy, meshes with their runs. */
function parseV2(r, header) {
  const [ncolours, nprotos] = header.counts;
  r.room(ncolours, 4);
  const palette = [];
  for (let i = 0; i < ncolours; i++) palette.push(r.bytes(4));
  r.room(nprotos, 8);
  const protos = [];
  for (let i = 0; i < nprotos; i++) protos.push(readMesh(r, false));
  const hierarchy = readHierarchy(r, r.u32(), r.u32(), true, (header.flags & FLAG_SCALED) !== 0);
  const w = ncolours <= 256 ? 1 : ncolours <= 65536 ? 2 : 4;
  const colour = () => {
    const i = w === 1 ? r.u8() : w === 2 ? r.u16() : r.u32();
    if (i >= palette.length) throw new SceneError('colour index beyond the palette');
    return palette[i];
  };
  const nmeshes = r.u32();
  r.room(nmeshes, 6);
  const meshes = [];
  for (let mi = 0; mi < nmeshes; mi++) {
    const name = utf8(r.bytes(r.u16()));
    const nruns = r.u32();
    r.room(nruns, 5);
    const runs = [];
    for (let k = 0; k < nruns; k++) {
      const type = r.u8(), n = r.u32();
      if (type === RUN_PRIMITIVES || type === RUN_AFFINE || type === RUN_PLACED) {
        r.room(n, 33);
        const records = [];
        for (let i = 0; i < n; i++) {
          if (type === RUN_PRIMITIVES) {
            const code = r.u8();
            const kind = code & ~PARITY_BIT;
            if (kind > 8) throw new SceneError(`unknown primitive kind ${kind}`);
            const c = colour();
            const t = finite(r.f32s(3)), q = finite(r.f32s(4)), s = finite(r.f32s(1))[0];
            records.push({ kind, colour: c, map: similarityMap(t, q, s, (code & PARITY_BIT) !== 0) });
          } else if (type === RUN_AFFINE) {
            const kind = r.u8();
            if (kind > 8) throw new SceneError(`unknown primitive kind ${kind}`);
            const c = colour();
            const m = finite(r.f32s(9)), t = finite(r.f32s(3));
            records.push({ kind, colour: c, map: affineMap(m, t) });
          } else {
            const shape = r.u32();
            if (shape >= nprotos) throw new SceneError('placement of a prototype that does not exist');
            const parity = r.u8() !== 0;
            const c = colour();
            const t = finite(r.f32s(3)), q = finite(r.f32s(4)), s = finite(r.f32s(1))[0];
            records.push({ proto: protos[shape], colour: c, map: similarityMap(t, q, s, parity) });
          }
        }
        runs.push({ records });
      } else if (type === RUN_MESH && n === 1) {
        runs.push({ mesh: readMesh(r, true) });
      } else if (type === RUN_HIERARCHY && n === 1) {
        runs.push({ hierarchy: true });
      } else {
        throw new SceneError('unknown run type or count');
      }
    }
    meshes.push({ name, runs });
  }
  return { hierarchy, meshes };
}

/**
 * Decodes a scene file (Uint8Array) into the meshes rulemesh's flat glTF
 * holds for the same request: { version, detail, truncated, provenance,
 * meshes: [{ name, positions, normals (Float32Array, 3 per vertex), colours
 * (Uint8Array, linear RGBA), indices (Uint32Array, TRIANGLES) }] }.
 * Options: `detail` for version 1 files (which do not record theirs; 16 by
 * default), `maxTriangles` (default 50 million) refused before any work.
 */
export function decodeScene(bytes, { detail: v1Detail = 16, maxTriangles = 50e6 } = {}) {
  if (!(bytes instanceof Uint8Array)) throw new TypeError('decodeScene expects a Uint8Array');
  const r = new Reader(bytes);
  const header = readHeader(r);
  let parsed, detail;
  if (header.version === 1) {
    const hierarchy = readHierarchy(r, header.counts[0], header.counts[1], false);
    parsed = { hierarchy, meshes: leafCount(hierarchy) > 0 ? [{ name: 'isosurfaces', runs: [{ hierarchy: true }] }] : [] };
    detail = Math.min(Math.max(v1Detail, MIN_DETAIL), MAX_DETAIL);
  } else {
    parsed = parseV2(r, header);
    detail = header.detail;
  }
  if (r.at !== bytes.length) throw new SceneError('scene file is followed by trailing bytes');
  // Sizes first: refuse, then allocate each mesh once.
  const h = parsed.hierarchy;
  const leafProtos = [];
  const leafProto = (s) => leafProtos[s] || (leafProtos[s] = leafPrototype(h.shapes[s], detail));
  let total = 0;
  const sizes = parsed.meshes.map(({ runs }) => {
    let v = 0, t = 0;
    for (const run of runs) {
      if (run.records) {
        for (const rec of run.records) {
          const p = rec.proto || prototype(rec.kind, detail);
          v += p.positions.length / 3;
          t += p.indices.length / 3;
        }
      } else if (run.mesh) {
        v += run.mesh.positions.length / 3;
        t += run.mesh.indices.length / 3;
      } else {
        const tris = expansionTriangles(h, detail);
        if (tris > maxTriangles) throw new SceneError(`scene expands to ${tris} triangles, more than allowed`);
        // Vertices per leaf: count by walking the objects' leaf multiplicities.
        const counts = new Array(h.objects.length);
        for (let o = 0; o < h.objects.length; o++) {
          let verts = 0;
          for (const e of h.objects[o]) verts += e.shape >= 0 ? leafProto(e.shape).positions.length / 3 : counts[e.object];
          counts[o] = verts;
        }
        v += counts[counts.length - 1] || 0;
        t += tris;
      }
    }
    total += t;
    if (total > maxTriangles) throw new SceneError(`scene expands to more than ${maxTriangles} triangles`);
    return [v, t];
  });
  const meshes = parsed.meshes.map(({ name, runs }, mi) => {
    const out = new MeshOut(name, sizes[mi][0], sizes[mi][1]);
    for (const run of runs) {
      if (run.records) {
        for (const rec of run.records) appendMapped(out, rec.proto || prototype(rec.kind, detail), rec.map, rec.colour);
      } else if (run.mesh) {
        const m = run.mesh, base = out.nv;
        out.positions.set(m.positions, 3 * base);
        out.normals.set(m.normals, 3 * base);
        out.colours.set(m.colours, 4 * base);
        for (let k = 0; k < m.indices.length; k++) out.indices[out.ni++] = base + m.indices[k];
        out.nv += m.positions.length / 3;
      } else {
        walk(h, (shape, t, q, colour, scale) => {
          // Instance::new: translation, rotation and scale rounded to f32, the rotation renormalised in f32.
          const tf = [f(t[0]), f(t[1]), f(t[2])];
          const qf = quatNormalizeF32([f(q[0]), f(q[1]), f(q[2]), f(q[3])]);
          const sf = f(scale);
          if (!tf.every(Number.isFinite) || !qf.every(Number.isFinite) || !Number.isFinite(sf) || sf === 0) return;
          appendMapped(out, leafProto(shape), similarityMap(tf, qf, sf, false), colour);
        });
      }
    }
    return out.finish();
  });
  return { version: header.version, detail, truncated: (header.flags & FLAG_TRUNCATED) !== 0, provenance: header.provenance, meshes };
}
