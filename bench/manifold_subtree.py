"""Manifold's own union per distinct subtree of the level-3 Menger sponge,
for scripts/bench's print section (docs/benchmarks.md): the second anchor,
the method rulemesh's print stage uses on MDG hierarchies
(src/print/subtree.rs), done with the manifold3d wheel in the same run.

usage: manifold_subtree.py OUT.stl
Three batch unions of 20 pieces each (20 unit cubes; 20 copies of that
union; 20 copies of that), in integer coordinates so that faces meant to
coincide do exactly, then scaled to the 1 mm cube. Prints
"<best seconds of 3> <triangles> <watertight>" and writes the union.
"""
import sys

import manifold3d as m3

from manifold_common import best_of_3, report

CELLS = [(x, y, z) for x in (-1, 0, 1) for y in (-1, 0, 1) for z in (-1, 0, 1) if (x, y, z).count(0) <= 1]


def sponge():
    """The level-3 sponge, one batch union per level (per distinct subtree)."""
    m = m3.Manifold.cube((1, 1, 1), True)
    for level in range(3):
        s = 3**level
        m = m3.Manifold.batch_boolean([m.translate((x * s, y * s, z * s)) for (x, y, z) in CELLS], m3.OpType.Add)
    return m.scale((1 / 27, 1 / 27, 1 / 27))


best, mesh = best_of_3(sponge)
report(best, mesh, sys.argv[1])
