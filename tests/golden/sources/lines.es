line
{ x 2 } grid
{ x 4 } dot
{ y 2 } cylinder
{ y 4 } triangle[0,0,0;1,0,0;0,1,0]
{ x -2 s 0.5 } mesh
