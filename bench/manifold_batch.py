"""Manifold's own batch union of the boxes of an unprinted rulemesh STL, for
scripts/bench's print section (docs/benchmarks.md): the anchor that
`rulemesh render G --print` is measured against in the same run.

usage: manifold_batch.py BOXES.stl OUT.stl
BOXES.stl: an STL of closed boxes, 12 consecutive triangles each (what
`rulemesh render grammars/menger.mdg -o BOXES.stl` writes). Prints
"<best seconds of 3> <triangles> <watertight>" for the manifold3d wheel's
Manifold.batch_boolean(parts, OpType.Add) plus to_mesh (building the 8,000
Manifolds from their meshes included, reading the STL not), and writes the
union to OUT.stl.
"""
import sys

import manifold3d as m3
import numpy as np
import trimesh

from manifold_common import best_of_3, report

tris = trimesh.load(sys.argv[1], force="mesh", process=False).triangles
meshes = []
for c in range(len(tris) // 12):
    v, inv = np.unique(tris[12 * c : 12 * c + 12].reshape(-1, 3), axis=0, return_inverse=True)
    meshes.append(m3.Mesh(vert_properties=v.astype(np.float32), tri_verts=inv.reshape(-1, 3).astype(np.uint32)))
best, mesh = best_of_3(lambda: m3.Manifold.batch_boolean([m3.Manifold(m) for m in meshes], m3.OpType.Add))
report(best, mesh, sys.argv[2])
