// Sierpinski's bush (seed 001 fig 4.9, §4.5): every apex branches in three
// and branch lengths grow as the Fibonacci numbers (F → FB, B → F), so at 9
// steps the bush has 35 310 segments. It instances: the object hierarchy
// has one object per (module, remaining steps), about 70 entries in all.
// Segments are 0.8 wide, so the wood shows at icon size; one width for all
// (tapering would make the width part of each subtree's key and double the
// hierarchy).
iterations: 9
angle: 35
width: 0.8
axiom: A
p1: A -> [&FA]/(120)[&FA]/(120)[&FA]
p2: F -> FB
p3: B -> F
