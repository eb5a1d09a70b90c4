// ABOP fig 1.24c, with tapering branches (`!`) and green leaves at the tips
// (L, turned into a leaf by the termination table).
iterations: 4
angle: 22.5
width: 3
axiom: FL
F -> FF-[-!F+F+FL]+[+!F-F-FL]
terminate: L -> ['(0.2,0.5,0.08) !(1.5) F(3)]
