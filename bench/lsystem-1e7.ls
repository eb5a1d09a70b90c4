// Ten million segments: every segment becomes ten, seven times over
// (10^7 = 10 000 000). Derived as a string it would need 23 333 332
// modules; instanced it is seven objects of ten entries, and `format=scene` is 2.6 KB.
// It needs raised limits (--max-primitives, --max-triangles, --max-memory).
iterations: 7
angle: 25
width: 0.2
axiom: F
F -> F[+F]F[-F]F[&F]F[^F]FF
