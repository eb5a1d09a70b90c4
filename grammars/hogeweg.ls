// The Hogeweg–Hesper context-sensitive plant, ABOP fig 1.31a
// (seed 001 fig 6.3 uses it with "Ignore: +-F").
iterations: 30
angle: 22.5
width: 0.3
ignore: + - F
axiom: F1F1F1
0 < 0 > 0 -> 0
0 < 0 > 1 -> 1[+F1F1]
0 < 1 > 0 -> 1
0 < 1 > 1 -> 1
1 < 0 > 0 -> 0
1 < 0 > 1 -> 1F1
1 < 1 > 0 -> 0
1 < 1 > 1 -> 0
* < + > * -> -
* < - > * -> +
