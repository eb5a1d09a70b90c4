// The quadratic Koch curve (ABOP fig 1.9 family): 4^n segments.
iterations: 4
angle: 90
width: 0.2
axiom: F
F -> F+F-F-F+F
