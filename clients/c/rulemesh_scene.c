/* rulemesh_scene.c: the scene decoder (see rulemesh_scene.h and
 * docs/scene-format.md). C99; depends on the C library's <math.h> (sqrt,
 * sqrtf, fabs, cos, sin, atan2, isfinite), <string.h> and <stdio.h>
 * (vsnprintf for messages).
 *
 * One parser (`parse`) reads the file twice over: rmsc_inspect runs it to
 * validate and count, rmsc_decode runs it to validate and count again (into
 * the caller's scratch), then to place. The order of its checks follows
 * the Rust reference decoder (crates/engine/src/decode/scene/read.rs and
 * mod.rs), so both accept exactly the same files. The float work
 * is the shared kernel: rulemesh_tessellate.inc, rulemesh_place.inc and
 * rulemesh_shape.inc, also compiled into the JavaScript decoder's
 * WebAssembly. rulemesh_text.inc checks UTF-8 and JSON, rulemesh_walk.inc
 * expands hierarchies, rulemesh_crc32.inc checks a checksummed file's CRC.
 */
#include "rulemesh_scene.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* The kernel's float32 expressions must round once per operation: clang
 * (Xcode, the NDK) contracts a*b+c into a fused multiply-add by default on
 * ARM64, which this pragma forbids; GCC ignores it but does not contract in
 * ISO C mode (-std=c99). The arithmetic must also be binary32 and binary64
 * as written (FLT_EVAL_METHOD 0: every ARM and x86-64 target; not x87). */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

/* ---- the shared kernel, with the C library's functions ---- */

typedef uint32_t u32;
#define RMK_EXPORT(name) static
#define RMK_ISFINITE(x) isfinite(x)
#define RMK_SQRTF(x) sqrtf(x)
#define RMK_SQRT(x) sqrt(x)
#define RMK_FABS(x) fabs(x)
#define RMK_INF HUGE_VAL
#define RMK_COS(x) cos(x)
#define RMK_SIN(x) sin(x)
#define RMK_ATAN2(y, x) atan2(y, x)

#include "rulemesh_tessellate.inc"
#include "rulemesh_place.inc"
#include "rulemesh_shape.inc"
#include "rulemesh_text.inc"
#include "rulemesh_crc32.inc"

/* ---- format constants (docs/scene-format.md) ---- */

#define FLAG_TRUNCATED 1u
#define FLAG_PROVENANCE 2u
#define FLAG_SCALED 4u
#define FLAG_CHECKSUM 8u
#define CHECKSUM_BYTES 4u
#define SHAPE_BIT 0x80000000u
#define PARITY_BIT 0x80u
#define KINDS 9u
#define MIN_DETAIL_ 3u
#define MAX_DETAIL_ 256u
#define SHAPE_BYTES 28u
/* (kind, tube) pairs a decode tessellates: index 2·kind + tube. */
#define COMBOS (2u * KINDS)
enum { RUN_PRIMITIVES = 1, RUN_AFFINE = 2, RUN_PLACED = 3, RUN_MESH = 4, RUN_HIERARCHY = 5 };

static const char ISOSURFACES[] = "isosurfaces";

/* ---- small helpers ---- */

static uint32_t u32_at(const uint8_t *p) {
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}
static uint16_t u16_at(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }
static float f32_at(const uint8_t *p) {
    const uint32_t bits = u32_at(p);
    float f;
    memcpy(&f, &bits, sizeof f); /* IEEE 754 binary32 on every target we build for */
    return f;
}
static double f64_at(const uint8_t *p) {
    const uint64_t bits = (uint64_t)u32_at(p) | ((uint64_t)u32_at(p + 4) << 32);
    double d;
    memcpy(&d, &bits, sizeof d);
    return d;
}
static uint64_t sat_add(uint64_t a, uint64_t b) { return a > UINT64_MAX - b ? UINT64_MAX : a + b; }
static uint64_t sat_mul(uint64_t a, uint64_t b) { return a != 0 && b > UINT64_MAX / a ? UINT64_MAX : a * b; }
static size_t align8(size_t n) { return n > SIZE_MAX - 7 ? SIZE_MAX : (n + 7) & ~(size_t)7; }
static size_t add_size(size_t a, size_t b) { return a > SIZE_MAX - b ? SIZE_MAX : a + b; }
/* a·b as size_t, or SIZE_MAX */
static size_t mul_size(uint64_t a, uint64_t b) {
    const uint64_t p = sat_mul(a, b);
#if SIZE_MAX < UINT64_MAX
    if (p > (uint64_t)SIZE_MAX) return SIZE_MAX;
#endif
    return (size_t)p;
}

