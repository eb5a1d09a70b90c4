/* scene_dump: the test driver of the C scene decoder (tests/it/c_scene.rs),
 * and an example of the API.
 *
 *   scene_dump IN.rmscene OUT.dump     decode, write the dump below
 *   scene_dump --truncate IN           a result line per prefix (0 .. size-1 bytes)
 *   scene_dump --mutate IN XOR         a result line per byte of IN, that byte ^= XOR
 *   scene_dump --batch IN              a result line per payload of IN
 *                                      (each a u32 little-endian length, then the bytes)
 *
 * Result lines are "ok <FNV-1a 64 of the dump, hex>" or "err <status name>";
 * in those modes the dump is hashed as it is made, never stored.
 * Every decode runs on an exactly sized heap copy with exactly sized
 * buffers, so AddressSanitizer sees any read or write outside them. The
 * version 1 detail is RMSC_V1_DETAIL and the triangle limit 20 000 000
 * (the test's Rust side uses the same).
 *
 * The dump: "RMSS", u32 mesh count, then per mesh u32 name length, the
 * name, u32 V, u32 T, positions (3·V f32 bits), normals (3·V), colours
 * (4·V bytes), indices (3·T u32): the meshes as rmsc_decode wrote them.
 */
#include "rulemesh_scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_TRIANGLES 20000000u

/* Where a dump goes: a growing buffer, or (result lines) only its FNV-1a
 * 64 hash, computed as the bytes come (a 24 MB dump built and hashed per
 * flipped byte would cost four times the decode). */
typedef struct buf {
    uint8_t *data;
    size_t len, cap;
    int hash_only;
    uint64_t hash;
} buf;

#define FNV_OFFSET 0xcbf29ce484222325u
#define FNV_PRIME 0x100000001b3u

static void *must(void *p) {
    if (!p) {
        fprintf(stderr, "scene_dump: out of memory\n");
        exit(2);
    }
    return p;
}

static void put(buf *b, const void *p, size_t n) {
    if (b->hash_only) {
        const uint8_t *q = p;
        uint64_t h = b->hash;
        for (size_t i = 0; i < n; i++) h = (h ^ q[i]) * FNV_PRIME;
        b->hash = h;
        b->len += n;
        return;
    }
    if (b->len + n > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        while (cap < b->len + n) cap *= 2;
        b->data = must(realloc(b->data, cap));
        b->cap = cap;
    }
    if (n) memcpy(b->data + b->len, p, n);
    b->len += n;
}

static void put_u32(buf *b, uint32_t v) {
    uint8_t le[4];
    le[0] = (uint8_t)v;
    le[1] = (uint8_t)(v >> 8);
    le[2] = (uint8_t)(v >> 16);
    le[3] = (uint8_t)(v >> 24);
    put(b, le, 4);
}

static void put_f32(buf *b, float f) {
    uint32_t bits;
    memcpy(&bits, &f, 4);
    put_u32(b, bits);
}

static void check(int cond, const char *what) {
    if (!cond) {
        fprintf(stderr, "scene_dump: check failed: %s\n", what);
        exit(3);
    }
}

/* Whether decode_to_dump also checks that one byte less of scratch, or a
 * vertex less of room, is refused (the single-file mode). */
static int check_short = 1;

/* The API's use: inspect with a scratch of rmsc_inspect_scratch(size),
 * allocate what rmsc_info says, decode. Fills `dump`; returns the status. */
