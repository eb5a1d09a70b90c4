// ABOP fig 1.24c.
iterations: 4
angle: 22.5
width: 0.3
axiom: F
F -> FF-[-F+F+F]+[+F-F-F]
