// ABOP fig 1.24e (node rewriting). Branches taper (`!`); the apices X left
// at the end become green leaves (termination table).
iterations: 7
angle: 25.7
width: 6
axiom: X
X -> F[+!X][-!X]FX
F -> FF
terminate: X -> ['(0.2,0.5,0.08) !(3) F(6)]
