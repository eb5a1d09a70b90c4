// ABOP fig 1.24f.
iterations: 5
angle: 22.5
width: 0.3
axiom: X
X -> F-[[X]+X]+F[+FX]-X
F -> FF
