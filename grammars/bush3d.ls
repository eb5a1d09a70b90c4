// A 3D bush after ABOP fig 1.25: three branches per apex, rolled apart;
// leaves are short green stubs instead of the book's polygons.
iterations: 5
angle: 22.5
width: 0.25
axiom: '(0.3,0.2,0.1) A
A -> [&FL!A]/////[&FL!A]///////[&FL!A]
F -> S/////F
S -> FL
L -> ['(0.2,0.55,0.1)^^F(0.3,0.06)]
