// Decoder for rulemesh's `scene` format (application/vnd.rulemesh.scene,
// .rmscene), specified byte by byte in docs/scene-format.md. Reads versions
// 1 and 2, with or without the CRC-32 a `checksum: true` request adds.
// Dependency-free ES module.
//
// The decoder tessellates every primitive instance (primitives.mjs) and
// places it with the arithmetic of rulemesh's mesher (src/mesh/mod.rs,
// glam's f32 Mat3 and Quat, f64 DQuat for hierarchies), so the meshes it
// returns are the flat glTF's meshes bit for bit: same positions, normals,
// colours and indices, in the same order. The float32 placement runs in a
// small WebAssembly kernel (kernel/place.c, embedded by kernel.mjs): see
// "Placement" below for why.
//
// The functions a decode runs are parenthesised function expressions
// (`const f = (function f() {...});`): V8 compiles those when the module
// loads rather than on their first call (its heuristic for functions that
// are about to run), which takes about half a millisecond off the first
// decode in a process.
//
// Every length and offset is checked; damaged input throws a SceneError,
// never reads out of bounds, and never allocates more than the payload's
// size (or the caller's triangle limit) justifies.

import { prototype, triangleCount, MIN_DETAIL, MAX_DETAIL } from './primitives.mjs';
import { kernel, HEAP_BASE, reserve } from './kernel.mjs';

/**
 * Thrown for any payload that is not a valid scene file. `code` is
 * 'checksum' when a checksummed file's CRC-32 does not match its bytes (a
 * damaged byte), else 'malformed'.
 */
export class SceneError extends Error {
  constructor(message, code = 'malformed') {
    super(message);
    this.name = 'SceneError';
    this.code = code;
  }
}

const FLAG_TRUNCATED = 1;
const FLAG_PROVENANCE = 2;
const FLAG_SCALED = 4; // version 2: hierarchy entries carry an f64 uniform scale (MDG)
const FLAG_CHECKSUM = 8; // version 2: the file ends with a CRC-32 of the bytes before it
const CHECKSUM_BYTES = 4;
const SHAPE_BIT = 0x80000000;
const RUN_PRIMITIVES = 1, RUN_AFFINE = 2, RUN_PLACED = 3, RUN_MESH = 4, RUN_HIERARCHY = 5;
const PARITY_BIT = 0x80;

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

let crcTable = null;
/**
 * CRC-32 of IEEE 802.3 (reflected polynomial 0xEDB88320, as zlib, PNG and
 * strips.mjs compute it) of `bytes`, unsigned. strips.mjs has its own copy:
 * each decoder stays loadable without the other.
 */
