// ABOP fig 1.24b.
iterations: 5
angle: 20
width: 0.3
axiom: F
F -> F[+F]F[-F][F]
