"""What bench/manifold_batch.py and bench/manifold_subtree.py share: timing a
union with the manifold3d wheel (best of 3) and writing and judging its mesh."""
import time

import trimesh


def best_of_3(unite):
    """Runs `unite()` (returning a Manifold) three times; the best seconds and the last mesh (to_mesh timed too)."""
    best, mesh = None, None
    for _ in range(3):
        t0 = time.perf_counter()
        mesh = unite().to_mesh()
        t = time.perf_counter() - t0
        best = t if best is None else min(best, t)
    return best, mesh


def report(best, mesh, path):
    """Writes `mesh` to the STL `path` and prints "<seconds> <triangles> <watertight>"."""
    out = trimesh.Trimesh(vertices=mesh.vert_properties[:, :3], faces=mesh.tri_verts, process=False)
    out.export(path)
    print("%.3f %d %s" % (best, len(mesh.tri_verts), trimesh.load(path, force="mesh").is_watertight))
