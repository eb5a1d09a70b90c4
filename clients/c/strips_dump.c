/* strips_dump: the test driver of the C strips decoder (tests/it/c_decoder.rs
 * runs it; it is also a usage example of the two-call API).
 *
 *   strips_dump FILE OUT    decode FILE and write its arrays to OUT (format
 *                           below); exit 1 with "error <status>: <message>"
 *                           on stderr if the decoder refuses FILE
 *   strips_dump --batch F   F holds payloads, each a u32 LE length and its
 *                           bytes; print one line per payload: "ok <FNV-1a
 *                           64 of its dump, hex>" or "err <status>"
 *   strips_dump --truncate FILE
 *                           the same lines for every prefix FILE[..n],
 *                           n = 0 .. len−1
 *   strips_dump --mutate FILE X FIX
 *                           the same lines for FILE with byte i XORed with X
 *                           (decimal), i = 0 .. len−1; with FIX = 1 the
 *                           CRC is recomputed afterwards (for i < len − 4),
 *                           so the damage reaches the streams
 *
 * Each payload is decoded from its own exact-size heap copy, so
 * AddressSanitizer reports any read past its end.
 *
 * The dump (all little-endian): "RMSD", position bits (u8), normal bits
 * (u8), two zero bytes, V, T, S (strip length), P (palette entries) as u32,
 * then the bits of 3·V position floats, 3·V normal floats, 4·V colour bytes,
 * 3·T triangle indices and S strip indices. tests/it/c_decoder.rs builds the
 * same bytes from the Rust decoder's output and compares them.
 *
 * Besides decoding, the driver checks what only C can see: rms_inspect agrees
 * with rms_decode, rms_restrip's length-only call gives the decoded strip's
 * length, and a strip buffer one index short is refused with
 * RMS_ERR_ARGUMENT. A failed check exits 3.
 */
#include "rulemesh_strips.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct buf {
    uint8_t *data;
    size_t len, cap;
} buf;

static void put(buf *b, const void *p, size_t n) {
    if (b->len + n > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        while (cap < b->len + n) cap *= 2;
        b->data = realloc(b->data, cap);
        if (!b->data) {
            fprintf(stderr, "strips_dump: out of memory\n");
            exit(2);
        }
        b->cap = cap;
    }
    memcpy(b->data + b->len, p, n);
    b->len += n;
}

static void put_u32(buf *b, uint32_t v) {
    uint8_t le[4];
    le[0] = (uint8_t)v, le[1] = (uint8_t)(v >> 8), le[2] = (uint8_t)(v >> 16), le[3] = (uint8_t)(v >> 24);
    put(b, le, 4);
}

static void put_f32(buf *b, float f) {
    uint32_t bits;
    memcpy(&bits, &f, 4);
    put_u32(b, bits);
}

static void check(int cond, const char *what) {
    if (!cond) {
        fprintf(stderr, "strips_dump: check failed: %s\n", what);
        exit(3);
    }
}

/* Whether decode_to_dump also tries a strip buffer one index short (the
 * single-file mode does; the bulk modes skip it, it doubles their time). */
static int check_short_strip = 1;

/* Decodes one payload into `dump` (emptied first). Returns the status. */
static rms_status decode_to_dump(const uint8_t *data, size_t size, buf *dump, rms_error *err) {
    rms_info info;
    rms_output out;
    rms_status s;
    size_t v, i, n3;
    dump->len = 0;
    s = rms_inspect(data, size, &info, err);
    if (s != RMS_OK) return s;
    v = info.vertex_count;
    n3 = 3u * (size_t)info.triangle_count;
    memset(&out, 0, sizeof out);
    /* +1: malloc(0) may return NULL, and NULL is "skip" for the attributes */
    out.positions = malloc((3 * v + 1) * sizeof(float));
    out.normals = malloc((3 * v + 1) * sizeof(float));
    out.colours = malloc(4 * v + 1);
    out.triangles = malloc((n3 + 1) * sizeof(uint32_t));
    out.strip = malloc((info.strip_capacity + 1) * sizeof(uint32_t));
    out.strip_capacity = info.strip_capacity;
    if (!out.positions || !out.normals || !out.colours || !out.triangles || !out.strip) {
        fprintf(stderr, "strips_dump: out of memory\n");
        exit(2);
    }
    s = rms_decode(data, size, &out, err);
    if (s == RMS_OK) {
        size_t len = out.strip_length;
        check(rms_restrip(out.triangles, info.triangle_count, NULL, 0) == len, "length-only rms_restrip");
        if (check_short_strip && len > 0) {
            rms_output short_out = out;
            rms_error e2;
            short_out.strip_capacity = len - 1;
            check(rms_decode(data, size, &short_out, &e2) == RMS_ERR_ARGUMENT, "a short strip buffer is refused");
        }
        put(dump, "RMSD", 4);
        put(dump, &info.position_bits, 1);
        put(dump, &info.normal_bits, 1);
        put(dump, "\0\0", 2);
        put_u32(dump, info.vertex_count);
        put_u32(dump, info.triangle_count);
        put_u32(dump, (uint32_t)len);
        put_u32(dump, info.palette_count);
        for (i = 0; i < 3 * v; i++) put_f32(dump, out.positions[i]);
        for (i = 0; i < 3 * v; i++) put_f32(dump, out.normals[i]);
        put(dump, out.colours, 4 * v);
        for (i = 0; i < n3; i++) put_u32(dump, out.triangles[i]);
        for (i = 0; i < len; i++) put_u32(dump, out.strip[i]);
    } else {
        check(err->message[0] != '\0', "an error has a message");
    }
    free(out.positions);
    free(out.normals);
    free(out.colours);
    free(out.triangles);
    free(out.strip);
    return s;
}

