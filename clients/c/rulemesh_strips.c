/* rulemesh_strips.c: the strips decoder (see rulemesh_strips.h and
 * docs/strips-format.md). C99, no dependencies beyond the C library's
 * <string.h>, <stdio.h> and <stdarg.h> (vsnprintf for messages) and <math.h>
 * (sqrt, fabs, isfinite).
 *
 * The meshoptimizer vertex codec (versions 0 and 1) and index buffer codec
 * (versions 0 and 1) below are a hand port of the scalar paths of
 * meshoptimizer's src/vertexcodec.cpp (decodeBytesGroup, decodeBytes,
 * decodeVertexBlock, meshopt_decodeVertexBuffer) and src/indexcodec.cpp
 * (decodeVByte, decodeIndex, meshopt_decodeIndexBuffer), version 1.3:
 *
 *   meshoptimizer, Copyright (c) 2016-2026 Arseny Kapoulkine.
 *   MIT License: Permission is hereby granted, free of charge, to any person
 *   obtaining a copy of this software and associated documentation files
 *   (the "Software"), to deal in the Software without restriction, including
 *   without limitation the rights to use, copy, modify, merge, publish,
 *   distribute, sublicense, and/or sell copies of the Software, and to permit
 *   persons to whom the Software is furnished to do so, subject to the
 *   following conditions: The above copyright notice and this permission
 *   notice shall be included in all copies or substantial portions of the
 *   Software. THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND,
 *   EXPRESS OR IMPLIED.
 *
 * Differences from the reference, all for safety on hostile input: every
 * read is checked against the stream's end (the reference relies on the
 * same checks but reads one speculative byte past some groups), vertices are
 * decoded one 256-vertex block at a time into a stack buffer (no allocation)
 * and validated as they come, and indices are written only inside the
 * caller's 3·T array.
 */
#include "rulemesh_strips.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* The spec's dequantisation is "f64 arithmetic, one rounding to f32": a
 * fused multiply-add would round once less and give floats that differ from
 * the Rust decoder's in the last bit. Clang (Xcode, the NDK) contracts
 * a*b+c by default on ARM64; this pragma forbids it. GCC ignores the pragma
 * but does not contract in ISO C mode (-std=c99). */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

#define HEADER_LEN 52u
#define TRAILER_LEN 4u
#define VERTEX_BYTES 16u
#define FLAG_ZSTD 1u
#define FLAG_PALETTE 2u
#define MAX_PALETTE 256u
/* Safety limits (docs/strips-format.md, "Decoder safety limits"). */
#define MAX_VERTICES_PER_STREAM_BYTE 64u
#define INDEX_STREAM_OVERHEAD 17u

/* ---- small helpers ---- */

