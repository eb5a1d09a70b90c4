/*
 * Tessellation of rulemesh's nine built-in primitives for the JavaScript
 * scene decoder, compiled into the same WebAssembly kernel as place.c.
 *
 * A line-by-line port of src/geom/primitives.rs (and of the JavaScript port
 * it replaced): the geometry is built in double precision with the same
 * operations in the same order, and rounded to float once, when a vertex is
 * written. cos, sin and atan2 are imported from JavaScript's Math (the
 * functions the JavaScript port called), square roots are WebAssembly's
 * correctly rounded f64.sqrt, and -ffp-contract=off keeps every product and
 * sum a separate IEEE 754 operation; so each prototype is the server's, bit
 * for bit. Why not JavaScript: V8 runs a first decode in its interpreter,
 * where this float arithmetic costs about a millisecond per polyhedron.
 *
 * The caller (primitives.mjs) gives the output arrays, sized by
 * tessellation_vertices and tessellation_triangles.
 */
typedef unsigned int u32;
#define EXPORT(name) __attribute__((export_name(name)))
#define IMPORT(name) __attribute__((import_module("math"), import_name(name)))

IMPORT("cos") double js_cos(double);
IMPORT("sin") double js_sin(double);
IMPORT("atan2") double js_atan2(double, double);

#define PI 3.141592653589793
#define MIN_DETAIL 3u
#define MAX_DETAIL 256u
#define TORUS_MAJOR 0.375
#define TORUS_MINOR 0.125
#define MAX_POLY_VERTICES 20u

enum { BOX, SPHERE, CYLINDER, CONE, TORUS, TETRAHEDRON, OCTAHEDRON, ICOSAHEDRON, DODECAHEDRON };

typedef struct { double x, y, z; } vec;