static uint8_t *read_file(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    buf b = {NULL, 0, 0};
    uint8_t chunk[65536];
    size_t n;
    if (!f) {
        fprintf(stderr, "strips_dump: cannot open %s\n", path);
        exit(2);
    }
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) put(&b, chunk, n);
    fclose(f);
    put(&b, "", 1); /* so an empty file is not a NULL buffer */
    *len = b.len - 1;
    return b.data;
}

static uint64_t fnv1a64(const uint8_t *p, size_t n);

/* Decodes a heap copy of data[0..n] and prints its result line. */
static void line(const uint8_t *data, size_t n, buf *dump) {
    rms_error err;
    rms_status s;
    uint8_t *one;
    check_short_strip = 0;
    one = malloc(n ? n : 1);
    if (!one) exit(2);
    memcpy(one, data, n);
    s = decode_to_dump(one, n, dump, &err);
    free(one);
    if (s == RMS_OK) printf("ok %016llx\n", (unsigned long long)fnv1a64(dump->data, dump->len));
    else printf("err %s\n", rms_status_name(s));
}

static uint64_t fnv1a64(const uint8_t *p, size_t n) {
    uint64_t h = 0xcbf29ce484222325u;
    size_t i;
    for (i = 0; i < n; i++) {
        h ^= p[i];
        h *= 0x100000001b3u;
    }
    return h;
}

int main(int argc, char **argv) {
    buf dump = {NULL, 0, 0};
    rms_error err;
    size_t len;
    uint8_t *data;
    if (argc == 3 && strcmp(argv[1], "--batch") == 0) {
        size_t at = 0;
        data = read_file(argv[2], &len);
        while (at < len) {
            uint32_t n;
            if (len - at < 4) break;
            n = (uint32_t)data[at] | ((uint32_t)data[at + 1] << 8) | ((uint32_t)data[at + 2] << 16) | ((uint32_t)data[at + 3] << 24);
            at += 4;
            if (len - at < n) break;
            line(data + at, n, &dump);
            at += n;
        }
        free(data);
        free(dump.data);
        if (at != len) {
            fprintf(stderr, "strips_dump: batch file ends inside a record\n");
            return 2;
        }
        return 0;
    }
    if (argc == 3 && strcmp(argv[1], "--truncate") == 0) {
        size_t n;
        data = read_file(argv[2], &len);
        for (n = 0; n < len; n++) line(data, n, &dump);
        free(data);
        free(dump.data);
        return 0;
    }
    if (argc == 5 && strcmp(argv[1], "--mutate") == 0) {
        uint8_t x = (uint8_t)atoi(argv[3]);
        int fix = atoi(argv[4]);
        size_t i;
        data = read_file(argv[2], &len);
        for (i = 0; i < len; i++) {
            data[i] ^= x;
            if (fix && len >= 4 && i < len - 4) {
                uint32_t c = rms_crc32(data, len - 4);
                uint8_t saved[4];
                memcpy(saved, data + len - 4, 4);
                data[len - 4] = (uint8_t)c, data[len - 3] = (uint8_t)(c >> 8);
                data[len - 2] = (uint8_t)(c >> 16), data[len - 1] = (uint8_t)(c >> 24);
                line(data, len, &dump);
                memcpy(data + len - 4, saved, 4);
            } else {
                line(data, len, &dump);
            }
            data[i] ^= x;
        }
        free(data);
        free(dump.data);
        return 0;
    }
    if (argc == 3) {
        FILE *f;
        rms_status s;
        data = read_file(argv[1], &len);
        s = decode_to_dump(data, len, &dump, &err);
        free(data);
        if (s != RMS_OK) {
            fprintf(stderr, "error %s: %s\n", rms_status_name(s), err.message);
            free(dump.data);
            return 1;
        }
        f = fopen(argv[2], "wb");
        if (!f || fwrite(dump.data, 1, dump.len, f) != dump.len || fclose(f) != 0) {
            fprintf(stderr, "strips_dump: cannot write %s\n", argv[2]);
            return 2;
        }
        free(dump.data);
        return 0;
    }
    fprintf(stderr, "usage: strips_dump FILE OUT | strips_dump --batch FILE\n");
    return 2;
}
