/*
 * Tessellation of rulemesh's nine built-in primitives for the JavaScript
 * scene decoder, compiled into the same WebAssembly kernel as place.c.
 *
 * The code is clients/c/rulemesh_tessellate.inc, which the C decoder
 * (clients/c/rulemesh_scene.c) builds from too: one implementation of the
 * tessellation. This file supplies what it needs in WebAssembly: cos, sin
 * and atan2 imported from JavaScript's Math (the functions the JavaScript
 * port called), WebAssembly's correctly rounded f64.sqrt, and an export per
 * entry point. -ffp-contract=off (scripts/build-js-kernel) keeps every
 * product and sum a separate IEEE 754 operation. Why not JavaScript: V8 runs
 * a first decode in its interpreter, where this float arithmetic costs about
 * a millisecond per polyhedron.
 *
 * The caller (primitives.mjs) gives the output arrays, sized by
 * tessellation_vertices and tessellation_triangles.
 */
typedef unsigned int u32;
#define IMPORT(name) __attribute__((import_module("math"), import_name(name)))

IMPORT("cos") double js_cos(double);
IMPORT("sin") double js_sin(double);
IMPORT("atan2") double js_atan2(double, double);

#define RMK_EXPORT(name) __attribute__((export_name(name)))
#define RMK_SQRT(x) __builtin_sqrt(x)
#define RMK_FABS(x) __builtin_fabs(x)
#define RMK_INF __builtin_inf()
#define RMK_COS(x) js_cos(x)
#define RMK_SIN(x) js_sin(x)
#define RMK_ATAN2(y, x) js_atan2(y, x)

#include "../../c/rulemesh_tessellate.inc"