function crc32(bytes) {
  if (!crcTable) {
    crcTable = new Uint32Array(256);
    for (let n = 0; n < 256; n++) {
      let c = n;
      for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      crcTable[n] = c >>> 0;
    }
  }
  let c = 0xffffffff;
  for (let i = 0; i < bytes.length; i++) c = crcTable[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
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

// ---- Placement (kernel/place.c, WebAssembly) ----
//
// Placing a prototype is float32 arithmetic on every vertex (Mat3 * Vec3,
// the normal matrix, a renormalisation). A first decode runs in V8's
// interpreter, where every floating-point operation allocates a boxed
// number: about 2 µs a vertex, 4 ms for a 2 000-vertex icon. The same
// loops compiled from C cost nanoseconds, and WebAssembly's f32 operations
// are IEEE 754 binary32 without fused multiply-add, so the bits are the
// same as the emulation with Math.fround this replaced (and the server's).

/** Records' float data as the kernel reads it: similarity t, q, s (8); affine linear, t (12). */
const SIMILARITY_FLOATS = 8, AFFINE_FLOATS = 12;
/** A placement's `op` in the kernel's batch (kernel/place.c). */
const OP_SIMILARITY = 0, OP_MIRRORED = 1, OP_AFFINE = 2, OP_LEAF = 3;
/** Bytes of one placement in a batch, and placements a batch holds. */
const PLACEMENT_BYTES = 96, BATCH = 1024;

/**
 * One mesh's output, built in the kernel's memory and copied out by
 * finish(). Placements are queued in a batch there and placed by one call
 * to the kernel's place_batch per batch (each call from JavaScript into
 * WebAssembly costs microseconds while the process is cold). Meshes are
 * built one at a time, so each starts again at the kernel's heap base.
 */
class MeshOut {
  constructor(name, vertices, triangles, protos) {
    this.name = name;
    let at = HEAP_BASE;
    // The kernel's mesh_out: positions, normals, colours, indices (pointers), vertices, indices written.
    this.state = at; at += 32;
    this.pos = at; at += 12 * vertices;
    this.nrm = at; at += 12 * vertices;
    this.col = at; at += 4 * vertices;
    this.idx = at; at += 12 * triangles;
    at = (at + 15) & ~15;
    this.batch = at; at += PLACEMENT_BYTES * BATCH;
    this.protoAt = new Map();
    for (const p of protos) {
      this.protoAt.set(p, at);
      at += 4 * (p.positions.length + p.normals.length + p.indices.length);
    }
    const buf = reserve(at);
    for (const [p, off] of this.protoAt) {
      new Float32Array(buf, off, p.positions.length).set(p.positions);
      new Float32Array(buf, off + 4 * p.positions.length, p.normals.length).set(p.normals);
      new Uint32Array(buf, off + 4 * (p.positions.length + p.normals.length), p.indices.length).set(p.indices);
    }
    this.u32 = new Uint32Array(buf);
    this.f32 = new Float32Array(buf);
    this.f64 = new Float64Array(buf);
    this.u32.set([this.pos, this.nrm, this.col, this.idx, 0, 0], this.state >> 2);
    this.queued = 0;
  }

  /** Queues `proto` placed by `op` in `colour` (an RGBA little-endian word); returns where its args go (byte offset). */
  queue(proto, op, colour) {
    if (this.queued === BATCH) this.flush();
    const at = this.batch + PLACEMENT_BYTES * this.queued++, w = at >> 2;
    const u32 = this.u32;
    u32[w] = op;
    u32[w + 1] = this.protoAt.get(proto);
    u32[w + 2] = proto.positions.length / 3;
    u32[w + 3] = proto.indices.length;
    u32[w + 4] = colour;
    return at + 32;
  }

  /** Places the queued placements. */
  flush() {
    if (this.queued) kernel.place_batch(this.batch, this.queued, this.state);
    this.queued = 0;
  }

  /** A mesh that is not an instance (a sweep, an isosurface), copied as it is. */
  appendMesh(m) {
    this.flush();
    const s = this.state >> 2, base = this.u32[s + 4], ni = this.u32[s + 5], at = this.idx + 4 * ni;
    this.f32.set(m.positions, (this.pos >> 2) + 3 * base);
    this.f32.set(m.normals, (this.nrm >> 2) + 3 * base);
    new Uint8Array(kernel.memory.buffer, this.col + 4 * base, m.colours.length).set(m.colours);
    this.u32.set(m.indices, at >> 2);
    kernel.indices(at, m.indices.length, base, 0, at);
    this.u32[s + 4] = base + m.positions.length / 3;
    this.u32[s + 5] = ni + m.indices.length;
  }

  finish() {
    this.flush();
    const buf = kernel.memory.buffer, s = this.state >> 2, nv = this.u32[s + 4], ni = this.u32[s + 5];
    return {
      name: this.name,
      positions: new Float32Array(buf, this.pos, 3 * nv).slice(),
      normals: new Float32Array(buf, this.nrm, 3 * nv).slice(),
      colours: new Uint8Array(buf, this.col, 4 * nv).slice(),
      indices: new Uint32Array(buf, this.idx, ni).slice(),
    };
  }
}

/** Queues one record of a primitives, affine or placed run. */
const appendRecord = (function appendRecord(out, proto, rec) {
  const op = rec.affine ? OP_AFFINE : rec.parity ? OP_MIRRORED : OP_SIMILARITY;
  out.f32.set(rec.data, out.queue(proto, op, rec.colour) >> 2);
});


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

/** A leaf shape's prototype: the primitive scaled and offset in f32, normals by the inverse scale (LeafShape::prototype). */
const leafPrototype = (function leafPrototype(shape, detail) {
  const d = shape.tube ? Math.max(Math.floor(detail / 2), 4) : detail;
  const p = prototype(shape.kind, d);
  // A bare primitive (MDG's leaves, LeafShape::is_bare) is used untouched.
  const bare = !shape.tube && shape.scale.every((x) => x === 1) && shape.offset.every((x) => x === 0);
  if (bare) return p;
  const n = p.positions.length, pos = HEAP_BASE, nrm = pos + 4 * n, out = nrm + 4 * n, args = out + 8 * n;
  const buf = reserve(args + 24);
  new Float32Array(buf, pos, n).set(p.positions);
  new Float32Array(buf, nrm, n).set(p.normals);
  new Float32Array(buf, args, 6).set([...shape.scale, ...shape.offset]);
  kernel.shape_prototype(pos, nrm, n / 3, args, out, out + 4 * n);
  const positions = new Float32Array(buf, out, n).slice();
  const normals = new Float32Array(buf, out + 4 * n, n).slice();
  return { positions, normals, indices: p.indices };
});


/** Leaves of the hierarchy's expansion, in drawing order (Hierarchy::walk). */
const walk = (function walk(h, leaf) {
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
});


/** Leaves and triangles of the expansion (saturating at 2^53). */
const expansionTriangles = (function expansionTriangles(h, detail) {
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
});


/** Leaves of the root's expansion (Hierarchy::leaves). */
const leafCount = (function leafCount(h) {
  const leaves = [];
  for (const entries of h.objects) leaves.push(entries.reduce((n, e) => n + (e.shape >= 0 ? 1 : leaves[e.object]), 0));
  return leaves.length ? leaves[leaves.length - 1] : 0;
});


const readHierarchy = (function readHierarchy(r, nshapes, nobjects, wide, scaled = false) {
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
      const colour = r.u32(); // RGBA bytes as one little-endian word
      const isShape = raw >= SHAPE_BIT;
      const idx = isShape ? raw - SHAPE_BIT : raw;
      if (isShape ? idx >= nshapes : idx >= o) throw new SceneError(`object ${o} refers to ${raw}, which is not an earlier object or a known shape`);
      entries.push({ shape: isShape ? idx : -1, object: isShape ? -1 : idx, t, q, s, colour });
    }
    objects.push(entries);
  }
  return { shapes, objects };
});


