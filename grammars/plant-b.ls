// ABOP fig 1.24b, with tapering branches (`!`) and green leaves at the tips
// (L, turned into a leaf by the termination table).
iterations: 5
angle: 20
width: 3
axiom: FL
F -> F[+!FL]F[-!FL][!FL]
terminate: L -> ['(0.2,0.5,0.08) !(1.2) F(2.5)]
