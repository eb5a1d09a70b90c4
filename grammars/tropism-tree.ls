// Seed 001 fig 5.12: a tree bent by tropism (`@` bends towards T, `~`
// rolls the branch's up vector towards T).
#define TrunkLength 200
#define WidthReduce 0.6
#define StartLength 50
#define Twist1 80
#define Twist2 120
#define Twist3 120
#define LengthReduce 0.9
#define StartWidth 20
#define BranchAngle 29
iterations: 7
tropism: 0 -1 0
elasticity: 0.0015
axiom: F(TrunkLength, StartWidth) A(StartLength, StartWidth)
p1: A(l, w) : w > 1 -> @F(l, w) /(Twist1)
    [&(BranchAngle) F(l, w*WidthReduce) ~A(l*LengthReduce, w*WidthReduce)] /(Twist2)
    [&(BranchAngle) F(l, w*WidthReduce) ~A(l*LengthReduce, w*WidthReduce)] /(Twist3)
    [&(BranchAngle) F(l, w*WidthReduce) ~A(l*LengthReduce, w*WidthReduce)]
p2: A(l, w) : w <= 1 -> @F(l, w)