const readHeader = (function readHeader(r) {
  const m = r.bytes(4);
  if (m[0] !== 0x52 || m[1] !== 0x4d || m[2] !== 0x53 || m[3] !== 0x43) throw new SceneError('not a rulemesh scene file');
  const version = r.u16();
  if (version !== 1 && version !== 2) throw new SceneError(`unknown scene version ${version}`);
  const flags = r.u16();
  if (flags & ~(FLAG_TRUNCATED | FLAG_PROVENANCE | (version === 2 ? FLAG_SCALED | FLAG_CHECKSUM : 0))) throw new SceneError('unknown flag bits');
  if (flags & FLAG_CHECKSUM) {
    // Checked before anything else is read (as the Rust and C decoders do);
    // the rest is then read as if the file ended before the CRC.
    r.need(CHECKSUM_BYTES);
    const end = r.b.length - CHECKSUM_BYTES;
    const stored = r.v.getUint32(end, true), computed = crc32(r.b.subarray(0, end));
    if (stored !== computed) {
      const hex = (x) => x.toString(16).padStart(8, '0');
      throw new SceneError(`scene file is corrupted: CRC-32 is ${hex(computed)}, the file says ${hex(stored)}`, 'checksum');
    }
    r.b = r.b.subarray(0, end);
  }
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
});


const readMesh = (function readMesh(r, withColours) {
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
});


