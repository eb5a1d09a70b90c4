// ABOP fig 1.24a: a bracketed plant (edge rewriting).
iterations: 5
angle: 25.7
width: 0.3
axiom: F
F -> F[+F]F[-F]F
