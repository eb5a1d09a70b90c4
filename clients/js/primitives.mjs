// Tessellation of rulemesh's nine built-in primitives: the kernel's
// `tessellate` (kernel/tessellate.c, a line-by-line port of
// src/geom/primitives.rs), so every position and normal is the same float32
// the server computes. Dependency-free ES module.
import { kernel, HEAP_BASE, reserve } from './kernel.mjs';

/** Primitive kinds in the order of the format's kind codes. */
export const KINDS = ['box', 'sphere', 'cylinder', 'cone', 'torus', 'tetrahedron', 'octahedron', 'icosahedron', 'dodecahedron'];

export const MIN_DETAIL = 3;
export const MAX_DETAIL = 256;
const clampDetail = (d) => Math.min(Math.max(d, MIN_DETAIL), MAX_DETAIL);

/** Triangle count of tessellate(kind, detail), without tessellating. */
export function triangleCount(kind, detail) {
  if (!(Number.isInteger(kind) && kind >= 0 && kind < KINDS.length)) throw new RangeError(`unknown primitive kind ${kind}`);
  return kernel.tessellation_triangles(kind, clampDetail(detail));
}

/**
 * Tessellates primitive `kind` (0–8, KINDS order) at `detail` (clamped to
 * 3..256; polyhedra ignore it): { positions, normals (Float32Array, 3 per
 * vertex), indices (Uint32Array, counter-clockwise outward) }, identical to
 * rulemesh's geom::primitives::tessellate.
 */
export function tessellate(kind, detail) {
  const t = triangleCount(kind, detail), d = clampDetail(detail);
  const v = kernel.tessellation_vertices(kind, d);
  const pos = HEAP_BASE, nrm = pos + 12 * v, idx = nrm + 12 * v;
  const buf = reserve(idx + 12 * t);
  kernel.tessellate(kind, d, pos, nrm, idx);
  return {
    positions: new Float32Array(buf, pos, 3 * v).slice(),
    normals: new Float32Array(buf, nrm, 3 * v).slice(),
    indices: new Uint32Array(buf, idx, 3 * t).slice(),
  };
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