static vec v3(double x, double y, double z) { vec r = { x, y, z }; return r; }
static vec sub(vec a, vec b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec cross(vec a, vec b) { return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static vec scale(vec a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static vec normalize(vec a) {
  const double l = __builtin_sqrt(dot(a, a));
  return l > 0 ? v3(a.x / l, a.y / l, a.z / l) : a;
}
static u32 clamp_detail(u32 d) { return d < MIN_DETAIL ? MIN_DETAIL : d > MAX_DETAIL ? MAX_DETAIL : d; }
static u32 max_u32(u32 a, u32 b) { return a > b ? a : b; }
static u32 sphere_bands(u32 d) { return max_u32(d / 2, 2); }
static u32 torus_tube(u32 d) { return max_u32(d / 2, 3); }

/* The output being written: float positions and normals, u32 triangles. */
typedef struct {
  float *pos, *nrm;
  u32 *idx;
  u32 nv, ni;
} builder;

static u32 vertex(builder *b, vec p, vec n) {
  float *o = b->pos + 3 * b->nv, *m = b->nrm + 3 * b->nv;
  o[0] = (float)p.x; o[1] = (float)p.y; o[2] = (float)p.z;
  m[0] = (float)n.x; m[1] = (float)n.y; m[2] = (float)n.z;
  return b->nv++;
}
static void tri(builder *b, u32 a, u32 c, u32 d) {
  b->idx[b->ni++] = a;
  b->idx[b->ni++] = c;
  b->idx[b->ni++] = d;
}

/* The point at angle 2πj/d on a ring of radius r at height y (ringPoint). */
static vec ring_point(u32 j, u32 d, double r, double y) {
  const double phi = (2.0 * PI * j) / d;
  return v3(r * js_cos(phi), y, -r * js_sin(phi));
}

static void box(builder *b) {
  static const double faces[6][3][3] = {
    { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },  { { -1, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 } },
    { { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 } },  { { 0, -1, 0 }, { 1, 0, 0 }, { 0, 0, 1 } },
    { { 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0 } },  { { 0, 0, -1 }, { 0, 1, 0 }, { 1, 0, 0 } },
  };
  static const double corners[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
  for (u32 f = 0; f < 6; f++) {
    const double *n = faces[f][0], *u = faces[f][1], *v = faces[f][2];
    const u32 base = b->nv;
    for (u32 c = 0; c < 4; c++) {
      const double su = corners[c][0], sv = corners[c][1];
      vertex(b, v3(0.5 * (n[0] + su * u[0] + sv * v[0]), 0.5 * (n[1] + su * u[1] + sv * v[1]), 0.5 * (n[2] + su * u[2] + sv * v[2])),
             v3(n[0], n[1], n[2]));
    }
    tri(b, base, base + 1, base + 2);
    tri(b, base, base + 2, base + 3);
  }
}

static void sphere(builder *b, u32 d) {
  const u32 bands = sphere_bands(d), rings = bands - 1;
  const u32 north = vertex(b, v3(0, 0.5, 0), v3(0, 1, 0));
  for (u32 i = 1; i < bands; i++) {
    const double theta = (PI * i) / bands;
    const double rho = js_sin(theta), y = js_cos(theta);
    for (u32 j = 0; j < d; j++) {
      const vec n = ring_point(j, d, rho, y);
      vertex(b, scale(n, 0.5), normalize(n));
    }
  }
  const u32 south = vertex(b, v3(0, -0.5, 0), v3(0, -1, 0));
#define RING(i, j) (1 + (i) * d + ((j) % d))
  for (u32 j = 0; j < d; j++) tri(b, north, RING(0, j), RING(0, j + 1));
  for (u32 i = 0; i + 1 < rings; i++) {
    for (u32 j = 0; j < d; j++) {
      const u32 a0 = RING(i, j), a1 = RING(i, j + 1), b0 = RING(i + 1, j), b1 = RING(i + 1, j + 1);
      tri(b, a0, b0, b1);
      tri(b, a0, b1, a1);
    }
  }
  for (u32 j = 0; j < d; j++) tri(b, RING(rings - 1, j), south, RING(rings - 1, j + 1));
#undef RING
}

/* A flat cap facing -y on the ring of d points at height -0.5, radius 0.5. */
static void bottom_cap(builder *b, u32 d) {
  const u32 c = vertex(b, v3(0, -0.5, 0), v3(0, -1, 0));
  for (u32 j = 0; j < d; j++) vertex(b, ring_point(j, d, 0.5, -0.5), v3(0, -1, 0));
  for (u32 j = 0; j < d; j++) tri(b, c, c + 1 + ((j + 1) % d), c + 1 + (j % d));
}

static void cylinder(builder *b, u32 d) {
  for (u32 j = 0; j < d; j++) vertex(b, ring_point(j, d, 0.5, 0.5), normalize(ring_point(j, d, 1.0, 0.0)));
  for (u32 j = 0; j < d; j++) vertex(b, ring_point(j, d, 0.5, -0.5), normalize(ring_point(j, d, 1.0, 0.0)));
  for (u32 j = 0; j < d; j++) {
    tri(b, j % d, d + (j % d), d + ((j + 1) % d));
    tri(b, j % d, d + ((j + 1) % d), (j + 1) % d);
  }
  const u32 c = vertex(b, v3(0, 0.5, 0), v3(0, 1, 0));
  for (u32 j = 0; j < d; j++) vertex(b, ring_point(j, d, 0.5, 0.5), v3(0, 1, 0));
  for (u32 j = 0; j < d; j++) tri(b, c, c + 1 + (j % d), c + 1 + ((j + 1) % d));
  bottom_cap(b, d);
}

static void cone(builder *b, u32 d) {
  for (u32 j = 0; j < d; j++) vertex(b, ring_point(j, d, 0.5, -0.5), normalize(ring_point(j, d, 1.0, 0.5)));
  for (u32 j = 0; j < d; j++) {
    const double mid = (2.0 * PI * (j + 0.5)) / d;
    vertex(b, v3(0, 0.5, 0), normalize(v3(1.0 * js_cos(mid), 0.5, -1.0 * js_sin(mid))));
  }
  for (u32 j = 0; j < d; j++) tri(b, d + j, j, (j + 1) % d);
  bottom_cap(b, d);
}

static void torus(builder *b, u32 d) {
  const u32 m = torus_tube(d);
  for (u32 i = 0; i < d; i++) {
    const double phi = (2.0 * PI * i) / d, cp = js_cos(phi), sp = js_sin(phi);
    for (u32 k = 0; k < m; k++) {
      const double th = (2.0 * PI * k) / m, ct = js_cos(th), st = js_sin(th);
      const vec n = v3(ct * cp, st, -ct * sp);
      const vec p = v3((TORUS_MAJOR + TORUS_MINOR * ct) * cp, TORUS_MINOR * st, -(TORUS_MAJOR + TORUS_MINOR * ct) * sp);
      vertex(b, p, normalize(n));
    }
  }
#define V(i, k) (((i) % d) * m + ((k) % m))
  for (u32 i = 0; i < d; i++) {
    for (u32 k = 0; k < m; k++) {
      tri(b, V(i, k), V(i + 1, k), V(i + 1, k + 1));
      tri(b, V(i, k), V(i + 1, k + 1), V(i, k + 1));
    }
  }
#undef V
}

static double golden(void) { return (1.0 + __builtin_sqrt(5.0)) / 2.0; }

/* The solid's vertices on the unit-diameter sphere (toCircumradius); returns how many. */
static u32 polyhedron_vertices(u32 kind, vec *v) {
  u32 n = 0;
  const double g = golden();
  if (kind == TETRAHEDRON) {
    v[n++] = v3(1, 1, 1); v[n++] = v3(1, -1, -1); v[n++] = v3(-1, 1, -1); v[n++] = v3(-1, -1, 1);
  } else if (kind == OCTAHEDRON) {
    v[n++] = v3(1, 0, 0); v[n++] = v3(-1, 0, 0); v[n++] = v3(0, 1, 0);
    v[n++] = v3(0, -1, 0); v[n++] = v3(0, 0, 1); v[n++] = v3(0, 0, -1);
  } else {
    if (kind == DODECAHEDRON)
      for (int x = -1; x <= 1; x += 2)
        for (int y = -1; y <= 1; y += 2)
          for (int z = -1; z <= 1; z += 2) v[n++] = v3(x, y, z);
    const double a0 = kind == DODECAHEDRON ? 1.0 / g : 1.0;
    const double as[2] = { -a0, a0 }, bs[2] = { -g, g };
    for (u32 i = 0; i < 2; i++)
      for (u32 j = 0; j < 2; j++) {
        const double a = as[i], c = bs[j];
        v[n++] = v3(0, a, c); v[n++] = v3(a, c, 0); v[n++] = v3(c, 0, a);
      }
  }
  for (u32 i = 0; i < n; i++) v[i] = scale(normalize(v[i]), 0.5);
  return n;
}

/* One face's corners by angle around its centre, then a fan (flatPolyhedron). */
static void flat_face(builder *b, const vec *v, const u32 *face, u32 k) {
  vec centre = v3(0, 0, 0);
  for (u32 i = 0; i < k; i++) centre = v3(centre.x + v[face[i]].x / k, centre.y + v[face[i]].y / k, centre.z + v[face[i]].z / k);
  const vec n = normalize(centre);
  const vec u = normalize(sub(v[face[0]], centre));
  const vec w = cross(n, u);
  double angle[5];
  u32 order[5];
  for (u32 i = 0; i < k; i++) {
    const vec r = sub(v[face[i]], centre);
    angle[i] = js_atan2(dot(r, w), dot(r, u));
    order[i] = face[i];
  }
  for (u32 i = 1; i < k; i++) /* insertion sort: stable, as Array.prototype.sort */
    for (u32 j = i; j > 0 && angle[j - 1] > angle[j]; j--) {
      const double ta = angle[j]; angle[j] = angle[j - 1]; angle[j - 1] = ta;
      const u32 to = order[j]; order[j] = order[j - 1]; order[j - 1] = to;
    }
  const vec normal = normalize(n);
  const u32 base = b->nv;
  for (u32 i = 0; i < k; i++) vertex(b, v[order[i]], normal);
  for (u32 t = 1; t + 1 < k; t++) tri(b, base, base + t, base + t + 1);
}

static void polyhedron(builder *b, u32 kind) {
  vec v[MAX_POLY_VERTICES];
  const u32 n = polyhedron_vertices(kind, v);
  if (kind == DODECAHEDRON) {
    const double g = golden(), as[2] = { -1.0, 1.0 }, bs[2] = { -g, g };
    for (u32 i = 0; i < 2; i++)
      for (u32 j = 0; j < 2; j++) {
        const double a = as[i], c = bs[j];
        const vec axes[3] = { v3(0, c, a), v3(c, a, 0), v3(a, 0, c) };
        for (u32 x = 0; x < 3; x++) {
          double best = -__builtin_inf();
          for (u32 p = 0; p < n; p++) {
            const double dp = dot(v[p], axes[x]);
            best = dp > best ? dp : best;
          }
          u32 face[5], k = 0;
          for (u32 p = 0; p < n && k < 5; p++)
            if (dot(v[p], axes[x]) > best - 1e-9) face[k++] = p;
          flat_face(b, v, face, k);
        }
      }
    return;
  }
  /* Triangular faces: every triple of mutually adjacent vertices (triangleFaces). */
  double edge = __builtin_inf();
  for (u32 i = 0; i < n; i++)
    for (u32 j = i + 1; j < n; j++) {
      const vec d = sub(v[i], v[j]);
      const double dd = dot(d, d);
      edge = dd < edge ? dd : edge;
    }
#define ADJACENT(i, j) (__builtin_fabs(dot(sub(v[i], v[j]), sub(v[i], v[j])) - edge) < 1e-9)
  for (u32 i = 0; i < n; i++)
    for (u32 j = i + 1; j < n; j++)
      for (u32 k = j + 1; k < n; k++)
        if (ADJACENT(i, j) && ADJACENT(j, k) && ADJACENT(i, k)) {
          const u32 face[3] = { i, j, k };
          flat_face(b, v, face, 3);
        }
#undef ADJACENT
}

static u32 polyhedron_faces(u32 kind) {
  return kind == TETRAHEDRON ? 4 : kind == OCTAHEDRON ? 8 : kind == ICOSAHEDRON ? 20 : 12;
}

/* Vertices of tessellate(kind, detail); 0 for an unknown kind. */
EXPORT("tessellation_vertices")
u32 tessellation_vertices(u32 kind, u32 detail) {
  const u32 d = clamp_detail(detail);
  switch (kind) {
    case BOX: return 24;
    case SPHERE: return 2 + d * (sphere_bands(d) - 1);
    case CYLINDER: return 4 * d + 2;
    case CONE: return 3 * d + 1;
    case TORUS: return d * torus_tube(d);
    case DODECAHEDRON: return 12 * 5;
    case TETRAHEDRON: case OCTAHEDRON: case ICOSAHEDRON: return 3 * polyhedron_faces(kind);
    default: return 0;
  }
}

/* Triangles of tessellate(kind, detail); 0 for an unknown kind. */
EXPORT("tessellation_triangles")
u32 tessellation_triangles(u32 kind, u32 detail) {
  const u32 d = clamp_detail(detail);
  switch (kind) {
    case BOX: return 12;
    case SPHERE: return 2 * d * (sphere_bands(d) - 1);
    case CYLINDER: return 4 * d;
    case CONE: return 2 * d;
    case TORUS: return 2 * d * torus_tube(d);
    case DODECAHEDRON: return 12 * 3;
    case TETRAHEDRON: case OCTAHEDRON: case ICOSAHEDRON: return polyhedron_faces(kind);
    default: return 0;
  }
}

/* Tessellates primitive `kind` at `detail` into pos, nrm (3 floats a vertex)
 * and idx (counter-clockwise outward triangles); returns the vertices
 * written, which is tessellation_vertices(kind, detail). */
EXPORT("tessellate")
u32 tessellate(u32 kind, u32 detail, float *pos, float *nrm, u32 *idx) {
  builder b = { pos, nrm, idx, 0, 0 };
  const u32 d = clamp_detail(detail);
  switch (kind) {
    case BOX: box(&b); break;
    case SPHERE: sphere(&b, d); break;
    case CYLINDER: cylinder(&b, d); break;
    case CONE: cone(&b, d); break;
    case TORUS: torus(&b, d); break;
    case TETRAHEDRON: case OCTAHEDRON: case ICOSAHEDRON: case DODECAHEDRON: polyhedron(&b, kind); break;
    default: break;
  }
  return b.nv;
}
