// Seed 001 fig 5.4: a square patch of grass blades (fewer recursion levels
// than the thesis's 11). Blade lengths, tilts, rolls and colours come from
// the seeded stream, so each seed grows a different lawn.
#define RecursionLevels 3
#define Gdist 2
#define BladeLength ran(4)*ran(4)+8
#define BladeInitialTilt ran(10)+10
#define RedColor 0.1+ran(20)/100
#define GreenColor 0.3+ran(25)/100
#define BlueColor 0.14
#define BladeWidth 0.2
#define BladeBendFactor 10
iterations: 14
axiom: &(90) G(RecursionLevels)
p1: G(l) : l == 0 -> /(ran(360)) '(RedColor, GreenColor, BlueColor) P(BladeLength, BladeInitialTilt)
p2: G(l) : l > 0 -> [G(l-1)] [f(2^(l-1)*Gdist) G(l-1)] [+(90) f(2^(l-1)*Gdist) -(90) G(l-1)]
    [+(45) f(2^(l-1)*Gdist*sqrt(2)) -(45) G(l-1)]
p3: P(n, a) -> -(a) B(n, a)
p4: B(n, a) : n > 0 -> F(1, BladeWidth) -(BladeBendFactor*sin(a*pi/180)) B(n-1, a+BladeBendFactor*sin(a*pi/180))
