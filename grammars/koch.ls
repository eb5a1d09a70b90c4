// The quadratic Koch curve (ABOP fig 1.9 family): 5^n segments, 3 steps
// (125 of them) so it reads at icon size. The tube is 0.7 of a segment wide
// (neighbouring segments are a segment apart), so the curve is a solid
// blue band at icon size, not a hairline.
iterations: 3
angle: 90
width: 0.7
axiom: '(0.1,0.3,0.85) F
F -> F+F-F-F+F
