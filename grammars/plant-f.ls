// ABOP fig 1.24f (node rewriting). Branches taper (`!`); the apices X left
// at the end become green leaves (termination table).
iterations: 5
angle: 22.5
width: 3
axiom: X
X -> F-[[!X]+!X]+F[+!FX]-X
F -> FF
terminate: X -> ['(0.2,0.5,0.08) !(1.5) F(3)]
