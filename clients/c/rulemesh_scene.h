/* rulemesh_scene.h: a dependency-free C99 decoder for rulemesh's `scene`
 * format (application/vnd.rulemesh.scene, .rmscene, versions 1 and 2),
 * specified in docs/scene-format.md. Built for iOS (Swift through
 * module.modulemap) and Android (NDK); see clients/c/README.md.
 *
 * A scene file holds what the grammar placed (primitive instances, meshes,
 * an object-instancing hierarchy); the decoder tessellates and places every
 * record and gives the meshes the flat glTF of the same request holds: the
 * same float positions and normals, colours and indices, in the same order.
 * The tessellation and placement are clients/c/rulemesh_{tessellate,place,
 * shape}.inc, the code the JavaScript decoder's WebAssembly kernel is built
 * from (one implementation). tests/it/c_scene.rs compares every library
 * grammar's meshes with the Rust decoder's, bit for bit.
 *
 * The decoder never allocates. The caller gives working memory and output
 * arrays:
 *   1. rmsc_inspect() with a scratch buffer of rmsc_inspect_scratch(size)
 *      bytes validates the whole file and fills rmsc_info: the meshes, the
 *      vertex and triangle counts, and the scratch rmsc_decode() needs.
 *   2. rmsc_decode() fills the arrays and the mesh table.
 * A file written with `checksum: true` (the header's CHECKSUM flag) ends
 * with a CRC-32 of its bytes, checked before anything else is read: any
 * damaged byte of it is RMSC_ERR_CHECKSUM (docs/scene-format.md, "Checksum").
 * Every count is checked against the bytes that are left before it is used;
 * damaged, truncated or hostile input returns an error status with a
 * message, and nothing is read or written outside the payload and the
 * caller's buffers (whose sizes rmsc_output carries).
 *
 * Thread safety: no global state; any number of threads may decode at once.
 */
#ifndef RULEMESH_SCENE_H
#define RULEMESH_SCENE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The detail version 1 files (which do not record theirs) are tessellated
 * at unless the caller says otherwise: the server's default. */
#define RMSC_V1_DETAIL 16u

/* Why a payload was refused. Values are stable: bindings may switch on them. */
typedef enum rmsc_status {
    RMSC_OK = 0,
    RMSC_ERR_ARGUMENT = 1,  /* a NULL pointer, a misaligned or too small buffer */
    RMSC_ERR_TRUNCATED = 2, /* the data ends early (a cut download) */
    RMSC_ERR_MAGIC = 3,     /* not a scene file, or a version other than 1 and 2 */
    RMSC_ERR_HEADER = 4,    /* unknown flag bits, detail out of range, reserved
                               bytes not zero, provenance not a UTF-8 JSON object */
    RMSC_ERR_TRAILING = 5,  /* bytes after the last mesh */
    RMSC_ERR_KIND = 6,      /* an unknown primitive kind */
    RMSC_ERR_REFERENCE = 7, /* a hierarchy entry refers to a later object or an
                               unknown shape */
    RMSC_ERR_NON_FINITE = 8, /* a transform, position or leaf shape value is
                                NaN or infinite, or an entry's scale is not > 0 */
    RMSC_ERR_RECORD = 9,    /* a mesh, run or record is malformed (index beyond
                               the vertices or the palette, unknown run type,
                               name not UTF-8, missing prototype) */
    RMSC_ERR_TOO_LARGE = 10, /* more triangles than the caller allows, or counts
                               that do not fit this platform's size_t */
    RMSC_ERR_CHECKSUM = 11  /* the header's CHECKSUM flag is set and the CRC-32
                               at the end does not match: a damaged byte */
} rmsc_status;

/* Filled on failure (status and a NUL-terminated English message); on
 * success status is RMSC_OK and message is empty. */
typedef struct rmsc_error {
    rmsc_status status;
    char message[160];
} rmsc_error;

/* One mesh of the output. Its vertices are elements [first_vertex,
 * first_vertex + vertex_count) of the vertex arrays, its triangles indices
 * [first_index, first_index + 3·triangle_count) of `indices`, which count
 * from the mesh's own first vertex (as glTF's meshes do: draw with a base
 * vertex, or add first_vertex). */
