#!/usr/bin/env python3
"""Compares two SVGs in cfdg -V's layout (cfdg's and rulemesh's): the same
number of shape elements, in order the same kind, transforms within 1e-4 of
the picture's size, fill colours within one 8-bit step. Prints one word
(SAME, COUNT, ORDER, TRANSFORM or COLOUR) and the details."""
import re, sys

# A shape: a primitive element, or a path's <g> (its paint and transform;
# an iso stroke has no transform: its stroke width stands in for it).
TAG = re.compile(r'<(circle|rect|use xlink:href="#TRIANGLE"|g)(?=[\s>/])([^>]*)>', re.S)
COLOUR = re.compile(r'(?:fill|stroke)="#([0-9a-f]{6})"')
OPACITY = re.compile(r'(?:fill|stroke)-opacity="([\d.e+-]+)"')
MATRIX = re.compile(r'transform="matrix\(([^)]*)\)"')
WIDTH = re.compile(r'stroke-width="([\d.e+-]+)"')

def load(path):
    text = open(path, encoding="utf-8", errors="replace").read()
    m = re.search(r'<svg width="(\d+)px" height="(\d+)px"', text)
    size = max(int(m.group(1)), int(m.group(2))) if m else 1
    shapes = []
    for e in TAG.finditer(text):
        attrs = e.group(2)
        colour = COLOUR.search(attrs)
        opacity = OPACITY.search(attrs)
        matrix = MATRIX.search(attrs) or WIDTH.search(attrs)
        numbers = [float(x) for x in matrix.group(1).split()] if matrix else []
        shapes.append((e.group(1)[:3], colour.group(1) if colour else "000000", float(opacity.group(1)) if opacity else 1.0, numbers))
    return size, shapes, 0

def main():
    size, a, pa = load(sys.argv[1])
    _, b, _ = load(sys.argv[2])
    if len(a) != len(b) or pa:
        print(f"COUNT cfdg={len(a)}{'+paths' if pa else ''} rulemesh={len(b)}")
        return 1
    worst = colour = order = 0
    for x, y in zip(a, b):
        order += x[0] != y[0]
        worst = max(worst, max((abs(p - q) for p, q in zip(x[3], y[3])), default=0.0) / size, 0.0 if len(x[3]) == len(y[3]) else 1.0)
        c1 = [int(x[1][i:i + 2], 16) for i in (0, 2, 4)] + [round(x[2] * 255)]
        c2 = [int(y[1][i:i + 2], 16) for i in (0, 2, 4)] + [round(y[2] * 255)]
        colour = max(colour, max(abs(p - q) for p, q in zip(c1, c2)))
    word = "ORDER" if order else "TRANSFORM" if worst > 1e-4 else "COLOUR" if colour > 1 else "SAME"
    print(f"{word} shapes={len(a)} transform={worst:.1e} colour={colour}")
    return 0 if word == "SAME" else 1

if __name__ == "__main__":
    sys.exit(main())
