// ABOP fig 1.24a: a bracketed plant (edge rewriting). Every branch starts
// 0.7 as wide as its parent (`!`), and each branch tip carries a module L
// that the termination table turns into a green leaf, so the stems are
// bark brown (the turtle's default) and the tips green, as in ABOP.
iterations: 5
angle: 25.7
width: 6
axiom: FL
F -> F[+!FL]F[-!FL]F
terminate: L -> ['(0.2,0.5,0.08) !(2.5) F(5)]