static uint32_t u32_at(const uint8_t *p) {
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

static float f32_at(const uint8_t *p) {
    uint32_t bits = u32_at(p);
    float f;
    memcpy(&f, &bits, sizeof f); /* IEEE 754 binary32 on every target we build for */
    return f;
}

/* Fills `err` and returns its status, so failures read `return fail(...)`. */
static rms_status fail(rms_error *err, rms_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static rms_status fail(rms_error *err, rms_status status, const char *fmt, ...) {
    va_list ap;
    err->status = status;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return status;
}

static rms_status ok(rms_error *err) {
    err->status = RMS_OK;
    err->message[0] = '\0';
    return RMS_OK;
}

const char *rms_status_name(rms_status status) {
    switch (status) {
    case RMS_OK: return "ok";
    case RMS_ERR_ARGUMENT: return "argument";
    case RMS_ERR_TRUNCATED: return "truncated";
    case RMS_ERR_MAGIC: return "magic";
    case RMS_ERR_CHECKSUM: return "checksum";
    case RMS_ERR_VERSION: return "version";
    case RMS_ERR_ZSTD: return "zstd";
    case RMS_ERR_HEADER: return "header";
    case RMS_ERR_BODY: return "body";
    }
    return "unknown";
}

/* ---- CRC-32 ---- */

/* A 16-entry (nibble) table of the reflected polynomial 0xEDB88320: a
 * constant, so there is no lazily built table to race on between threads. */
static const uint32_t crc_nibble[16] = {
    0x00000000u, 0x1DB71064u, 0x3B6E20C8u, 0x26D930ACu, 0x76DC4190u, 0x6B6B51F4u, 0x4DB26158u, 0x5005713Cu,
    0xEDB88320u, 0xF00F9344u, 0xD6D6A3E8u, 0xCB61B38Cu, 0x9B64C2B0u, 0x86D3D2D4u, 0xA00AE278u, 0xBDBDF21Cu,
};

uint32_t rms_crc32(const uint8_t *data, size_t size) {
    uint32_t c = 0xFFFFFFFFu;
    size_t i;
    for (i = 0; i < size; i++) {
        c ^= data[i];
        c = (c >> 4) ^ crc_nibble[c & 15u];
        c = (c >> 4) ^ crc_nibble[c & 15u];
    }
    return c ^ 0xFFFFFFFFu;
}

/* ---- meshoptimizer vertex codec (decodeVertexBuffer) ---- */

#define VX_BLOCK_MAX 256u   /* kVertexBlockMaxSize; 16-byte vertices use full blocks */
#define VX_GROUP 16u        /* kByteGroupSize */
#define VX_GROUP_LIMIT 24u  /* kByteGroupDecodeLimit: most bytes one group reads */
#define VX_TAIL_MIN_V0 32u
#define VX_TAIL_MIN_V1 24u

static const int bits_v0[4] = {0, 2, 4, 8};
static const int bits_v1[5] = {0, 1, 2, 4, 8};

/* Decodes one group of 16 values of `bits` bits each into out[0..16] and
 * returns the bytes consumed. The caller has checked that VX_GROUP_LIMIT
 * bytes are readable at `data`, which covers the worst case (4-bit values:
 * 8 packed bytes and 16 escaped literals). */
static size_t decode_bytes_group(const uint8_t *data, uint8_t *out, int bits) {
    size_t packed, lit, i;
    unsigned sentinel;
    if (bits == 0) {
        memset(out, 0, VX_GROUP);
        return 0;
    }
    if (bits == 8) {
        memcpy(out, data, VX_GROUP);
        return VX_GROUP;
    }
    packed = (size_t)(VX_GROUP * (unsigned)bits / 8u);
    lit = packed; /* escaped literal bytes follow the packed ones */
    sentinel = (1u << bits) - 1u;
    for (i = 0; i < VX_GROUP; i++) {
        unsigned byte = data[i * (unsigned)bits / 8u];
        unsigned enc;
        if (bits == 1) {
            enc = (byte >> (i & 7u)) & 1u; /* 1-bit groups are least significant bit first */
        } else {
            unsigned per = 8u / (unsigned)bits;
            enc = (byte >> (8u - (unsigned)bits * (unsigned)(i % per + 1u))) & sentinel;
        }
        out[i] = enc == sentinel ? data[lit++] : (uint8_t)enc;
    }
    return lit;
}

/* Decodes `size` (a multiple of 16) bytes into `out`: a 2-bit-per-group
 * header choosing each group's width from `bits`, then the groups. Returns
 * the new position or 0 when the stream ends too early (0 is never a valid
 * position here: byte 0 is the stream header). */
static size_t decode_bytes(const uint8_t *data, size_t p, size_t end, uint8_t *out, size_t size, const int *bits) {
    size_t header_size = (size / VX_GROUP + 3u) / 4u, header = p, i;
    if (end - p < header_size) return 0;
    p += header_size;
    for (i = 0; i < size; i += VX_GROUP) {
        size_t g = i / VX_GROUP;
        int bitsk;
        if (end - p < VX_GROUP_LIMIT) return 0;
        bitsk = (data[header + g / 4u] >> ((g % 4u) * 2u)) & 3;
        p += decode_bytes_group(data + p, out + i, bits[bitsk]);
    }
    return p;
}

/* Decodes one block of `count` (1..=256) 16-byte vertices into
 * block[0 .. 16·count], updating `last` (the previous vertex, the delta
 * base). Returns the new position, or 0 on malformed data. */
static size_t decode_vertex_block(const uint8_t *data, size_t p, size_t end, uint8_t *block, size_t count,
                                  uint8_t last[VERTEX_BYTES], const uint8_t *channels, int version) {
    /* Byte column j of the current 4-byte lane at buffer[j·count ..]; the
     * last column's group decoding may write up to count rounded up to 16,
     * which 4·256 bytes always hold. */
    uint8_t buffer[VX_BLOCK_MAX * 4u];
    size_t aligned = (count + VX_GROUP - 1u) & ~(size_t)(VX_GROUP - 1u);
    size_t control_size = version == 0 ? 0 : VERTEX_BYTES / 4u, control = p, k, i, j;
    if (end - p < control_size) return 0;
    p += control_size;
    for (k = 0; k < VERTEX_BYTES; k += 4) {
        unsigned ctrl_byte = version == 0 ? 0u : data[control + k / 4u];
        int channel;
        for (j = 0; j < 4; j++) {
            unsigned ctrl = (ctrl_byte >> (j * 2u)) & 3u;
            if (ctrl == 3) { /* literal bytes */
                if (end - p < count) return 0;
                memcpy(buffer + j * count, data + p, count);
                p += count;
            } else if (ctrl == 2) { /* all zero */
                memset(buffer + j * count, 0, count);
            } else {
                p = decode_bytes(data, p, end, buffer + j * count, aligned, version == 0 ? bits_v0 : bits_v1 + ctrl);
                if (p == 0) return 0;
            }
        }
        channel = version == 0 ? 0 : channels[k / 4u];
        switch (channel & 3) {
        case 0: /* bytewise zigzag deltas */
            for (j = 0; j < 4; j++) {
                uint8_t prev = last[k + j];
                for (i = 0; i < count; i++) {
                    uint8_t v = buffer[j * count + i];
                    prev = (uint8_t)(((v & 1u) ? (uint8_t)~(v >> 1) : (uint8_t)(v >> 1)) + prev);
                    block[i * VERTEX_BYTES + k + j] = prev;
                }
            }
            break;
        case 1: /* 16-bit zigzag deltas */
            for (j = 0; j < 4; j += 2) {
                uint16_t prev = (uint16_t)(last[k + j] | (last[k + j + 1] << 8));
                for (i = 0; i < count; i++) {
                    uint16_t v = (uint16_t)(buffer[j * count + i] | (buffer[(j + 1) * count + i] << 8));
                    prev = (uint16_t)(((v & 1u) ? (uint16_t)~(v >> 1) : (uint16_t)(v >> 1)) + prev);
                    block[i * VERTEX_BYTES + k + j] = (uint8_t)prev;
                    block[i * VERTEX_BYTES + k + j + 1] = (uint8_t)(prev >> 8);
                }
            }
            break;
        case 2: { /* 32-bit rotated xor deltas */
            unsigned rot = (32u - ((unsigned)channel >> 4)) & 31u;
            uint32_t prev = u32_at(last + k);
            for (i = 0; i < count; i++) {
                uint32_t v = (uint32_t)buffer[i] | ((uint32_t)buffer[count + i] << 8) |
                             ((uint32_t)buffer[2 * count + i] << 16) | ((uint32_t)buffer[3 * count + i] << 24);
                v = ((v << rot) | (v >> ((32u - rot) & 31u))) ^ prev;
                block[i * VERTEX_BYTES + k] = (uint8_t)v;
                block[i * VERTEX_BYTES + k + 1] = (uint8_t)(v >> 8);
                block[i * VERTEX_BYTES + k + 2] = (uint8_t)(v >> 16);
                block[i * VERTEX_BYTES + k + 3] = (uint8_t)(v >> 24);
                prev = v;
            }
            break;
        }
        default:
            return 0; /* channel mode 3 does not exist */
        }
    }
    memcpy(last, block + (count - 1) * VERTEX_BYTES, VERTEX_BYTES);
    return p;
}

/* The vertex stream's framing: header byte, then blocks, then a tail (the
 * first vertex's delta base and, in version 1, the channel modes). */
typedef struct vx_stream {
    const uint8_t *data;
    size_t end, p, pad;
    int version;
    uint8_t last[VERTEX_BYTES];
    const uint8_t *channels;
} vx_stream;

static rms_status vx_open(vx_stream *s, const uint8_t *data, size_t size, rms_error *err) {
    size_t tail_size, tail_min;
    memset(s, 0, sizeof *s);
    if (size < 1) return fail(err, RMS_ERR_BODY, "invalid strips body: vertex stream empty");
    if ((data[0] & 0xF0u) != 0xA0u) return fail(err, RMS_ERR_BODY, "invalid strips body: vertex stream has a bad header");
    s->version = data[0] & 0x0F;
    if (s->version > 1) return fail(err, RMS_ERR_BODY, "invalid strips body: vertex codec version %d unsupported", s->version);
    tail_size = VERTEX_BYTES + (s->version == 0 ? 0u : VERTEX_BYTES / 4u);
    tail_min = s->version == 0 ? VX_TAIL_MIN_V0 : VX_TAIL_MIN_V1;
    s->pad = tail_size < tail_min ? tail_min : tail_size;
    if (size - 1 < s->pad) return fail(err, RMS_ERR_BODY, "invalid strips body: vertex stream truncated");
    s->data = data;
    s->end = size;
    s->p = 1;
    memcpy(s->last, data + size - tail_size, VERTEX_BYTES);
    s->channels = s->version == 0 ? NULL : data + size - tail_size + VERTEX_BYTES;
    return RMS_OK;
}

/* ---- meshoptimizer index buffer codec (decodeIndexBuffer) ---- */

/* A varint of up to 5 bytes. The caller guarantees 16 readable bytes (the
 * codeaux table at the stream's end makes the reference's check enough). */
static uint32_t decode_vbyte(const uint8_t *data, size_t *p) {
    uint32_t lead = data[(*p)++], result, shift = 7;
    int i;
    if (lead < 128) return lead;
    result = lead & 127u;
    for (i = 0; i < 4; i++) {
        uint32_t group = data[(*p)++];
        result |= (group & 127u) << shift;
        shift += 7;
        if (group < 128) break;
    }
    return result;
}

static uint32_t decode_index(const uint8_t *data, size_t *p, uint32_t last) {
    uint32_t v = decode_vbyte(data, p);
    uint32_t d = (v >> 1) ^ (0u - (v & 1u));
    return last + d;
}

/* Decodes 3·triangles indices into out. 0 on success, else a message. */
static const char *decode_index_buffer(const uint8_t *data, size_t size, uint32_t *out, size_t triangles) {
    uint32_t edge[16][2], vfifo[16], next = 0, last = 0;
    size_t eo = 0, vo = 0, code = 1, code_end, p, safe_end, o = 0;
    int version, fecmax;
    if (size < 1 + triangles + 16) return "index stream too short for its triangle count";
    if ((data[0] & 0xF0u) != 0xE0u) return "index stream has a bad header";
    version = data[0] & 0x0F;
    if (version > 1) return "index codec version unsupported";
    memset(edge, 0xFF, sizeof edge);
    memset(vfifo, 0xFF, sizeof vfifo);
    fecmax = version >= 1 ? 13 : 15;
    code_end = 1 + triangles;
    p = code_end;
    safe_end = size - 16; /* the 16-byte codeaux table */
#define PUSH_V(v, cond) (vfifo[vo] = (v), vo = (vo + (size_t)(cond)) & 15u)
#define PUSH_E(x, y) (edge[eo][0] = (x), edge[eo][1] = (y), eo = (eo + 1u) & 15u)
    while (code < code_end) {
        unsigned codetri = data[code++];
        uint32_t a, b, c;
        if (codetri < 0xF0u) {
            size_t fe = codetri >> 4;
            int fec = (int)(codetri & 15u);
            a = edge[(eo - 1 - fe) & 15u][0];
            b = edge[(eo - 1 - fe) & 15u][1];
            if (fec < fecmax) {
                uint32_t cf = vfifo[(vo - 1 - (size_t)fec) & 15u];
                c = fec == 0 ? next : cf;
                next += fec == 0;
                PUSH_V(c, fec == 0);
            } else {
                /* one vbyte at most: 5 bytes, inside the guaranteed 16 */
                if (p > safe_end) return "index stream truncated";
                c = fec != 15 ? last + (uint32_t)(fec * 2 - 27) : decode_index(data, &p, last);
                last = c;
                PUSH_V(c, 1);
            }
            PUSH_E(c, b);
            PUSH_E(a, c);
        } else if (codetri < 0xFEu) {
            unsigned codeaux = data[safe_end + (codetri & 15u)];
            size_t feb = codeaux >> 4, fec = codeaux & 15u;
            uint32_t bf, cf;
            a = next++;
            bf = vfifo[(vo - feb) & 15u];
            b = feb == 0 ? next : bf;
            next += feb == 0;
            cf = vfifo[(vo - fec) & 15u];
            c = fec == 0 ? next : cf;
            next += fec == 0;
            PUSH_V(a, 1);
            PUSH_V(b, feb == 0);
            PUSH_V(c, fec == 0);
            PUSH_E(b, a);
            PUSH_E(c, b);
            PUSH_E(a, c);
        } else {
            unsigned codeaux;
            size_t fea, feb, fec;
            /* one codeaux byte and three vbytes at most: 16 bytes */
            if (p > safe_end) return "index stream truncated";
            codeaux = data[p++];
            fea = codetri == 0xFEu ? 0 : 15;
            feb = codeaux >> 4;
            fec = codeaux & 15u;
            if (codeaux == 0) next = 0;
            a = fea == 0 ? next++ : 0;
            b = feb == 0 ? next++ : vfifo[(vo - feb) & 15u];
            c = fec == 0 ? next++ : vfifo[(vo - fec) & 15u];
            if (fea == 15) last = a = decode_index(data, &p, last);
            if (feb == 15) last = b = decode_index(data, &p, last);
            if (fec == 15) last = c = decode_index(data, &p, last);
            PUSH_V(a, 1);
            PUSH_V(b, feb == 0 || feb == 15);
            PUSH_V(c, fec == 0 || fec == 15);
            PUSH_E(b, a);
            PUSH_E(c, b);
            PUSH_E(a, c);
        }
        out[o++] = a;
        out[o++] = b;
        out[o++] = c;
    }
#undef PUSH_V
#undef PUSH_E
    if (p != safe_end) return "index stream has the wrong length";
    return NULL;
}

/* ---- strip rebuild (geom::strip::restrip) ---- */

/* The third corner of triangle t if it holds the directed edge p → q. */
static int third(const uint32_t *t, uint32_t p, uint32_t q, uint32_t *z) {
    if (t[0] == p && t[1] == q) { *z = t[2]; return 1; }
    if (t[1] == p && t[2] == q) { *z = t[0]; return 1; }
    if (t[2] == p && t[0] == q) { *z = t[1]; return 1; }
    return 0;
}

size_t rms_restrip(const uint32_t *tris, size_t n, uint32_t *strip, size_t capacity) {
    size_t len = 0, i = 0;
    /* x, y: the run's last two indices, kept here so a short buffer does not
     * change the result. */
    uint32_t x = 0, y = 0, z;
#define EMIT(v) do { uint32_t v_ = (v); if (len < capacity) strip[len] = v_; len++; } while (0)
    while (i < n) {
        const uint32_t *t = tris + 3 * i;
        uint32_t s0 = t[0], s1 = t[1], s2 = t[2];
        size_t k = 1;
        if (i > 0) EMIT(RMS_RESTART);
        if (i + 1 < n) {
            /* the first rotation whose last edge, reversed, the next triangle holds */
            const uint32_t *nt = tris + 3 * (i + 1);
            if (third(nt, t[2], t[1], &z)) {
                /* (a, b, c) */
            } else if (third(nt, t[0], t[2], &z)) {
                s0 = t[1];
                s1 = t[2];
                s2 = t[0];
            } else if (third(nt, t[1], t[0], &z)) {
                s0 = t[2];
                s1 = t[0];
                s2 = t[1];
            }
        }
        EMIT(s0);
        EMIT(s1);
        EMIT(s2);
        x = s1;
        y = s2;
        i++;
        while (i < n) {
            int found = (k % 2 == 0) ? third(tris + 3 * i, x, y, &z) : third(tris + 3 * i, y, x, &z);
            if (!found) break;
            EMIT(z);
            x = y;
            y = z;
            i++;
            k++;
        }
    }
#undef EMIT
    return len;
}

void rms_indices_to_u16(const uint32_t *in, size_t count, uint16_t *out) {
    size_t i;
    for (i = 0; i < count; i++) out[i] = in[i] == RMS_RESTART ? (uint16_t)RMS_RESTART_U16 : (uint16_t)in[i];
}

/* ---- the container ---- */

/* The header and body layout, read and checked once. */
typedef struct layout {
    rms_info info;
    uint8_t version;                 /* 2: one mesh; 3: a chunk list */
    const uint8_t *palette;          /* 4·P bytes, or NULL */
    const uint8_t *body;             /* the body and its length */
    size_t blen;
    size_t chunks_at;                /* where the first chunk starts in the body */
    uint32_t chunk_count;            /* 1 in version 2 */
} layout;

/* One chunk: its counts and streams (version 2's one mesh is one chunk). */
typedef struct chunk {
    uint32_t vertices, triangles;
    const uint8_t *vstream, *istream;
    size_t vlen, ilen;
} chunk;

/* Reads one stream of the body at *at: a u32 length, then that many bytes
 * (the vertex and the index stream are laid out alike). */
static rms_status length_prefixed(const uint8_t *body, size_t blen, size_t *at, const char *name, const uint8_t **stream,
                                  size_t *len, rms_error *err) {
    uint32_t n;
    if (blen - *at < 4) return fail(err, RMS_ERR_BODY, "invalid strips body: %s stream length missing", name);
    n = u32_at(body + *at);
    if (blen - *at - 4 < n)
        return fail(err, RMS_ERR_BODY, "invalid strips body: %s stream says %lu bytes, only %lu left", name, (unsigned long)n,
                    (unsigned long)(blen - *at - 4));
    *stream = body + *at + 4;
    *len = n;
    *at += 4 + (size_t)n;
    return RMS_OK;
}

/* Reads a u32 of the body at *at. */
static rms_status body_u32(const uint8_t *body, size_t blen, size_t *at, const char *name, uint32_t *v, rms_error *err) {
    if (blen - *at < 4) return fail(err, RMS_ERR_BODY, "invalid strips body: %s missing", name);
    *v = u32_at(body + *at);
    *at += 4;
    return RMS_OK;
}

/* Reads the chunk `k` at *at (version 3: counts, then the two streams;
 * version 2: the streams, with the header's counts) and checks its counts
 * against its streams' lengths (the safety limits of the spec). */
static rms_status read_chunk(const layout *l, size_t *at, uint32_t k, chunk *c, rms_error *err) {
    rms_status st;
    char name[40];
    if (l->version == 2) {
        c->vertices = l->info.vertex_count;
        c->triangles = l->info.triangle_count;
        name[0] = 0;
    } else {
        st = body_u32(l->body, l->blen, at, "chunk vertex count", &c->vertices, err);
        if (st != RMS_OK) return st;
        st = body_u32(l->body, l->blen, at, "chunk triangle count", &c->triangles, err);
        if (st != RMS_OK) return st;
        snprintf(name, sizeof name, "chunk %lu: ", (unsigned long)k);
    }
    st = length_prefixed(l->body, l->blen, at, "vertex", &c->vstream, &c->vlen, err);
    if (st != RMS_OK) return st;
    st = length_prefixed(l->body, l->blen, at, "index", &c->istream, &c->ilen, err);
    if (st != RMS_OK) return st;
    if ((uint64_t)c->vertices > (uint64_t)c->vlen * MAX_VERTICES_PER_STREAM_BYTE + 256u)
        return fail(err, RMS_ERR_HEADER, "invalid strips header: %s%lu vertices cannot fit in a %lu-byte vertex stream", name,
                    (unsigned long)c->vertices, (unsigned long)c->vlen);
    if ((uint64_t)c->triangles + INDEX_STREAM_OVERHEAD > (uint64_t)c->ilen)
        return fail(err, RMS_ERR_HEADER, "invalid strips header: %s%lu triangles cannot fit in a %lu-byte index stream", name,
                    (unsigned long)c->triangles, (unsigned long)c->ilen);
    return RMS_OK;
}

static rms_status parse(const uint8_t *data, size_t size, layout *l, rms_error *err) {
    const size_t min = HEADER_LEN + TRAILER_LEN;
    uint64_t body_len, expected;
    uint32_t stored, computed, raw_len;
    rms_status st;
    uint8_t version, flags, pb, nb;
    const uint8_t *body;
    size_t blen, at, a;
    rms_info *info = &l->info;
    if (data == NULL && size > 0) return fail(err, RMS_ERR_ARGUMENT, "data is NULL");
    if (size < min)
        return fail(err, RMS_ERR_TRUNCATED, "strips payload truncated: %lu bytes, the header and CRC alone need %lu",
                    (unsigned long)size, (unsigned long)min);
    if (memcmp(data, "RMST", 4) != 0) return fail(err, RMS_ERR_MAGIC, "not a strips payload (bad magic)");
    body_len = u32_at(data + 44);
    expected = body_len + min;
    if (expected != (uint64_t)size)
        return fail(err, RMS_ERR_TRUNCATED, "strips payload truncated or padded: the header promises %lu bytes, got %lu",
                    (unsigned long)expected, (unsigned long)size);
    stored = u32_at(data + size - TRAILER_LEN);
    computed = rms_crc32(data, size - TRAILER_LEN);
    if (stored != computed)
        return fail(err, RMS_ERR_CHECKSUM, "strips payload corrupted: CRC32 is %08lx, the file says %08lx",
                    (unsigned long)computed, (unsigned long)stored);
    version = data[4];
    flags = data[5];
    pb = data[6];
    nb = data[7];
    if (version != 2 && version != 3)
        return fail(err, RMS_ERR_VERSION, "unsupported strips version %u (this decoder reads versions 2 and 3)", version);
    l->version = version;
    if (flags & ~(FLAG_ZSTD | FLAG_PALETTE)) return fail(err, RMS_ERR_HEADER, "invalid strips header: unknown flags 0x%02x", flags);
    if (flags & FLAG_ZSTD)
        return fail(err, RMS_ERR_ZSTD,
                    "this payload is zstd-wrapped; the C decoder reads only unwrapped payloads (request zstd=false)");
    if (!(pb == 8 || pb == 10 || pb == 12 || pb == 16) || !(nb == 8 || nb == 16))
        return fail(err, RMS_ERR_HEADER, "invalid strips header: position bits %u, normal bits %u", pb, nb);
    for (a = 0; a < 3; a++) {
        float lo = f32_at(data + 8 + 4 * a), hi = f32_at(data + 20 + 4 * a);
        if (!isfinite(lo) || !isfinite(hi) || lo > hi)
            return fail(err, RMS_ERR_HEADER, "invalid strips header: bounding box not finite or min > max");
        info->bbox_min[a] = lo;
        info->bbox_max[a] = hi;
    }
    info->vertex_count = u32_at(data + 32);
    info->triangle_count = u32_at(data + 36);
    info->palette_count = u32_at(data + 40);
    raw_len = u32_at(data + 48);
    info->position_bits = pb;
    info->normal_bits = nb;
    info->flags = flags;
    if (((flags & FLAG_PALETTE) != 0) != (info->palette_count > 0) || info->palette_count > MAX_PALETTE)
        return fail(err, RMS_ERR_HEADER, "invalid strips header: palette of %lu entries with palette flag %s",
                    (unsigned long)info->palette_count, (flags & FLAG_PALETTE) ? "true" : "false");
    body = data + HEADER_LEN;
    blen = size - min;
    if ((uint64_t)blen != raw_len)
        return fail(err, RMS_ERR_BODY, "invalid strips body: body is %lu bytes, the header says %lu", (unsigned long)blen,
                    (unsigned long)raw_len);
    at = 4u * info->palette_count;
    if (blen < at) return fail(err, RMS_ERR_BODY, "invalid strips body: palette cut short");
    l->palette = info->palette_count ? body : NULL;
    l->body = body;
    l->blen = blen;
    if (info->vertex_count == RMS_RESTART)
        return fail(err, RMS_ERR_HEADER, "invalid strips header: %lu vertices: the restart index is no vertex",
                    (unsigned long)info->vertex_count);
    l->chunk_count = 1;
    if (version == 3) {
        st = body_u32(body, blen, &at, "chunk count", &l->chunk_count, err);
        if (st != RMS_OK) return st;
        if ((uint64_t)l->chunk_count * 16u > (uint64_t)(blen - at))
            return fail(err, RMS_ERR_HEADER, "invalid strips header: %lu chunks cannot fit in %lu bytes", (unsigned long)l->chunk_count,
                        (unsigned long)(blen - at));
    }
    l->chunks_at = at;
    {
        /* Walk the chunk list once: every chunk's counts against its streams, and the sums against the header. */
        uint64_t vsum = 0, tsum = 0;
        uint32_t k;
        chunk c;
        for (k = 0; k < l->chunk_count; k++) {
            st = read_chunk(l, &at, k, &c, err);
            if (st != RMS_OK) return st;
            vsum += c.vertices;
            tsum += c.triangles;
        }
        if (vsum != info->vertex_count || tsum != info->triangle_count)
            return fail(err, RMS_ERR_HEADER, "invalid strips header: chunks hold %lu vertices and %lu triangles, the header says %lu and %lu",
                        (unsigned long)vsum, (unsigned long)tsum, (unsigned long)info->vertex_count,
                        (unsigned long)info->triangle_count);
    }
    if (at != blen)
        return fail(err, RMS_ERR_BODY, "invalid strips body: %lu stray bytes after the index stream", (unsigned long)(blen - at));
#if SIZE_MAX / 16u < UINT32_MAX
    /* With a 32-bit size_t (armv7), the arrays a caller allocates must still
     * be addressable; on 64 bits every u32 count is. */
    if (info->triangle_count > SIZE_MAX / 16u || info->vertex_count > SIZE_MAX / 16u)
        return fail(err, RMS_ERR_HEADER, "invalid strips header: counts too large for this platform");
#endif
    info->strip_capacity = info->triangle_count ? 4u * (size_t)info->triangle_count - 1u : 0u;
    return ok(err);
}

rms_status rms_inspect(const uint8_t *data, size_t size, rms_info *info, rms_error *err) {
    layout l;
    rms_status s;
    if (err == NULL) return RMS_ERR_ARGUMENT;
    if (info == NULL) return fail(err, RMS_ERR_ARGUMENT, "info is NULL");
    s = parse(data, size, &l, err);
    if (s == RMS_OK) *info = l.info;
    return s;
}

/* Octahedral decode in double, rounded once (Rust's decode::strips::oct_decode). */
static void oct_decode(unsigned qx, unsigned qy, double m, float *out) {
    double x = (double)qx / m * 2.0 - 1.0;
    double y = (double)qy / m * 2.0 - 1.0;
    double z = 1.0 - fabs(x) - fabs(y);
    double len, xx, yy, zz;
    if (z < 0.0) {
        double ox = x, oy = y;
        x = (1.0 - fabs(oy)) * (ox >= 0.0 ? 1.0 : -1.0);
        y = (1.0 - fabs(ox)) * (oy >= 0.0 ? 1.0 : -1.0);
    }
    /* separate statements, so no compiler fuses the products into the sums */
    xx = x * x;
    yy = y * y;
    zz = z * z;
    len = sqrt(xx + yy + zz);
    out[0] = (float)(x / len);
    out[1] = (float)(y / len);
    out[2] = (float)(z / len);
}

/* Checks and dequantises one block of raw vertices into the outputs. */
static rms_status emit_block(const layout *l, const uint8_t *block, size_t first, size_t count, rms_output *out,
                             rms_error *err) {
    const rms_info *info = &l->info;
    const unsigned pmax = (1u << info->position_bits) - 1u, nmax = (1u << info->normal_bits) - 1u;
    size_t i, a;
    for (i = 0; i < count; i++) {
        const uint8_t *v = block + i * VERTEX_BYTES;
        size_t k = first + i;
        unsigned q[6];
        for (a = 0; a < 6; a++) q[a] = (unsigned)v[2 * a] | ((unsigned)v[2 * a + 1] << 8);
        if (q[0] > pmax || q[1] > pmax || q[2] > pmax || q[3] != 0 || q[4] > nmax || q[5] > nmax)
            return fail(err, RMS_ERR_BODY, "invalid strips body: vertex %lu has a value out of range for its bit count",
                        (unsigned long)k);
        if (l->palette && (v[13] | v[14] | v[15]) != 0)
            return fail(err, RMS_ERR_BODY, "invalid strips body: vertex %lu: palette padding not zero", (unsigned long)k);
        if (l->palette && v[12] >= info->palette_count)
            return fail(err, RMS_ERR_BODY, "invalid strips body: vertex %lu: palette index %u out of range", (unsigned long)k,
                        v[12]);
        if (out->positions) {
            for (a = 0; a < 3; a++) {
                /* lo + q·(hi − lo)/M, in this order, in double (the spec) */
                double lo = (double)info->bbox_min[a], hi = (double)info->bbox_max[a];
                double ext = hi - lo, scaled = (double)q[a] * ext, step = scaled / (double)pmax;
                out->positions[3 * k + a] = (float)(lo + step);
            }
        }
        if (out->normals) oct_decode(q[4], q[5], (double)nmax, out->normals + 3 * k);
        if (out->colours) memcpy(out->colours + 4 * k, l->palette ? l->palette + 4u * v[12] : v + 12, 4);
    }
    return RMS_OK;
}

rms_status rms_decode(const uint8_t *data, size_t size, rms_output *out, rms_error *err) {
    layout l;
    rms_status s;
    vx_stream vs;
    uint8_t block[VX_BLOCK_MAX * VERTEX_BYTES];
    const char *why;
    size_t t, n3, done, at, vbase = 0, tbase = 0;
    uint32_t k;
    chunk c;
    if (err == NULL) return RMS_ERR_ARGUMENT;
    if (out == NULL) return fail(err, RMS_ERR_ARGUMENT, "out is NULL");
    out->strip_length = 0;
    s = parse(data, size, &l, err);
    if (s != RMS_OK) return s;
    n3 = 3u * (size_t)l.info.triangle_count;
    if (out->triangles == NULL && n3 > 0) return fail(err, RMS_ERR_ARGUMENT, "out->triangles is NULL");
    if (out->strip == NULL && out->strip_capacity > 0) return fail(err, RMS_ERR_ARGUMENT, "out->strip is NULL");

    /* Chunk by chunk; within one, triangles first: they go straight into the caller's array. */
    at = l.chunks_at;
    for (k = 0; k < l.chunk_count; k++) {
        uint32_t *tris = out->triangles ? out->triangles + 3u * tbase : NULL;
        s = read_chunk(&l, &at, k, &c, err);
        if (s != RMS_OK) return s;
        n3 = 3u * (size_t)c.triangles;
        why = decode_index_buffer(c.istream, c.ilen, tris, c.triangles);
        if (why) return fail(err, RMS_ERR_BODY, "invalid strips body: %s", why);
        for (t = 0; t < n3; t++) {
            if (tris[t] >= c.vertices)
                return fail(err, RMS_ERR_BODY, "invalid strips body: index %lu out of range (%lu vertices)", (unsigned long)tris[t],
                            (unsigned long)c.vertices);
        }
        for (t = 0; t < n3; t += 3) {
            const uint32_t *tr = tris + t;
            if (tr[0] == tr[1] || tr[1] == tr[2] || tr[0] == tr[2])
                return fail(err, RMS_ERR_BODY, "invalid strips body: triangle %lu has a repeated index", (unsigned long)(t / 3));
        }
        /* Fits: the header's vertex count (the sum) is below RMS_RESTART. */
        for (t = 0; t < n3; t++) tris[t] += (uint32_t)vbase;

        /* Vertices one block at a time through a 4 KiB stack buffer. */
        s = vx_open(&vs, c.vstream, c.vlen, err);
        if (s != RMS_OK) return s;
        for (done = 0; done < c.vertices;) {
            size_t count = c.vertices - done < VX_BLOCK_MAX ? c.vertices - done : VX_BLOCK_MAX;
            vs.p = decode_vertex_block(vs.data, vs.p, vs.end, block, count, vs.last, vs.channels, vs.version);
            if (vs.p == 0) return fail(err, RMS_ERR_BODY, "invalid strips body: vertex stream does not decode (truncated or corrupt)");
            s = emit_block(&l, block, vbase + done, count, out, err);
            if (s != RMS_OK) return s;
            done += count;
        }
        if (vs.end - vs.p != vs.pad) return fail(err, RMS_ERR_BODY, "invalid strips body: vertex stream has the wrong length");
        vbase += c.vertices;
        tbase += c.triangles;
    }

    if (out->strip) {
        size_t len = rms_restrip(out->triangles, l.info.triangle_count, out->strip, out->strip_capacity);
        if (len > out->strip_capacity)
            return fail(err, RMS_ERR_ARGUMENT, "strip buffer holds %lu indices, the strip needs %lu",
                        (unsigned long)out->strip_capacity, (unsigned long)len);
        out->strip_length = len;
    }
    return ok(err);
}