/** Parses version 2 after the header: palette, prototypes, hierarchy, meshes with their runs. */
const parseV2 = (function parseV2(r, header) {
  const [ncolours, nprotos] = header.counts;
  r.room(ncolours, 4);
  const palette = [];
  for (let i = 0; i < ncolours; i++) palette.push(r.u32()); // RGBA bytes as one little-endian word
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
            records.push({ kind, colour: c, data: new Float32Array(finite(r.f32s(SIMILARITY_FLOATS))), parity: (code & PARITY_BIT) !== 0 });
          } else if (type === RUN_AFFINE) {
            const kind = r.u8();
            if (kind > 8) throw new SceneError(`unknown primitive kind ${kind}`);
            const c = colour();
            records.push({ kind, colour: c, data: new Float32Array(finite(r.f32s(AFFINE_FLOATS))), affine: true });
          } else {
            const shape = r.u32();
            if (shape >= nprotos) throw new SceneError('placement of a prototype that does not exist');
            const parity = r.u8() !== 0;
            const c = colour();
            records.push({ proto: protos[shape], colour: c, data: new Float32Array(finite(r.f32s(SIMILARITY_FLOATS))), parity });
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
});


/**
 * Decodes a scene file (Uint8Array) into the meshes rulemesh's flat glTF
 * holds for the same request: { version, detail, truncated, provenance,
 * meshes: [{ name, positions, normals (Float32Array, 3 per vertex), colours
 * (Uint8Array, linear RGBA), indices (Uint32Array, TRIANGLES) }] }.
 * Options: `detail` for version 1 files (which do not record theirs; 16 by
 * default), `maxTriangles` (default 50 million) refused before any work.
 */
export const decodeScene = (function decodeScene(bytes, { detail: v1Detail = 16, maxTriangles = 50e6 } = {}) {
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
  if (r.at !== r.b.length) throw new SceneError('scene file is followed by trailing bytes');
  // Sizes first: refuse, then allocate each mesh once.
  const h = parsed.hierarchy;
  const leafProtos = [];
  const leafProto = (s) => leafProtos[s] || (leafProtos[s] = leafPrototype(h.shapes[s], detail));
  let total = 0;
  const sizes = parsed.meshes.map(({ runs }) => {
    let v = 0, t = 0;
    const protos = new Set(); // every prototype the mesh places, copied into the kernel once
    for (const run of runs) {
      if (run.records) {
        for (const rec of run.records) {
          const p = rec.proto || prototype(rec.kind, detail);
          protos.add(p);
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
          for (const e of h.objects[o]) {
            if (e.shape >= 0) protos.add(leafProto(e.shape));
            verts += e.shape >= 0 ? leafProto(e.shape).positions.length / 3 : counts[e.object];
          }
          counts[o] = verts;
        }
        v += counts[counts.length - 1] || 0;
        t += tris;
      }
    }
    total += t;
    if (total > maxTriangles) throw new SceneError(`scene expands to more than ${maxTriangles} triangles`);
    return [v, t, protos];
  });
  const meshes = parsed.meshes.map(({ name, runs }, mi) => {
    const out = new MeshOut(name, sizes[mi][0], sizes[mi][1], sizes[mi][2]);
    for (const run of runs) {
      if (run.records) {
        for (const rec of run.records) appendRecord(out, rec.proto || prototype(rec.kind, detail), rec);
      } else if (run.mesh) {
        out.appendMesh(run.mesh);
      } else {
        walk(h, (shape, t, q, colour, scale) => {
          // Instance::new (the kernel's OP_LEAF): rounded to f32, the rotation
          // renormalised in f32; a leaf with a non-finite value or a zero scale is dropped.
          const f64 = out.f64, at = out.queue(leafProto(shape), OP_LEAF, colour) >> 3;
          f64[at] = t[0]; f64[at + 1] = t[1]; f64[at + 2] = t[2];
          f64[at + 3] = q[0]; f64[at + 4] = q[1]; f64[at + 5] = q[2]; f64[at + 6] = q[3];
          f64[at + 7] = scale;
        });
      }
    }
    return out.finish();
  });
  return { version: header.version, detail, truncated: (header.flags & FLAG_TRUNCATED) !== 0, provenance: header.provenance, meshes };
});

