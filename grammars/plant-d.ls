// ABOP fig 1.24d (node rewriting: X is not drawn). Branches taper (`!`);
// the apices X left at the end become green leaves (termination table).
iterations: 7
angle: 20
width: 6
axiom: X
X -> F[+!X]F[-!X]+X
F -> FF
terminate: X -> ['(0.2,0.5,0.08) !(3) F(6)]
