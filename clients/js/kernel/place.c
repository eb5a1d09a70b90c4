/*
 * The float32 arithmetic of rulemesh's scene decoder for JavaScript
 * (clients/js/scene.mjs), compiled to WebAssembly by scripts/build-js-kernel.
 *
 * Why C and WebAssembly: a first decode runs in V8's interpreter, where every
 * floating-point operation allocates a boxed number (about 2 µs a vertex);
 * compiled, the same loops cost nanoseconds. WebAssembly's f32 operations are
 * IEEE 754 binary32 with round-to-nearest and no fused multiply-add, and this
 * file is compiled with -ffp-contract=off, so each expression below gives the
 * bits the server's glam code gives (src/mesh/, the operation order noted at
 * each function). Freestanding: no libc, no static data, no allocation; the
 * JavaScript side lays out the kernel's memory (scene.mjs, class MeshOut).
 */
typedef unsigned int u32;
#define EXPORT(name) __attribute__((export_name(name)))

static int finite(float x) { return __builtin_isfinite(x); }

/* mesh::append_mapped: positions by the linear map then the translation
 * (Mat3 * Vec3: x_axis·px, + y_axis·py, + z_axis·pz), normals by the normal
 * matrix and renormalised (Vec3::try_normalize, else +Z). m: linear (9,
 * columns), normal (9, columns), translation (3). */
static void place(const float *p, const float *q, u32 n, const float *m, float *op, float *on) {
  const float l0 = m[0], l1 = m[1], l2 = m[2], l3 = m[3], l4 = m[4], l5 = m[5], l6 = m[6], l7 = m[7], l8 = m[8];
  const float n0 = m[9], n1 = m[10], n2 = m[11], n3 = m[12], n4 = m[13], n5 = m[14], n6 = m[15], n7 = m[16], n8 = m[17];
  const float tx = m[18], ty = m[19], tz = m[20];
  for (u32 k = 0; k < 3 * n; k += 3) {
    const float px = p[k], py = p[k + 1], pz = p[k + 2];
    op[k] = ((l0 * px + l3 * py) + l6 * pz) + tx;
    op[k + 1] = ((l1 * px + l4 * py) + l7 * pz) + ty;
    op[k + 2] = ((l2 * px + l5 * py) + l8 * pz) + tz;
    const float nx = q[k], ny = q[k + 1], nz = q[k + 2];
    const float mx = (n0 * nx + n3 * ny) + n6 * nz;
    const float my = (n1 * nx + n4 * ny) + n7 * nz;
    const float mz = (n2 * nx + n5 * ny) + n8 * nz;
    const float rcp = 1.0f / __builtin_sqrtf((mx * mx + my * my) + mz * mz);
    if (rcp > 0.0f && finite(rcp)) {
      on[k] = mx * rcp;
      on[k + 1] = my * rcp;
      on[k + 2] = mz * rcp;
    } else {
      on[k] = 0.0f;
      on[k + 1] = 0.0f;
      on[k + 2] = 1.0f;
    }
  }
}

/* A similarity placement (mesh::instance_map): glam Mat3::from_quat of q,
 * times sign·s for positions and times sign for normals, sign = -1 when
 * mirrored. tqs: translation (3), rotation x y z w (4), scale (1). */
static void place_similarity(const float *p, const float *q, u32 n, const float *tqs, u32 parity, float *op, float *on) {
  const float x = tqs[3], y = tqs[4], z = tqs[5], w = tqs[6];
  const float x2 = x + x, y2 = y + y, z2 = z + z;
  const float xx = x * x2, xy = x * y2, xz = x * z2;
  const float yy = y * y2, yz = y * z2, zz = z * z2;
  const float wx = w * x2, wy = w * y2, wz = w * z2;
  const float r[9] = {
    1.0f - (yy + zz), xy + wz, xz - wy,
    xy - wz, 1.0f - (xx + zz), yz + wx,
    xz + wy, yz - wx, 1.0f - (xx + yy),
  };
  const float sign = parity ? -1.0f : 1.0f;
  const float k = sign * tqs[7];
  float m[21];
  for (u32 i = 0; i < 9; i++) {
    m[i] = r[i] * k;
    m[9 + i] = r[i] * sign;
  }
  m[18] = tqs[0];
  m[19] = tqs[1];
  m[20] = tqs[2];
  place(p, q, n, m, op, on);
}

/* An affine placement (AffineInstance): linear map a (9, columns) and
 * translation; normals by the cofactor matrix (b×c, c×a, a×b), negated
 * when the determinant is negative, which mirrors the copy. Returns whether
 * it does. */
static int place_affine(const float *p, const float *q, u32 n, const float *mt, float *op, float *on) {
  const float ax = mt[0], ay = mt[1], az = mt[2], bx = mt[3], by = mt[4], bz = mt[5], cx = mt[6], cy = mt[7], cz = mt[8];
  float m[21];
  for (u32 i = 0; i < 9; i++) m[i] = mt[i];
  m[9] = by * cz - cy * bz; m[10] = bz * cx - cz * bx; m[11] = bx * cy - cx * by;   /* b × c */
  m[12] = cy * az - ay * cz; m[13] = cz * ax - az * cx; m[14] = cx * ay - ax * cy;  /* c × a */
  m[15] = ay * bz - by * az; m[16] = az * bx - bz * ax; m[17] = ax * by - bx * ay;  /* a × b */
  const float det = (ax * m[9] + ay * m[10]) + az * m[11];
  const int parity = det < 0.0f;
  if (parity)
    for (u32 i = 9; i < 18; i++) m[i] = m[i] * -1.0f;
  m[18] = mt[9];
  m[19] = mt[10];
  m[20] = mt[11];
  place(p, q, n, m, op, on);
  return parity;
}

