set maxdepth 30
40 * { x 1 } r
rule r { { color random } box }
rule r w 2 { { y 1 color random } sphere }