typedef struct rmsc_mesh {
    const char *name;       /* into the payload: UTF-8, NOT NUL-terminated */
    size_t name_length;     /* bytes */
    size_t first_vertex;    /* where the mesh's room starts (fixed by rmsc_inspect) */
    size_t first_index;
    uint32_t vertex_capacity;   /* its room (rmsc_inspect) */
    uint32_t triangle_capacity;
    uint32_t vertex_count;      /* what rmsc_decode wrote; below the capacity only
                                   when hierarchy leaves are dropped (a scale that
                                   rounds to 0 or a frame that overflows float) */
    uint32_t triangle_count;
} rmsc_mesh;

/* What rmsc_inspect() reads. */
typedef struct rmsc_info {
    uint16_t version;        /* 1 or 2 */
    uint16_t flags;          /* the header's flags (bit 3, 8: the file ended with a
                                CRC-32, which matched) */
    uint32_t detail;         /* the detail primitives are tessellated at */
    int truncated;           /* a limit cut the model short on the server */
    uint32_t mesh_count;     /* rmsc_mesh entries rmsc_decode fills */
    size_t vertex_count;     /* vertex array elements needed (sum of the meshes'
                                capacities): 3 floats, 3 floats, 4 bytes each */
    size_t triangle_count;   /* triangles (3 indices each) needed */
    uint64_t triangles;      /* triangles the file expands to, as the Rust
                                decoder counts them (saturating) */
    size_t scratch_bytes;    /* the scratch rmsc_decode() needs */
    const uint8_t *provenance;  /* the provenance JSON object, into the payload
                                   (NOT NUL-terminated), or NULL */
    size_t provenance_length;
} rmsc_info;

/* Where rmsc_decode() writes, and how much room each buffer has (in
 * elements, except scratch_bytes). All buffers are required. */
typedef struct rmsc_output {
    float *positions;       /* 3 floats a vertex */
    float *normals;         /* 3 floats a vertex, unit length (as written) */
    uint8_t *colours;       /* 4 bytes a vertex: RGBA8, linear (glTF COLOR_0) */
    uint32_t *indices;      /* 3 a triangle: GL_TRIANGLES, counter-clockwise */
    size_t vertex_capacity;   /* vertices the three vertex arrays hold */
    size_t triangle_capacity; /* triangles `indices` holds */
    rmsc_mesh *meshes;        /* the mesh table */
    size_t mesh_capacity;
    void *scratch;            /* working memory, aligned as malloc's */
    size_t scratch_bytes;
} rmsc_output;

/* Bytes of scratch rmsc_inspect() needs for a payload of `size` bytes
 * (6·size + 64: a few counters per hierarchy object, of which a payload
 * holds at most size / 4), or SIZE_MAX when that does not fit. */
size_t rmsc_inspect_scratch(size_t size);

/* Validates a whole payload (every check rmsc_decode makes) and fills
 * `info`. `v1_detail` is the detail for version 1 files (clamped to 3–256;
 * RMSC_V1_DETAIL is the server's default); `max_triangles` refuses, before
 * any tessellation, a file that expands to more (RMSC_ERR_TOO_LARGE).
 * `scratch` (aligned as malloc's) must hold rmsc_inspect_scratch(size)
 * bytes. `info` and `err` must not be NULL. */
rmsc_status rmsc_inspect(const uint8_t *data, size_t size, uint32_t v1_detail, uint64_t max_triangles,
                         void *scratch, size_t scratch_bytes, rmsc_info *info, rmsc_error *err);

/* Decodes a payload into the caller's buffers (sized from rmsc_inspect()
 * with the same v1_detail and max_triangles). The payload is validated
 * again, and every buffer's size is checked, so a payload accepted here is
 * one the Rust decoder accepts. On failure the buffers hold unspecified
 * partial data. `out` and `err` must not be NULL. */
rmsc_status rmsc_decode(const uint8_t *data, size_t size, uint32_t v1_detail, uint64_t max_triangles,
                        rmsc_output *out, rmsc_error *err);

/* A short name for a status ("ok", "truncated", ...), never NULL. */
const char *rmsc_status_name(rmsc_status status);

#ifdef __cplusplus
}
#endif

#endif /* RULEMESH_SCENE_H */
