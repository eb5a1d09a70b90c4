// Sierpinski's tetrahedron (seed 001 fig 2.4): four half-size copies at the
// vertices of a regular tetrahedron, six levels deep: 4^6 = 4096 spheres in
// an object hierarchy of 6 levels with 4 instances each. T(d) places its
// copies at distance d from its centre; the spheres touch their neighbours.
// The axiom sets one amber colour for all of them (the turtle's default is
// bark brown, meant for wood).
#define Apex 109.4712206
iterations: 6
shape: SPHERE
axiom: '(0.85,0.5,0.1) T(1)
T(d) -> [f(d) T(d/2)] [&(Apex) f(d) T(d/2)] [/(120) &(Apex) f(d) T(d/2)] [/(240) &(Apex) f(d) T(d/2)]
terminate: T(d) -> f(-d*0.8165) F(d*1.633)
