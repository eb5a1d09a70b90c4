// ABOP fig 1.27: a stochastic plant; every seed gives another specimen.
iterations: 5
angle: 25.7
width: 0.3
axiom: F
F -> F[+F]F[-F]F : 0.33
F -> F[+F]F : 0.33
F -> F[-F]F : 0.34
