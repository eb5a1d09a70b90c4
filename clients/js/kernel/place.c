/*
 * The float32 arithmetic of rulemesh's scene decoder for JavaScript
 * (clients/js/scene.mjs), compiled to WebAssembly by scripts/build-js-kernel.
 *
 * Why C and WebAssembly: a first decode runs in V8's interpreter, where every
 * floating-point operation allocates a boxed number (about 2 µs a vertex);
 * compiled, the same loops cost nanoseconds. WebAssembly's f32 operations are
 * IEEE 754 binary32 with round-to-nearest and no fused multiply-add, and this
 * file is compiled with -ffp-contract=off, so each expression gives the bits
 * the server's glam code gives.
 *
 * The placement itself is clients/c/rulemesh_place.inc and
 * clients/c/rulemesh_shape.inc, which the C decoder (clients/c/rulemesh_scene.c)
 * builds from too: one implementation. What is
 * here is the JavaScript side's batch interface (place_batch): no libc, no
 * static data, no allocation; the JavaScript side lays out the kernel's
 * memory (scene.mjs, class MeshOut).
 */
typedef unsigned int u32;
#define EXPORT(name) __attribute__((export_name(name)))
#define RMK_EXPORT(name) EXPORT(name)
#define RMK_ISFINITE(x) __builtin_isfinite(x)
#define RMK_SQRTF(x) __builtin_sqrtf(x)

#include "../../c/rulemesh_place.inc"

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

#include "../../c/rulemesh_shape.inc"
