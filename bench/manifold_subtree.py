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
import time

import manifold3d as m3
import trimesh

CELLS = [(x, y, z) for x in (-1, 0, 1) for y in (-1, 0, 1) for z in (-1, 0, 1) if (x, y, z).count(0) <= 1]
best, mesh = None, None
for _ in range(3):
    t0 = time.perf_counter()
    m = m3.Manifold.cube((1, 1, 1), True)
    for level in range(3):
        s = 3**level
        m = m3.Manifold.batch_boolean([m.translate((x * s, y * s, z * s)) for (x, y, z) in CELLS], m3.OpType.Add)
    m = m.scale((1 / 27, 1 / 27, 1 / 27))
    mesh = m.to_mesh()
    t = time.perf_counter() - t0
    best = t if best is None else min(best, t)
out = trimesh.Trimesh(vertices=mesh.vert_properties[:, :3], faces=mesh.tri_verts, process=False)
out.export(sys.argv[1])
print("%.3f %d %s" % (best, len(mesh.tri_verts), trimesh.load(sys.argv[1], force="mesh").is_watertight))
