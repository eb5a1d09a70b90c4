set scale 2
set pivot [1 2 3]
set background #223344
10 * { ry 36 x 2 hue 30 } spiral
rule spiral maxdepth 20 { { s 0.9 y 0.4 rz 12 } spiral box::glass }
