// ABOP fig 1.27: a stochastic plant; every seed gives another specimen.
// Branches taper (`!`) and each tip's L becomes a green leaf (termination
// table), over the turtle's bark-brown stems.
iterations: 5
angle: 25.7
width: 6
axiom: FL
F -> F[+!FL]F[-!FL]F : 0.33
F -> F[+!FL]F : 0.33
F -> F[-!FL]F : 0.34
terminate: L -> ['(0.2,0.5,0.08) !(2.5) F(5)]
