/* rulemesh_strips.h: a dependency-free C99 decoder for rulemesh's `strips`
 * format (application/vnd.rulemesh.strips, format versions 2 and 3), specified in
 * docs/strips-format.md. Built for iOS (Swift through a bridging header) and
 * Android (NDK); see clients/c/README.md.
 *
 * The decoder never allocates. The caller asks rms_inspect() for the
 * counts, allocates the arrays it wants, and calls rms_decode(). Every read
 * is bounds-checked: damaged or truncated input returns an error status with
 * a message, and never reads or writes outside the caller's buffers.
 * Payloads wrapped in zstd (flag ZSTD) are refused with RMS_ERR_ZSTD, as the
 * JavaScript decoder refuses them: this file has no zstd.
 *
 * Decoded values are bit-identical to rulemesh's Rust reference decoder
 * (rulemesh::decode::strips::decode_strips_full): positions and normals are
 * computed in double and rounded once to float, exactly as the spec says.
 * tests/it/c_decoder.rs checks this on every grammar.
 *
 * Thread safety: no global state; any number of threads may decode at once.
 */
#ifndef RULEMESH_STRIPS_H
#define RULEMESH_STRIPS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The strip index that separates runs (primitive restart). */
#define RMS_RESTART 0xFFFFFFFFu
/* The 16-bit restart index, for rms_indices_to_u16(). */
#define RMS_RESTART_U16 0xFFFFu

/* Why a payload was refused. Values are stable: bindings may switch on them. */
typedef enum rms_status {
    RMS_OK = 0,
    RMS_ERR_ARGUMENT = 1,  /* a NULL pointer, or a caller's buffer too small */
    RMS_ERR_TRUNCATED = 2, /* shorter or longer than the header says (a cut download) */
    RMS_ERR_MAGIC = 3,     /* not a strips payload */
    RMS_ERR_CHECKSUM = 4,  /* the CRC-32 does not match (a damaged byte) */
    RMS_ERR_VERSION = 5,   /* a format version other than 2 and 3 */
    RMS_ERR_ZSTD = 6,      /* zstd-wrapped: request zstd=false */
    RMS_ERR_HEADER = 7,    /* a header field out of range */
    RMS_ERR_BODY = 8       /* a stream does not decode, or a value is out of range */
} rms_status;

/* Filled on failure (status and a NUL-terminated English message); on
 * success status is RMS_OK and message is empty. */
typedef struct rms_error {
    rms_status status;
    char message[160];
} rms_error;

/* What rms_inspect() reads from the header (after the length, CRC and
 * stream-layout checks). */
typedef struct rms_info {
    uint32_t vertex_count;   /* V */
    uint32_t triangle_count; /* T; the triangle list has 3·T indices */
    uint32_t palette_count;  /* palette entries (0 without a palette) */
    uint8_t position_bits;   /* 8, 10, 12 or 16 */
    uint8_t normal_bits;     /* 8 or 16 */
    uint8_t flags;           /* bit 1: colours came from a palette */
    float bbox_min[3];       /* the quantisation box */
    float bbox_max[3];
    /* An upper bound of the rebuilt strip's length (4·T − 1, or 0): a strip
     * buffer this long never fails. rms_restrip() gives the exact length. */
    size_t strip_capacity;
} rms_info;

/* Where rms_decode() writes. Sizes are in elements, not bytes. */
typedef struct rms_output {
    float *positions;    /* 3·V floats (x, y, z per vertex), or NULL to skip */
    float *normals;      /* 3·V floats, unit length, or NULL to skip */
    uint8_t *colours;    /* 4·V bytes, RGBA8 linear (glTF COLOR_0), or NULL */
    uint32_t *triangles; /* 3·T indices, required: the triangle list in strip
                            order (for TRIANGLES draws) */
    uint32_t *strip;     /* optional: the strip, RMS_RESTART between runs
                            (for TRIANGLE_STRIP with primitive restart) */
    size_t strip_capacity; /* elements of `strip` (rms_info.strip_capacity
                              always suffices) */
    size_t strip_length;   /* out: indices written to `strip` */
} rms_output;

/* Checks a payload (length, CRC, header, stream layout, the safety limits of
 * docs/strips-format.md) and fills `info`. Decodes no stream, so it is cheap;
 * rms_decode() can still refuse a payload whose streams are damaged. `info`
 * and `err` must not be NULL. */
rms_status rms_inspect(const uint8_t *data, size_t size, rms_info *info, rms_error *err);

/* Decodes a payload into the caller's arrays (sized from rms_inspect()).
 * The whole payload is validated whatever arrays are requested, so a payload
 * accepted here is one the Rust decoder accepts. On failure the arrays hold
 * unspecified partial data. `out` and `err` must not be NULL. */
rms_status rms_decode(const uint8_t *data, size_t size, rms_output *out, rms_error *err);

/* Rebuilds the strip from a triangle list in strip order (the spec's
 * "Strip indices" rule; the same strip as Rust's geom::strip::restrip).
 * Returns the strip's length; writes its first min(length, capacity)
 * indices to `strip` (which may be NULL when capacity is 0, to ask for the
 * length). Indices are not range-checked here. */
size_t rms_restrip(const uint32_t *triangles, size_t triangle_count, uint32_t *strip, size_t capacity);

/* Copies `count` indices to 16 bits, mapping RMS_RESTART to RMS_RESTART_U16
 * (GLES 3 and Metal restart at the largest value of the index type). Only
 * meaningful when vertex_count < 65535. */
void rms_indices_to_u16(const uint32_t *in, size_t count, uint16_t *out);

/* CRC-32 (IEEE 802.3, as in zlib and PNG) of `size` bytes. */
uint32_t rms_crc32(const uint8_t *data, size_t size);

/* A short name for a status ("ok", "truncated", ...), never NULL. */
const char *rms_status_name(rms_status status);

#ifdef __cplusplus
}
#endif

#endif /* RULEMESH_STRIPS_H */
