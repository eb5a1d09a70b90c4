/* fuzz_scene.c: a libFuzzer target for the C scene decoder. Build and run
 * (clients/c/README.md, "Fuzzing"):
 *
 *   clang -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined \
 *     -fno-sanitize-recover=all clients/c/fuzz_scene.c clients/c/rulemesh_scene.c -lm -o fuzz_scene
 *   mkdir -p corpus && ./fuzz_scene corpus clients/js/fixtures -max_len=20000
 *
 * Each input is decoded as given and, when it is at least a header long,
 * again with the header made plausible (magic, version 2, the known flag
 * bits, a detail of 3–10): random bytes rarely start "RMSC". When that
 * copy's CHECKSUM flag is set, its last four bytes are rewritten to the
 * CRC-32 of the rest (rulemesh_crc32.inc), as fuzz_strips.c does: without
 * it nearly every mutation of a checksummed seed would stop at the CRC and
 * the parser behind it would never see damaged data.
 * The triangle limit is 200 000 and the scratch 64 MiB, so one input costs
 * milliseconds (a real app picks its own limits; these only keep the fuzzer
 * fast).
 *
 * After a successful decode the target checks what the API promises: each
 * mesh's counts are within its room and its room within the arrays, every
 * index is below its mesh's vertex count, and a file rmsc_inspect accepts
 * rmsc_decode accepts too. (Positions are not promised finite: a large but
 * finite scale times a large coordinate overflows float in the server's
 * arithmetic as well.) A broken promise aborts, which libFuzzer reports.
 */
#include "rulemesh_scene.h"

#include <stdlib.h>
#include <string.h>

#include "rulemesh_crc32.inc"

#define MAX_TRIANGLES 200000u
#define MAX_SCRATCH (64u << 20)

static void decode_checked(const uint8_t *data, size_t size) {
    rmsc_info info;
    rmsc_output out;
    rmsc_error err;
    void *work = malloc(rmsc_inspect_scratch(size));
    rmsc_status s;
    if (!work) abort();
    s = rmsc_inspect(data, size, RMSC_V1_DETAIL, MAX_TRIANGLES, work, rmsc_inspect_scratch(size), &info, &err);
    free(work);
    if (s != RMSC_OK) {
        if (err.message[0] == '\0') abort();
        return;
    }
    if (info.scratch_bytes > MAX_SCRATCH) return;
    memset(&out, 0, sizeof out);
    /* exact sizes (+1 only where a count may be 0), so ASan sees any overrun */
    out.positions = malloc(3 * info.vertex_count * sizeof(float) + 1);
    out.normals = malloc(3 * info.vertex_count * sizeof(float) + 1);
    out.colours = malloc(4 * info.vertex_count + 1);
    out.indices = malloc(3 * info.triangle_count * sizeof(uint32_t) + 1);
    out.meshes = malloc(info.mesh_count * sizeof(rmsc_mesh) + 1);
    out.scratch = malloc(info.scratch_bytes + 1);
    if (!out.positions || !out.normals || !out.colours || !out.indices || !out.meshes || !out.scratch) abort();
    out.vertex_capacity = info.vertex_count;
    out.triangle_capacity = info.triangle_count;
    out.mesh_capacity = info.mesh_count;
    out.scratch_bytes = info.scratch_bytes;
    /* A file rmsc_inspect accepts, rmsc_decode accepts. */
    if (rmsc_decode(data, size, RMSC_V1_DETAIL, MAX_TRIANGLES, &out, &err) != RMSC_OK) abort();
    for (uint32_t m = 0; m < info.mesh_count; m++) {
        const rmsc_mesh *me = &out.meshes[m];
        if (me->vertex_count > me->vertex_capacity || me->triangle_count > me->triangle_capacity) abort();
        if (me->first_vertex + me->vertex_capacity > info.vertex_count) abort();
        if (me->first_index + 3 * (size_t)me->triangle_capacity > 3 * info.triangle_count) abort();
        for (size_t i = 0; i < 3 * (size_t)me->triangle_count; i++)
            if (out.indices[me->first_index + i] >= me->vertex_count) abort();
    }
    free(out.positions);
    free(out.normals);
    free(out.colours);
    free(out.indices);
    free(out.meshes);
    free(out.scratch);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    uint8_t *fixed;
    decode_checked(data, size);
    if (size < 20 || size > (1u << 24)) return 0;
    fixed = malloc(size);
    if (!fixed) abort();
    memcpy(fixed, data, size);
    memcpy(fixed, "RMSC", 4);
    fixed[4] = 2;
    fixed[5] = 0;
    fixed[6] &= 15;
    fixed[7] = 0;
    fixed[8] = (uint8_t)(3 + fixed[8] % 8);
    fixed[9] = fixed[10] = fixed[11] = 0;
    if (fixed[6] & 8) {
        const uint32_t crc = rmcrc32(fixed, size - 4);
        for (int i = 0; i < 4; i++) fixed[size - 4 + (size_t)i] = (uint8_t)(crc >> (8 * i));
    }
    decode_checked(fixed, size);
    free(fixed);
    return 0;
}