/* A hierarchy leaf (Instance::new): the walk's f64 translation, rotation and
 * scale rounded to f32, the rotation renormalised in f32 (glam
 * Quat::normalize), then placed as a similarity. Returns 0, placing nothing,
 * when a value is not finite or the scale is zero (the server drops such
 * leaves). tqs: 8 doubles as place_similarity's floats. */
static int place_leaf(const float *p, const float *q, u32 n, const double *tqs, float *op, float *on) {
  float f[8];
  for (u32 i = 0; i < 8; i++) f[i] = (float)tqs[i];
  const float d = ((f[3] * f[3] + f[4] * f[4]) + f[5] * f[5]) + f[6] * f[6];
  const float r = 1.0f / __builtin_sqrtf(d);
  for (u32 i = 3; i < 7; i++) f[i] = f[i] * r;
  for (u32 i = 0; i < 8; i++)
    if (!finite(f[i])) return 0;
  if (f[7] == 0.0f) return 0;
  place_similarity(p, q, n, f, 0, op, on);
  return 1;
}

/* The prototype's triangles, offset by `base`, reversed (first, third,
 * second) when `flip`. `in` may equal `out`. */
EXPORT("indices")
void indices(const u32 *in, u32 count, u32 base, u32 flip, u32 *out) {
  for (u32 k = 0; k + 2 < count; k += 3) {
    const u32 a = in[k], b = in[k + 1], c = in[k + 2];
    out[k] = base + a;
    out[k + 1] = base + (flip ? c : b);
    out[k + 2] = base + (flip ? b : c);
  }
}

/* How a placement's args are read. */
enum { OP_SIMILARITY = 0, OP_MIRRORED = 1, OP_AFFINE = 2, OP_LEAF = 3 };

/* One placement of a batch, 96 bytes, written by scene.mjs (MeshOut). */
typedef struct {
  u32 op;
  const float *proto; /* positions (3 per vertex), normals, then u32 triangles */
  u32 vertices, indices;
  u32 colour;         /* RGBA bytes as one little-endian word */
  u32 unused[3];
  union {
    float f[12];      /* OP_SIMILARITY, OP_MIRRORED: t, q, s; OP_AFFINE: linear, t */
    double d[8];      /* OP_LEAF: t, q, s as the walk computed them */
  } args;
} placement;

/* The mesh a batch appends to; vertices and triangles written so far advance. */
typedef struct {
  float *positions, *normals;
  u32 *colours, *indices;
  u32 vertices, index_count;
} mesh_out;

/* Appends `count` placements to `out` (mesh::append_mapped for each): one
 * call from JavaScript per batch, because every call across the boundary
 * costs microseconds in a cold process. */
EXPORT("place_batch")
void place_batch(const placement *ps, u32 count, mesh_out *out) {
  for (u32 i = 0; i < count; i++) {
    const placement *pl = &ps[i];
    const u32 base = out->vertices, n = pl->vertices;
    const float *p = pl->proto, *q = p + 3 * n;
    const u32 *tris = (const u32 *)(q + 3 * n);
    float *op = out->positions + 3 * base, *on = out->normals + 3 * base;
    int flip = 0;
    switch (pl->op) {
      case OP_SIMILARITY: place_similarity(p, q, n, pl->args.f, 0, op, on); break;
      case OP_MIRRORED: place_similarity(p, q, n, pl->args.f, 1, op, on); flip = 1; break;
      case OP_AFFINE: flip = place_affine(p, q, n, pl->args.f, op, on); break;
      case OP_LEAF: if (!place_leaf(p, q, n, pl->args.d, op, on)) continue; break;
      default: continue;
    }
    indices(tris, pl->indices, base, flip, out->indices + out->index_count);
    for (u32 k = 0; k < n; k++) out->colours[base + k] = pl->colour;
    out->vertices = base + n;
    out->index_count += pl->indices;
  }
}

/* A hierarchy leaf shape's prototype (LeafShape::prototype): the
 * primitive's positions scaled then offset, its normals scaled by the
 * inverse scale (0 where a scale is 0) and renormalised, or (0, 0, 0) when
 * that fails. so: scale (3), offset (3). */
EXPORT("shape_prototype")
void shape_prototype(const float *p, const float *q, u32 n, const float *so, float *op, float *on) {
  const float sx = so[0], sy = so[1], sz = so[2], ox = so[3], oy = so[4], oz = so[5];
  const float ix = sx == 0.0f ? 0.0f : 1.0f / sx, iy = sy == 0.0f ? 0.0f : 1.0f / sy, iz = sz == 0.0f ? 0.0f : 1.0f / sz;
  for (u32 k = 0; k < 3 * n; k += 3) {
    op[k] = p[k] * sx + ox;
    op[k + 1] = p[k + 1] * sy + oy;
    op[k + 2] = p[k + 2] * sz + oz;
    const float mx = q[k] * ix, my = q[k + 1] * iy, mz = q[k + 2] * iz;
    const float rcp = 1.0f / __builtin_sqrtf((mx * mx + my * my) + mz * mz);
    const int ok = rcp > 0.0f && finite(rcp);
    on[k] = ok ? mx * rcp : 0.0f;
    on[k + 1] = ok ? my * rcp : 0.0f;
    on[k + 2] = ok ? mz * rcp : 0.0f;
  }
}