static rmsc_status fail(rmsc_error *err, rmsc_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static rmsc_status fail(rmsc_error *err, rmsc_status status, const char *fmt, ...) {
    va_list ap;
    err->status = status;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return status;
}

const char *rmsc_status_name(rmsc_status status) {
    switch (status) {
        case RMSC_OK: return "ok";
        case RMSC_ERR_ARGUMENT: return "argument";
        case RMSC_ERR_TRUNCATED: return "truncated";
        case RMSC_ERR_MAGIC: return "magic";
        case RMSC_ERR_HEADER: return "header";
        case RMSC_ERR_TRAILING: return "trailing";
        case RMSC_ERR_KIND: return "kind";
        case RMSC_ERR_REFERENCE: return "reference";
        case RMSC_ERR_NON_FINITE: return "non_finite";
        case RMSC_ERR_RECORD: return "record";
        case RMSC_ERR_TOO_LARGE: return "too_large";
        case RMSC_ERR_CHECKSUM: return "checksum";
    }
    return "unknown";
}

size_t rmsc_inspect_scratch(size_t size) { return add_size(mul_size(size, 6), 64); }

/* ---- the parser's state ---- */

/* A tessellated primitive in scratch (positions, normals, triangles). */
typedef struct {
    float *pos, *nrm;
    uint32_t *idx;
    uint32_t v, t;
} proto;

/* A frame of the hierarchy walk (Hierarchy::walk_while's stack). */
typedef struct {
    double t[3], r[4], s;
    uint32_t object, next;
} frame;

typedef struct {
    const uint8_t *b;
    size_t size, at;
    rmsc_error *err;
    /* header */
    uint16_t version, flags;
    uint32_t detail, ncolours, nprotos, nshapes, nobjects, width;
    size_t palette_at, shapes_at, entry_bytes;
    const uint8_t *provenance;
    size_t provenance_length;
    /* counting (scratch): where each prototype and object starts, and each
     * object's expansion (vertices, triangles; saturating) */
    size_t *proto_at, *object_at;
    uint64_t *object_v, *object_t;
    uint32_t combos; /* bit 2·kind + tube: a (kind, detail) to tessellate */
    uint64_t shape_temp_v; /* vertices of the largest non-bare leaf shape */
    uint32_t meshes;
    uint64_t vertices, triangles, rust_triangles; /* sums of the meshes' capacities; Rust's count */
    /* placing (rmsc_decode only) */
    rmsc_output *out;
    proto combo[COMBOS];
    proto *natives;     /* the file's prototypes as native arrays */
    uint8_t *native_data;
    size_t native_used;
    uint64_t native_bytes; /* what they take (first pass) */
    float *shape_pos, *shape_nrm;
    uint32_t shape_cached;
    frame *stack;
    /* the mesh being written */
    size_t mesh_vertex0, mesh_index0;
    uint32_t mesh_v, mesh_t;
} parser;

#define TRY(x) do { const rmsc_status s_ = (x); if (s_ != RMSC_OK) return s_; } while (0)

static rmsc_status need(parser *p, uint64_t n) {
    if (n > (uint64_t)(p->size - p->at)) return fail(p->err, RMSC_ERR_TRUNCATED, "scene file is truncated (at byte %lu)", (unsigned long)p->at);
    return RMSC_OK;
}
static rmsc_status read_u8(parser *p, uint32_t *v) {
    TRY(need(p, 1));
    *v = p->b[p->at++];
    return RMSC_OK;
}
static rmsc_status read_u16(parser *p, uint32_t *v) {
    TRY(need(p, 2));
    *v = u16_at(p->b + p->at);
    p->at += 2;
    return RMSC_OK;
}
static rmsc_status read_u32(parser *p, uint32_t *v) {
    TRY(need(p, 4));
    *v = u32_at(p->b + p->at);
    p->at += 4;
    return RMSC_OK;
}
/* n little-endian floats, each finite unless `any` */
static rmsc_status read_f32s(parser *p, float *v, unsigned n, int any, const char *what) {
    TRY(need(p, 4u * (uint64_t)n));
    for (unsigned i = 0; i < n; i++) {
        v[i] = f32_at(p->b + p->at + 4 * i);
        if (!any && !isfinite(v[i])) return fail(p->err, RMSC_ERR_NON_FINITE, "non-finite number in %s", what);
    }
    p->at += 4u * n;
    return RMSC_OK;
}

static uint32_t clamp_detail_(uint32_t d) { return d < MIN_DETAIL_ ? MIN_DETAIL_ : d > MAX_DETAIL_ ? MAX_DETAIL_ : d; }
/* A leaf shape's detail: a tube is tessellated with the tube profile's sides. */
static uint32_t shape_detail(uint32_t detail, int tube) { return tube ? (detail / 2 > 4 ? detail / 2 : 4) : detail; }
static uint32_t combo_detail(const parser *p, uint32_t c) { return shape_detail(p->detail, (int)(c & 1)); }

/* Reads the header (either version) and the provenance block. */
static rmsc_status parse_header(parser *p, uint32_t v1_detail) {
    uint32_t version, flags, known, x;
    TRY(need(p, 4));
    if (memcmp(p->b, "RMSC", 4) != 0) return fail(p->err, RMSC_ERR_MAGIC, "not a rulemesh scene file (magic)");
    p->at = 4;
    TRY(read_u16(p, &version));
    if (version != 1 && version != 2) return fail(p->err, RMSC_ERR_MAGIC, "not a rulemesh scene (version 1 or 2) file: version %u", (unsigned)version);
    TRY(read_u16(p, &flags));
    known = FLAG_TRUNCATED | FLAG_PROVENANCE | (version == 2 ? FLAG_SCALED | FLAG_CHECKSUM : 0u);
    if (flags & ~known) return fail(p->err, RMSC_ERR_HEADER, "scene header is malformed: unknown flag bits %#x", (unsigned)flags);
    if (flags & FLAG_CHECKSUM) {
        /* Checked before anything else is read (as the Rust decoder does),
         * so a damaged byte after the flags is this error; the rest is then
         * read as if the file ended before the CRC. */
        uint32_t stored, computed;
        TRY(need(p, CHECKSUM_BYTES));
        stored = u32_at(p->b + p->size - CHECKSUM_BYTES);
        computed = rmcrc32(p->b, p->size - CHECKSUM_BYTES);
        if (stored != computed)
            return fail(p->err, RMSC_ERR_CHECKSUM, "scene file is corrupted: CRC-32 is %08lx, the file says %08lx", (unsigned long)computed, (unsigned long)stored);
        p->size -= CHECKSUM_BYTES;
    }
    p->version = (uint16_t)version;
    p->flags = (uint16_t)flags;
    if (version == 1) {
        TRY(read_u32(p, &p->nshapes));
        TRY(read_u32(p, &p->nobjects));
        TRY(need(p, 8)); /* leaves in the expansion: informative */
        p->at += 8;
        p->detail = clamp_detail_(v1_detail);
    } else {
        TRY(read_u16(p, &p->detail));
        if (p->detail < MIN_DETAIL_ || p->detail > MAX_DETAIL_) return fail(p->err, RMSC_ERR_HEADER, "scene header is malformed: detail %u out of range", (unsigned)p->detail);
        TRY(read_u16(p, &x));
        if (x != 0) return fail(p->err, RMSC_ERR_HEADER, "scene header is malformed: reserved bytes are not zero");
        TRY(read_u32(p, &p->ncolours));
        TRY(read_u32(p, &p->nprotos));
    }
    if (flags & FLAG_PROVENANCE) {
        TRY(read_u32(p, &x));
        TRY(need(p, x));
        p->provenance = p->b + p->at;
        p->provenance_length = x;
        p->at += x;
        if (!utf8_valid(p->provenance, x)) return fail(p->err, RMSC_ERR_HEADER, "scene header is malformed: provenance is not UTF-8");
        if (!json_is_object(p->provenance, x)) return fail(p->err, RMSC_ERR_HEADER, "scene header is malformed: provenance is not a JSON object");
    }
    return RMSC_OK;
}

/* Takes `bytes` of scratch (8-aligned) from *at; NULL when it does not fit. */
static void *carve(void *scratch, size_t scratch_bytes, size_t *at, size_t bytes) {
    void *r;
    bytes = align8(bytes);
    if (bytes == 0) return NULL;
    if (bytes > scratch_bytes - *at) return NULL;
    r = (uint8_t *)scratch + *at;
    *at += bytes;
    return r;
}

static rmsc_status no_scratch(parser *p) {
    return fail(p->err, RMSC_ERR_ARGUMENT, "scratch buffer too small (rmsc_inspect_scratch / rmsc_info.scratch_bytes say how large)");
}

/* Reads a prototype (`colours` 0) or a written mesh: V, T, positions
 * (finite), normals, colours, indices (each < V). Leaves p->at after it and
 * returns where it started in *start. */
static rmsc_status parse_mesh_data(parser *p, int colours, size_t *start, uint32_t *v, uint32_t *t) {
    const uint64_t per_vertex = colours ? 28u : 24u;
    *start = p->at;
    TRY(read_u32(p, v));
    TRY(read_u32(p, t));
    TRY(need(p, sat_add(sat_mul(*v, per_vertex), sat_mul(*t, 12))));
    for (uint64_t k = 0; k < 3u * (uint64_t)*v; k++)
        if (!isfinite(f32_at(p->b + p->at + 4 * k))) return fail(p->err, RMSC_ERR_NON_FINITE, "non-finite position in a mesh");
    p->at += (size_t)(per_vertex * *v);
    for (uint64_t k = 0; k < 3u * (uint64_t)*t; k++)
        if (u32_at(p->b + p->at + 4 * k) >= *v) return fail(p->err, RMSC_ERR_RECORD, "scene mesh is malformed: index beyond the vertices");
    p->at += (size_t)(12u * (uint64_t)*t);
    return RMSC_OK;
}

/* Vertices and triangles of leaf shape s. */
static void shape_counts(const parser *p, uint32_t s, uint64_t *v, uint64_t *t) {
    const uint8_t *r = p->b + p->shapes_at + (size_t)SHAPE_BYTES * s;
    const uint32_t d = shape_detail(p->detail, r[1] & 1);
    *v = tessellation_vertices(r[0], d);
    *t = tessellation_triangles(r[0], d);
}

static int shape_is_bare(const uint8_t *r) {
    if (r[1] & 1) return 0;
    for (int i = 0; i < 3; i++)
        if (f32_at(r + 4 + 4 * i) != 1.0f || f32_at(r + 16 + 4 * i) != 0.0f) return 0;
    return 1;
}

/* The hierarchy section: leaf shapes, then objects (children first). Counts
 * each object's expansion as it goes (entries refer only to earlier objects). */
static rmsc_status parse_hierarchy(parser *p, void *scratch, size_t scratch_bytes, size_t *carved) {
    const int wide = p->version == 2, scaled = (p->flags & FLAG_SCALED) != 0;
    p->entry_bytes = !wide ? 36u : scaled ? 72u : 64u;
    TRY(need(p, sat_mul(p->nshapes, SHAPE_BYTES)));
    TRY(need(p, sat_mul(p->nobjects, 4)));
    p->shapes_at = p->at;
    for (uint32_t s = 0; s < p->nshapes; s++) {
        const uint8_t *r = p->b + p->at;
        float v[6];
        if (r[0] >= KINDS) return fail(p->err, RMSC_ERR_KIND, "unknown primitive kind %u", (unsigned)r[0]);
        p->at += 4;
        TRY(read_f32s(p, v, 6, 0, "a leaf shape"));
        p->combos |= 1u << (2u * r[0] + (r[1] & 1u));
        if (!shape_is_bare(r)) {
            const uint64_t sv = tessellation_vertices(r[0], shape_detail(p->detail, r[1] & 1));
            if (sv > p->shape_temp_v) p->shape_temp_v = sv;
        }
    }
    p->object_at = carve(scratch, scratch_bytes, carved, sizeof(size_t) * (size_t)p->nobjects);
    p->object_v = carve(scratch, scratch_bytes, carved, sizeof(uint64_t) * (size_t)p->nobjects);
    p->object_t = carve(scratch, scratch_bytes, carved, sizeof(uint64_t) * (size_t)p->nobjects);
    if (p->nobjects && (!p->object_at || !p->object_v || !p->object_t)) return no_scratch(p);
    for (uint32_t o = 0; o < p->nobjects; o++) {
        uint32_t n;
        uint64_t ov = 0, ot = 0;
        p->object_at[o] = p->at;
        TRY(read_u32(p, &n));
        TRY(need(p, sat_mul(n, p->entry_bytes)));
        for (uint32_t k = 0; k < n; k++) {
            const uint8_t *e = p->b + p->at;
            const uint32_t raw = u32_at(e);
            int finite_ = 1;
            if (wide) {
                for (int i = 0; i < 7; i++) finite_ &= isfinite(f64_at(e + 4 + 8 * i)) != 0;
                if (scaled) {
                    const double s = f64_at(e + 60);
                    finite_ &= isfinite(s) && s > 0.0;
                }
            } else {
                for (int i = 0; i < 7; i++) finite_ &= isfinite(f32_at(e + 4 + 4 * i)) != 0;
            }
            if (!finite_) return fail(p->err, RMSC_ERR_NON_FINITE, "non-finite number in object %u", (unsigned)o);
            if (raw & SHAPE_BIT) {
                uint64_t sv, st;
                if ((raw & ~SHAPE_BIT) >= p->nshapes) return fail(p->err, RMSC_ERR_REFERENCE, "object %u refers to shape %u, which does not exist", (unsigned)o, (unsigned)(raw & ~SHAPE_BIT));
                shape_counts(p, raw & ~SHAPE_BIT, &sv, &st);
                ov = sat_add(ov, sv);
                ot = sat_add(ot, st);
            } else {
                if (raw >= o) return fail(p->err, RMSC_ERR_REFERENCE, "object %u refers to object %u, which is not earlier", (unsigned)o, (unsigned)raw);
                ov = sat_add(ov, p->object_v[raw]);
                ot = sat_add(ot, p->object_t[raw]);
            }
            p->at += p->entry_bytes;
        }
        p->object_v[o] = ov;
        p->object_t[o] = ot;
    }
    return RMSC_OK;
}

/* ---- placing (rmsc_decode's second pass) ---- */

/* Fails unless v more vertices and t more triangles fit the caller's arrays
 * (always, after the first pass sized them; checked all the same). */
static rmsc_status room(parser *p, uint32_t v, uint32_t t) {
    const rmsc_output *o = p->out;
    if ((uint64_t)p->mesh_v + v > UINT32_MAX || (uint64_t)p->mesh_t + t > UINT32_MAX ||
        p->mesh_vertex0 + p->mesh_v + (uint64_t)v > o->vertex_capacity ||
        p->mesh_index0 / 3 + p->mesh_t + (uint64_t)t > o->triangle_capacity)
        return fail(p->err, RMSC_ERR_ARGUMENT, "output arrays too small");
    return RMSC_OK;
}
/* Where the next vertex goes (NULL-safe: arrays may be NULL when a file
 * has no vertices, and NULL + 0 is undefined). */
static float *at_pos(parser *p) { return p->out->positions ? p->out->positions + 3 * (p->mesh_vertex0 + p->mesh_v) : NULL; }
static float *at_nrm(parser *p) { return p->out->normals ? p->out->normals + 3 * (p->mesh_vertex0 + p->mesh_v) : NULL; }

/* After a prototype's vertices are placed: its triangles (offset, reversed
 * when `flip`) and its colour, as mesh::append_mapped appends them. */
static void placed(parser *p, const proto *src, int flip, const uint8_t *colour) {
    uint8_t *c;
    if (src->v == 0 && src->t == 0) return;
    c = p->out->colours + 4 * (p->mesh_vertex0 + p->mesh_v);
    if (src->t) indices(src->idx, 3 * src->t, p->mesh_v, (u32)flip, p->out->indices + p->mesh_index0 + 3 * (size_t)p->mesh_t);
    for (uint32_t k = 0; k < src->v; k++) memcpy(c + 4 * (size_t)k, colour, 4);
    p->mesh_v += src->v;
    p->mesh_t += src->t;
}

#include "rulemesh_walk.inc"

/* ---- the meshes section ---- */

static rmsc_status colour_index(parser *p, const uint8_t **colour) {
    uint32_t i = 0;
    TRY(need(p, p->width));
    for (uint32_t k = 0; k < p->width; k++) i |= (uint32_t)p->b[p->at + k] << (8 * k);
    p->at += p->width;
    if (i >= p->ncolours) return fail(p->err, RMSC_ERR_RECORD, "scene mesh is malformed: colour index beyond the palette");
    *colour = p->b + p->palette_at + 4 * (size_t)i;
    return RMSC_OK;
}

/* One record of a primitives (1), affine (2) or placed (3) run: read,
 * checked, counted in *v and *t, and placed when decoding. */
static rmsc_status record(parser *p, uint32_t type, uint64_t *v, uint64_t *t) {
    uint32_t code, shape = 0, parity = 0;
    const uint8_t *colour;
    float a[12];
    const proto *src;
    if (type == RUN_PLACED) {
        TRY(read_u32(p, &shape));
        if (shape >= p->nprotos) return fail(p->err, RMSC_ERR_RECORD, "scene mesh is malformed: placement of a prototype that does not exist");
        TRY(read_u8(p, &parity));
        TRY(colour_index(p, &colour));
        TRY(read_f32s(p, a, 8, 0, "a placement"));
        *v = u32_at(p->b + p->proto_at[shape]);
        *t = u32_at(p->b + p->proto_at[shape] + 4);
        if (!p->out) return RMSC_OK;
        src = &p->natives[shape];
        TRY(room(p, src->v, src->t));
        place_similarity(src->pos, src->nrm, src->v, a, parity != 0, at_pos(p), at_nrm(p));
        placed(p, src, parity != 0, colour);
        return RMSC_OK;
    }
    TRY(read_u8(p, &code));
    /* The parity bit is masked for both record types, as the Rust decoder's kind() does. */
    if ((code & ~PARITY_BIT) >= KINDS) return fail(p->err, RMSC_ERR_KIND, "unknown primitive kind %u", (unsigned)code);
    TRY(colour_index(p, &colour));
    TRY(read_f32s(p, a, type == RUN_AFFINE ? 12u : 8u, 0, "a placement"));
    p->combos |= 1u << (2u * (code & ~PARITY_BIT));
    *v = tessellation_vertices(code & ~PARITY_BIT, p->detail);
    *t = tessellation_triangles(code & ~PARITY_BIT, p->detail);
    if (!p->out) return RMSC_OK;
    src = &p->combo[2u * (code & ~PARITY_BIT)];
    TRY(room(p, src->v, src->t));
    if (type == RUN_AFFINE) {
        const int flip = place_affine(src->pos, src->nrm, src->v, a, at_pos(p), at_nrm(p));
        placed(p, src, flip, colour);
    } else {
        const int mirrored = (code & PARITY_BIT) != 0;
        place_similarity(src->pos, src->nrm, src->v, a, (u32)mirrored, at_pos(p), at_nrm(p));
        placed(p, src, mirrored, colour);
    }
    return RMSC_OK;
}

/* A written mesh (run type 4) copied in, its indices offset. */
static rmsc_status copy_mesh(parser *p, size_t start) {
    const uint8_t *m = p->b + start;
    const uint32_t v = u32_at(m), t = u32_at(m + 4);
    const uint8_t *pos = m + 8, *nrm = pos + 12 * (size_t)v, *col = nrm + 12 * (size_t)v, *idx = col + 4 * (size_t)v;
    float *op, *on;
    uint32_t *oi;
    TRY(room(p, v, t));
    if (v == 0 && t == 0) return RMSC_OK;
    op = at_pos(p);
    on = at_nrm(p);
    oi = t ? p->out->indices + p->mesh_index0 + 3 * (size_t)p->mesh_t : NULL;
    for (size_t k = 0; k < 3 * (size_t)v; k++) {
        op[k] = f32_at(pos + 4 * k);
        on[k] = f32_at(nrm + 4 * k);
    }
    memcpy(p->out->colours + 4 * (p->mesh_vertex0 + p->mesh_v), col, 4 * (size_t)v);
    for (size_t k = 0; k < 3 * (size_t)t; k++) oi[k] = p->mesh_v + u32_at(idx + 4 * k);
    p->mesh_v += v;
    p->mesh_t += t;
    return RMSC_OK;
}

/* Adds a run's vertices and triangles to the mesh's (each must fit 32 bits). */
static rmsc_status count(parser *p, uint64_t *mv, uint64_t *mt, uint64_t v, uint64_t t) {
    *mv = sat_add(*mv, v);
    *mt = sat_add(*mt, t);
    p->rust_triangles = sat_add(p->rust_triangles, t);
    if (*mv > UINT32_MAX || *mt > UINT32_MAX)
        return fail(p->err, RMSC_ERR_TOO_LARGE, "a mesh of more than 2^32 - 1 vertices or triangles");
    return RMSC_OK;
}

/* Ends a mesh: its room is what was counted; with an output, its table entry. */
static rmsc_status end_mesh(parser *p, uint32_t index, const char *name, size_t name_length, uint64_t mv, uint64_t mt) {
    if (p->out) {
        rmsc_mesh *m;
        if (index >= p->out->mesh_capacity) return fail(p->err, RMSC_ERR_ARGUMENT, "mesh table too small");
        m = &p->out->meshes[index];
        m->name = name;
        m->name_length = name_length;
        m->first_vertex = p->mesh_vertex0;
        m->first_index = p->mesh_index0;
        m->vertex_capacity = (uint32_t)mv;
        m->triangle_capacity = (uint32_t)mt;
        m->vertex_count = p->mesh_v;
        m->triangle_count = p->mesh_t;
    }
    p->vertices = sat_add(p->vertices, mv);
    p->triangles = sat_add(p->triangles, mt);
    /* the next mesh's room starts after this one's */
    p->mesh_vertex0 = p->vertices > SIZE_MAX ? SIZE_MAX : (size_t)p->vertices;
    p->mesh_index0 = mul_size(p->triangles, 3);
    p->mesh_v = p->mesh_t = 0;
    return RMSC_OK;
}

static rmsc_status parse_meshes(parser *p) {
    uint32_t nmeshes;
    TRY(read_u32(p, &nmeshes));
    TRY(need(p, sat_mul(nmeshes, 6)));
    p->meshes = nmeshes;
    for (uint32_t mi = 0; mi < nmeshes; mi++) {
        uint32_t len, nruns;
        uint64_t mv = 0, mt = 0;
        const char *name;
        TRY(read_u16(p, &len));
        TRY(need(p, len));
        name = (const char *)(p->b + p->at);
        if (!utf8_valid(p->b + p->at, len)) return fail(p->err, RMSC_ERR_RECORD, "scene mesh %u is malformed: name is not UTF-8", (unsigned)mi);
        p->at += len;
        TRY(read_u32(p, &nruns));
        TRY(need(p, sat_mul(nruns, 5)));
        for (uint32_t k = 0; k < nruns; k++) {
            uint32_t type, n;
            TRY(read_u8(p, &type));
            TRY(read_u32(p, &n));
            if (type == RUN_PRIMITIVES || type == RUN_AFFINE || type == RUN_PLACED) {
                TRY(need(p, sat_mul(n, 33)));
                for (uint32_t i = 0; i < n; i++) {
                    uint64_t v = 0, t = 0;
                    TRY(record(p, type, &v, &t));
                    TRY(count(p, &mv, &mt, v, t));
                }
            } else if (type == RUN_MESH && n == 1) {
                size_t start;
                uint32_t v, t;
                TRY(parse_mesh_data(p, 1, &start, &v, &t));
                TRY(count(p, &mv, &mt, v, t));
                if (p->out) TRY(copy_mesh(p, start));
            } else if (type == RUN_HIERARCHY && n == 1) {
                const int any = p->nobjects > 0;
                TRY(count(p, &mv, &mt, any ? p->object_v[p->nobjects - 1] : 0, any ? p->object_t[p->nobjects - 1] : 0));
                if (p->out) TRY(walk(p));
            } else {
                return fail(p->err, RMSC_ERR_RECORD, "scene mesh %u is malformed: unknown run type %u or count %u", (unsigned)mi, (unsigned)type, (unsigned)n);
            }
        }
        TRY(end_mesh(p, mi, name, len, mv, mt));
    }
    return RMSC_OK;
}

/* ---- the whole file ---- */

/* A prototype copied into native arrays (rmsc_decode's second pass). */
static void convert_proto(parser *p, uint32_t i, size_t start) {
    const uint8_t *m = p->b + start;
    proto *d = &p->natives[i];
    d->v = u32_at(m);
    d->t = u32_at(m + 4);
    d->pos = d->nrm = NULL;
    d->idx = NULL;
    if (d->v == 0 && d->t == 0) return;
    d->pos = (float *)(void *)(p->native_data + p->native_used);
    d->nrm = d->pos + 3 * (size_t)d->v;
    d->idx = (uint32_t *)(void *)(d->nrm + 3 * (size_t)d->v);
    for (size_t k = 0; k < 6 * (size_t)d->v; k++) d->pos[k] = f32_at(m + 8 + 4 * k);
    for (size_t k = 0; k < 3 * (size_t)d->t; k++) d->idx[k] = u32_at(m + 8 + 24 * (size_t)d->v + 4 * k);
    p->native_used += align8(4 * (6 * (size_t)d->v + 3 * (size_t)d->t));
}

/* Reads (validates, counts; when p->out is set, places) the whole file. */
static rmsc_status parse(parser *p, uint32_t v1_detail, uint64_t max_triangles, void *scratch, size_t scratch_bytes, size_t *carved) {
    TRY(parse_header(p, v1_detail));
    if (p->version == 2) {
        p->width = p->ncolours <= 256u ? 1u : p->ncolours <= 65536u ? 2u : 4u;
        TRY(need(p, sat_mul(p->ncolours, 4)));
        p->palette_at = p->at;
        p->at += 4 * (size_t)p->ncolours;
        TRY(need(p, sat_mul(p->nprotos, 8)));
        p->proto_at = carve(scratch, scratch_bytes, carved, sizeof(size_t) * (size_t)p->nprotos);
        if (p->nprotos && !p->proto_at) return no_scratch(p);
        for (uint32_t i = 0; i < p->nprotos; i++) {
            uint32_t v, t;
            TRY(parse_mesh_data(p, 0, &p->proto_at[i], &v, &t));
            p->native_bytes = sat_add(p->native_bytes, align8(mul_size(4, 6 * (uint64_t)v + 3 * (uint64_t)t)));
            if (p->out) convert_proto(p, i, p->proto_at[i]);
        }
        TRY(read_u32(p, &p->nshapes));
        TRY(read_u32(p, &p->nobjects));
    }
    TRY(parse_hierarchy(p, scratch, scratch_bytes, carved));
    if (p->version == 2) {
        TRY(parse_meshes(p));
    } else {
        if (p->at != p->size) return fail(p->err, RMSC_ERR_TRAILING, "scene file is followed by trailing bytes");
        if (p->nobjects > 0 && p->object_t[p->nobjects - 1] > 0) {
            uint64_t mv = 0, mt = 0;
            TRY(count(p, &mv, &mt, p->object_v[p->nobjects - 1], p->object_t[p->nobjects - 1]));
            if (p->out) TRY(walk(p));
            TRY(end_mesh(p, 0, ISOSURFACES, sizeof ISOSURFACES - 1, mv, mt));
            p->meshes = 1;
        }
    }
    if (p->at != p->size) return fail(p->err, RMSC_ERR_TRAILING, "scene file is followed by trailing bytes");
    if (p->rust_triangles > max_triangles)
        return fail(p->err, RMSC_ERR_TOO_LARGE, "scene expands to %llu triangles, more than allowed (%llu)", (unsigned long long)p->rust_triangles, (unsigned long long)max_triangles);
    if (p->vertices > SIZE_MAX / 12 || p->triangles > SIZE_MAX / 12)
        return fail(p->err, RMSC_ERR_TOO_LARGE, "scene expands to more vertices or triangles than this platform's size_t holds");
    return RMSC_OK;
}

/* Bytes of each region rmsc_decode's second pass adds after the first's. */
static size_t decode_regions(const parser *p) {
    size_t n = align8(mul_size(p->nprotos, sizeof(proto)));
    n = add_size(n, p->native_bytes > SIZE_MAX ? SIZE_MAX : (size_t)p->native_bytes);
    for (uint32_t c = 0; c < COMBOS; c++)
        if (p->combos & (1u << c)) {
            const uint32_t d = combo_detail(p, c);
            n = add_size(n, align8(mul_size(4, 6 * (uint64_t)tessellation_vertices(c / 2, d) + 3 * (uint64_t)tessellation_triangles(c / 2, d))));
        }
    n = add_size(n, align8(mul_size(24, p->shape_temp_v)));
    return add_size(n, align8(mul_size((uint64_t)p->nobjects + 1, sizeof(frame))));
}

static rmsc_status check_scratch(void *scratch, size_t scratch_bytes, rmsc_error *err) {
    if (scratch_bytes && !scratch) return fail(err, RMSC_ERR_ARGUMENT, "scratch is NULL");
    if ((uintptr_t)scratch % 8 != 0) /* uintptr_t: optional in C99, present on every target */
        return fail(err, RMSC_ERR_ARGUMENT, "scratch is not 8-byte aligned");
    return RMSC_OK;
}

rmsc_status rmsc_inspect(const uint8_t *data, size_t size, uint32_t v1_detail, uint64_t max_triangles,
                         void *scratch, size_t scratch_bytes, rmsc_info *info, rmsc_error *err) {
    parser p;
    size_t carved = 0;
    if (!info || !err) return RMSC_ERR_ARGUMENT;
    memset(info, 0, sizeof *info);
    err->status = RMSC_OK;
    err->message[0] = '\0';
    if (!data && size) return fail(err, RMSC_ERR_ARGUMENT, "data is NULL");
    TRY(check_scratch(scratch, scratch_bytes, err));
    memset(&p, 0, sizeof p);
    p.b = data;
    p.size = size;
    p.err = err;
    TRY(parse(&p, v1_detail, max_triangles, scratch, scratch_bytes, &carved));
    info->version = p.version;
    info->flags = p.flags;
    info->detail = p.detail;
    info->truncated = (p.flags & FLAG_TRUNCATED) != 0;
    info->mesh_count = p.meshes;
    info->vertex_count = (size_t)p.vertices;
    info->triangle_count = (size_t)p.triangles;
    info->triangles = p.rust_triangles;
    info->scratch_bytes = add_size(align8(carved), decode_regions(&p));
    if (info->scratch_bytes == SIZE_MAX) return fail(err, RMSC_ERR_TOO_LARGE, "the decoder's scratch does not fit this platform's size_t");
    info->provenance = p.provenance;
    info->provenance_length = p.provenance_length;
    return RMSC_OK;
}

rmsc_status rmsc_decode(const uint8_t *data, size_t size, uint32_t v1_detail, uint64_t max_triangles,
                        rmsc_output *out, rmsc_error *err) {
    parser a, b;
    size_t carved = 0, at;
    void *region;
    if (!out || !err) return RMSC_ERR_ARGUMENT;
    err->status = RMSC_OK;
    err->message[0] = '\0';
    if (!data && size) return fail(err, RMSC_ERR_ARGUMENT, "data is NULL");
    TRY(check_scratch(out->scratch, out->scratch_bytes, err));
    memset(&a, 0, sizeof a);
    a.b = data;
    a.size = size;
    a.err = err;
    TRY(parse(&a, v1_detail, max_triangles, out->scratch, out->scratch_bytes, &carved));
    if (add_size(align8(carved), decode_regions(&a)) > out->scratch_bytes) return no_scratch(&a);
    if (out->vertex_capacity < a.vertices || out->triangle_capacity < a.triangles || out->mesh_capacity < a.meshes)
        return fail(err, RMSC_ERR_ARGUMENT, "output arrays too small (rmsc_info says how large)");
    if ((a.vertices && (!out->positions || !out->normals || !out->colours)) || (a.triangles && !out->indices) || (a.meshes && !out->meshes))
        return fail(err, RMSC_ERR_ARGUMENT, "an output array is NULL");
    /* The second pass's regions, after the first pass's arrays. */
    memset(&b, 0, sizeof b);
    b.b = data;
    b.size = size;
    b.err = err;
    b.out = out;
    b.shape_cached = UINT32_MAX;
    at = align8(carved);
    b.natives = carve(out->scratch, out->scratch_bytes, &at, (size_t)a.nprotos * sizeof(proto));
    b.native_data = carve(out->scratch, out->scratch_bytes, &at, (size_t)a.native_bytes);
    for (uint32_t c = 0; c < COMBOS; c++) {
        if (a.combos & (1u << c)) {
            const uint32_t d = combo_detail(&a, c), kind = c / 2;
            proto *q = &b.combo[c];
            q->v = tessellation_vertices(kind, d);
            q->t = tessellation_triangles(kind, d);
            region = carve(out->scratch, out->scratch_bytes, &at, 4 * (6 * (size_t)q->v + 3 * (size_t)q->t));
            q->pos = region;
            q->nrm = q->pos + 3 * (size_t)q->v;
            q->idx = (uint32_t *)(void *)(q->nrm + 3 * (size_t)q->v);
            tessellate(kind, d, q->pos, q->nrm, q->idx);
        }
    }
    b.shape_pos = carve(out->scratch, out->scratch_bytes, &at, 24 * (size_t)a.shape_temp_v);
    b.shape_nrm = b.shape_pos ? b.shape_pos + 3 * (size_t)a.shape_temp_v : NULL;
    b.stack = carve(out->scratch, out->scratch_bytes, &at, ((size_t)a.nobjects + 1) * sizeof(frame));
    carved = 0;
    return parse(&b, v1_detail, max_triangles, out->scratch, out->scratch_bytes, &carved);
}
