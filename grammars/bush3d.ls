// A 3D bush after ABOP fig 1.25: three branches per apex, rolled apart;
// leaves are short green stubs instead of the book's polygons. Each
// branch is 0.7 as wide as its parent (`!`) from a trunk of 0.6, and the
// stubs are 0.45 wide, so twigs and leaves show at icon size.
iterations: 5
angle: 22.5
width: 0.6
axiom: '(0.3,0.2,0.1) A
A -> [&FL!A]/////[&FL!A]///////[&FL!A]
F -> S/////F
S -> FL
L -> ['(0.2,0.55,0.1)^^F(0.9,0.45)]
