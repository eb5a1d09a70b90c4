// The Hogeweg–Hesper context-sensitive plant, ABOP fig 1.31a
// (seed 001 fig 6.3 uses it with "Ignore: +-F"). Each new branch starts
// thinner (`!`) and green (`'`), so the main stem stays bark brown; both
// are ignored in context matching, so the plant grows as the book's.
iterations: 30
angle: 22.5
width: 2
ignore: + - F ! '
axiom: F1F1F1
0 < 0 > 0 -> 0
0 < 0 > 1 -> 1[+!'(0.25,0.5,0.1)F1F1]
0 < 1 > 0 -> 1
0 < 1 > 1 -> 1
1 < 0 > 0 -> 0
1 < 0 > 1 -> 1F1
1 < 1 > 0 -> 0
1 < 1 > 1 -> 0
* < + > * -> -
* < - > * -> +
