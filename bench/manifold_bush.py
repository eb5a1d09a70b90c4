"""Manifold's own unions of the Sierpinski bush (grammars/sierpinski-bush.ls),
for scripts/bench's print section (docs/benchmarks.md): the anchors that
`rulemesh render grammars/sierpinski-bush.ls --print` is measured against in
the same run, with the manifold3d wheel.

usage: manifold_bush.py batch|subtree OUT.stl
The bush from its own L-system (axiom A; A -> [&FA]/[&FA]/[&FA] with & 35
degrees and / 120 degrees; F -> FB, B -> F; 9 steps: 35,310 segments), its
tubes 0.8 wide and 8-sided like rulemesh's at the default detail, each
straight branch one cylinder (29,523 of them).
- batch: Manifold.batch_boolean of the 29,523 cylinders (one run: it takes
  tens of seconds).
- subtree: once per distinct subtree, as rulemesh's print stage unites an
  L-system's hierarchy (src/print/rigid.rs): nine batch unions, each of three
  branches and three copies of the level below (best of 3).
Prints "<seconds> <triangles> <watertight>" and writes the union.
"""
import sys
import time

import manifold3d as m3
import numpy as np

from manifold_common import best_of_3, report

SIDES, RADIUS, STEPS = 8, 0.4, 9
PITCH, ROLL = np.radians(35), np.radians(120)


def rotation(axis, angle):
    """The 3x3 rotation by `angle` about unit `axis` (0 x, 2 z)."""
    c, s = np.cos(angle), np.sin(angle)
    m = np.eye(3)
    i, j = [(1, 2), None, (0, 1)][axis]
    m[i, i], m[i, j], m[j, i], m[j, j] = c, -s, s, c
    return m


def branch_length(steps_left):
    """Segments in an F after `steps_left` rewrites (F -> FB, B -> F): Fibonacci."""
    f, b = 1, 0
    for _ in range(steps_left):
        f, b = f + b, f
    return f


def turns():
    """The three branches' rotations: roll 120 degrees apart, then pitch 35 degrees."""
    return [rotation(2, i * ROLL) @ rotation(0, PITCH) for i in range(3)]


def tube(length):
    return m3.Manifold.cylinder(length, RADIUS, RADIUS, SIDES)


def place(m, r, t):
    return m.transform(np.column_stack([r, t]))


def subtree():
    """One batch union per level: three branches and three copies of the level below."""
    below = None
    for level in range(1, STEPS + 1):
        length = branch_length(level - 1)
        pieces = []
        for r in turns():
            pieces.append(place(tube(length), r, np.zeros(3)))
            if below is not None:
                pieces.append(place(below, r, r @ np.array([0.0, 0.0, length])))
        below = m3.Manifold.batch_boolean(pieces, m3.OpType.Add)
    return below


def cylinders():
    """Every branch of the expanded bush as its own cylinder."""
    out = []

    def grow(level, r0, t0):
        for r in turns():
            r1 = r0 @ r
            length = branch_length(level - 1)
            out.append(place(tube(length), r1, t0))
            if level > 1:
                grow(level - 1, r1, t0 + r1 @ np.array([0.0, 0.0, length]))

    grow(STEPS, np.eye(3), np.zeros(3))
    return out


if sys.argv[1] == "batch":
    parts = cylinders()
    t0 = time.perf_counter()
    mesh = m3.Manifold.batch_boolean(parts, m3.OpType.Add).to_mesh()
    report(time.perf_counter() - t0, mesh, sys.argv[2])
else:
    best, mesh = best_of_3(subtree)
    report(best, mesh, sys.argv[2])
