// ABOP fig 1.24d (node rewriting: X is not drawn).
iterations: 7
angle: 20
width: 0.5
axiom: X
X -> F[+X]F[-X]+X
F -> FF