static rmsc_status decode_to_dump(const uint8_t *data, size_t size, buf *dump, rmsc_error *err) {
    rmsc_info info;
    rmsc_output out;
    rmsc_status s;
    void *scratch = must(malloc(rmsc_inspect_scratch(size)));
    dump->len = 0;
    dump->hash = FNV_OFFSET;
    s = rmsc_inspect(data, size, RMSC_V1_DETAIL, MAX_TRIANGLES, scratch, rmsc_inspect_scratch(size), &info, err);
    free(scratch);
    if (s != RMSC_OK) {
        check(err->message[0] != '\0', "an error has a message");
        return s;
    }
    memset(&out, 0, sizeof out);
    /* exact sizes (+1 where a count may be 0: malloc(0) may be NULL) */
    out.positions = must(malloc(3 * info.vertex_count * sizeof(float) + 1));
    out.normals = must(malloc(3 * info.vertex_count * sizeof(float) + 1));
    out.colours = must(malloc(4 * info.vertex_count + 1));
    out.indices = must(malloc(3 * info.triangle_count * sizeof(uint32_t) + 1));
    out.meshes = must(malloc(info.mesh_count * sizeof(rmsc_mesh) + 1));
    out.scratch = must(malloc(info.scratch_bytes + 1));
    out.vertex_capacity = info.vertex_count;
    out.triangle_capacity = info.triangle_count;
    out.mesh_capacity = info.mesh_count;
    out.scratch_bytes = info.scratch_bytes;
    if (check_short) {
        rmsc_output o = out;
        rmsc_error e;
        o.scratch_bytes = info.scratch_bytes - 1;
        check(info.scratch_bytes == 0 || rmsc_decode(data, size, RMSC_V1_DETAIL, MAX_TRIANGLES, &o, &e) == RMSC_ERR_ARGUMENT, "one byte less of scratch is refused");
        o = out;
        o.vertex_capacity = info.vertex_count - 1;
        check(info.vertex_count == 0 || rmsc_decode(data, size, RMSC_V1_DETAIL, MAX_TRIANGLES, &o, &e) == RMSC_ERR_ARGUMENT, "a vertex less of room is refused");
    }
    s = rmsc_decode(data, size, RMSC_V1_DETAIL, MAX_TRIANGLES, &out, err);
    if (s == RMSC_OK) {
        put(dump, "RMSS", 4);
        put_u32(dump, info.mesh_count);
        for (uint32_t m = 0; m < info.mesh_count; m++) {
            const rmsc_mesh *me = &out.meshes[m];
            const size_t v0 = me->first_vertex;
            check(me->vertex_count <= me->vertex_capacity && me->triangle_count <= me->triangle_capacity, "counts within the room");
            check(v0 + me->vertex_capacity <= info.vertex_count && me->first_index + 3 * (size_t)me->triangle_capacity <= 3 * info.triangle_count, "room within the arrays");
            put_u32(dump, (uint32_t)me->name_length);
            put(dump, me->name, me->name_length);
            put_u32(dump, me->vertex_count);
            put_u32(dump, me->triangle_count);
            for (size_t i = 0; i < 3 * (size_t)me->vertex_count; i++) put_f32(dump, out.positions[3 * v0 + i]);
            for (size_t i = 0; i < 3 * (size_t)me->vertex_count; i++) put_f32(dump, out.normals[3 * v0 + i]);
            put(dump, out.colours + 4 * v0, 4 * (size_t)me->vertex_count);
            for (size_t i = 0; i < 3 * (size_t)me->triangle_count; i++) {
                const uint32_t x = out.indices[me->first_index + i];
                check(x < me->vertex_count, "an index below the mesh's vertex count");
                put_u32(dump, x);
            }
        }
    } else {
        check(err->message[0] != '\0', "an error has a message");
    }
    free(out.positions);
    free(out.normals);
    free(out.colours);
    free(out.indices);
    free(out.meshes);
    free(out.scratch);
    return s;
}

static uint8_t *read_file(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    buf b = {NULL, 0, 0, 0, 0};
    uint8_t chunk[65536];
    size_t n;
    b.hash_only = 0;
    if (!f) {
        fprintf(stderr, "scene_dump: cannot open %s\n", path);
        exit(2);
    }
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) put(&b, chunk, n);
    fclose(f);
    put(&b, "", 1); /* so an empty file is not a NULL buffer */
    *len = b.len - 1;
    return b.data;
}

/* Decodes an exactly sized heap copy of data[0..n] and prints its result line. */
static void line(const uint8_t *data, size_t n, buf *dump) {
    rmsc_error err;
    rmsc_status s;
    uint8_t *one = must(malloc(n ? n : 1));
    memcpy(one, data, n);
    s = decode_to_dump(one, n, dump, &err);
    free(one);
    if (s == RMSC_OK) printf("ok %016llx\n", (unsigned long long)dump->hash);
    else printf("err %s\n", rmsc_status_name(s));
}

int main(int argc, char **argv) {
    buf dump = {NULL, 0, 0, 1, 0}; /* result lines hash; the single-file mode below stores */
    size_t len;
    uint8_t *data;
    if (argc == 3 && strcmp(argv[1], "--truncate") == 0) {
        check_short = 0;
        data = read_file(argv[2], &len);
        for (size_t n = 0; n < len; n++) line(data, n, &dump);
    } else if (argc == 4 && strcmp(argv[1], "--mutate") == 0) {
        const uint8_t x = (uint8_t)atoi(argv[3]);
        check_short = 0;
        data = read_file(argv[2], &len);
        for (size_t i = 0; i < len; i++) {
            data[i] ^= x;
            line(data, len, &dump);
            data[i] ^= x;
        }
    } else if (argc == 3 && strcmp(argv[1], "--batch") == 0) {
        size_t at = 0;
        check_short = 0;
        data = read_file(argv[2], &len);
        while (len - at >= 4) {
            const size_t n = (size_t)data[at] | (size_t)data[at + 1] << 8 | (size_t)data[at + 2] << 16 | (size_t)data[at + 3] << 24;
            at += 4;
            check(n <= len - at, "batch entry within the file");
            line(data + at, n, &dump);
            at += n;
        }
    } else if (argc == 3) {
        rmsc_error err;
        FILE *f;
        rmsc_status s;
        data = read_file(argv[1], &len);
        dump.hash_only = 0;
        s = decode_to_dump(data, len, &dump, &err);
        if (s != RMSC_OK) {
            fprintf(stderr, "error %s: %s\n", rmsc_status_name(s), err.message);
            return 1;
        }
        f = fopen(argv[2], "wb");
        if (!f || fwrite(dump.data, 1, dump.len, f) != dump.len || fclose(f) != 0) {
            fprintf(stderr, "scene_dump: cannot write %s\n", argv[2]);
            return 2;
        }
    } else {
        fprintf(stderr, "usage: scene_dump IN OUT | --truncate IN | --mutate IN XOR | --batch IN\n");
        return 2;
    }
    free(data);
    free(dump.data);
    return 0;
}
