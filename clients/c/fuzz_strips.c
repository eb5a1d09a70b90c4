/* fuzz_strips.c: a libFuzzer target for the C strips decoder. Build and run
 * (clients/c/README.md, "Fuzzing"):
 *
 *   clang -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined \
 *     -fno-sanitize-recover=all clients/c/fuzz_strips.c clients/c/rulemesh_strips.c -lm -o fuzz_strips
 *   mkdir -p corpus && ./fuzz_strips corpus clients/js/fixtures -max_len=65536
 *
 * Each input is decoded twice: as it is, and with its body length and raw
 * length fields and its CRC-32 rewritten to agree with the input's size.
 * The first run covers the container checks; without the second nearly
 * every mutation would stop at the CRC, and the stream decoders (where the
 * bounds checks that matter live) would never see damaged data.
 *
 * After a successful decode the target checks what the API promises: every
 * index is below the vertex count, the strip fits rms_info.strip_capacity,
 * normals are unit length, and the strip's length matches a length-only
 * rms_restrip call. A broken promise aborts, which libFuzzer reports.
 */
#include "rulemesh_strips.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void decode_checked(const uint8_t *data, size_t size) {
    rms_info info;
    rms_output out;
    rms_error err;
    size_t v, n3, i;
    if (rms_inspect(data, size, &info, &err) != RMS_OK) {
        if (err.message[0] == '\0') abort();
        return;
    }
    v = info.vertex_count;
    n3 = 3u * (size_t)info.triangle_count;
    memset(&out, 0, sizeof out);
    /* exact sizes (+1 only where a count may be 0), so ASan sees any overrun */
    out.positions = malloc(3 * v * sizeof(float) + 1);
    out.normals = malloc(3 * v * sizeof(float) + 1);
    out.colours = malloc(4 * v + 1);
    out.triangles = malloc(n3 * sizeof(uint32_t) + 1);
    out.strip = malloc(info.strip_capacity * sizeof(uint32_t) + 1);
    out.strip_capacity = info.strip_capacity;
    if (!out.positions || !out.normals || !out.colours || !out.triangles || !out.strip) abort();
    if (rms_decode(data, size, &out, &err) == RMS_OK) {
        for (i = 0; i < n3; i++)
            if (out.triangles[i] >= v) abort();
        if (out.strip_length > info.strip_capacity) abort();
        if (rms_restrip(out.triangles, info.triangle_count, NULL, 0) != out.strip_length) abort();
        for (i = 0; i < v; i++) {
            const float *n = out.normals + 3 * i;
            double x = (double)n[0], y = (double)n[1], z = (double)n[2];
            double l = sqrt(x * x + y * y + z * z);
            if (fabs(l - 1.0) > 1e-5) abort();
        }
    } else if (err.message[0] == '\0') {
        abort();
    }
    free(out.positions);
    free(out.normals);
    free(out.colours);
    free(out.triangles);
    free(out.strip);
}

static void put_u32(uint8_t *p, uint32_t v) {
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    uint8_t *fixed;
    decode_checked(data, size);
    if (size < 56 || size > (1u << 24)) return 0;
    fixed = malloc(size);
    if (!fixed) abort();
    memcpy(fixed, data, size);
    put_u32(fixed + 44, (uint32_t)(size - 56)); /* B */
    put_u32(fixed + 48, (uint32_t)(size - 56)); /* R */
    put_u32(fixed + size - 4, rms_crc32(fixed, size - 4));
    decode_checked(fixed, size);
    free(fixed);
    return 0;
}
