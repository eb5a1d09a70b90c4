scale factor: 0.9
z buffer: on
render mode: shaded
line style: cylinder
light direction: 1.0,1.5,0.5
tropism direction: 0.0,1.0,0.0
surface: p petal.s 2 6 6 
surface: l leaf.s 6 6 10 
twist of cylinders: on
contour: 1 calyx.con
function set: functions.fset


