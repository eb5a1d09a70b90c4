angle factor: 12 
initial color: 127
color increment: 1
initial line width: 2.0 pixels
line width increment: 0.0
viewpoint: 0,0,30
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -10000000.0
back distance: 10000000.0
scale factor: 0.9
z buffer: off
cue range: 0
shade mode: 1
light direction: 1.0,0.0,0.5
diffuse reflection: 10
tropism direction: 0.0,1.0,0.0
initial elasticity: 0.0
elasticity increment: 0.0

