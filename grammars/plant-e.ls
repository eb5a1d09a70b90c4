// ABOP fig 1.24e.
iterations: 7
angle: 25.7
width: 0.5
axiom: X
X -> F[+X][-X]FX
F -> FF
