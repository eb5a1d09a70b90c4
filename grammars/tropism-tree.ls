// Seed 001 fig 5.12: a tree bent by tropism (`@` bends towards T, `~`
// rolls the branch's up vector towards T). Ours: each twig ends in a
// tuft of three green leaves (LeafLength, LeafWidth), over the turtle's
// bark-brown wood, and no branch is drawn thinner than MinWidth (the
// widths still end the recursion as in the thesis), so the crown reads at
// icon size.
#define TrunkLength 200
#define WidthReduce 0.6
#define StartLength 50
#define Twist1 80
#define Twist2 120
#define Twist3 120
#define LengthReduce 0.9
#define StartWidth 20
#define BranchAngle 29
#define LeafLength 20
#define LeafWidth 10
#define MinWidth 4
iterations: 7
tropism: 0 -1 0
elasticity: 0.0015
axiom: F(TrunkLength, StartWidth) A(StartLength, StartWidth)
p1: A(l, w) : w > 1 -> @F(l, w) /(Twist1)
    [&(BranchAngle) F(l, max(w*WidthReduce, MinWidth)) ~A(l*LengthReduce, w*WidthReduce)] /(Twist2)
    [&(BranchAngle) F(l, max(w*WidthReduce, MinWidth)) ~A(l*LengthReduce, w*WidthReduce)] /(Twist3)
    [&(BranchAngle) F(l, max(w*WidthReduce, MinWidth)) ~A(l*LengthReduce, w*WidthReduce)]
p2: A(l, w) : w <= 1 -> @F(l, MinWidth) '(0.22,0.5,0.1)
    [&(35) F(LeafLength, LeafWidth)] [/(120) &(35) F(LeafLength, LeafWidth)] [/(240) &(35) F(LeafLength, LeafWidth)]
