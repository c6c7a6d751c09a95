#!/usr/bin/env python3
"""Neighbouring panels that pass through each other (found 2026-12-05; not yet in the report).

Two panels that share an edge meet along the line where their planes cross. Each panel's
interior may meet that line elsewhere too (a concave panel, or one that runs past the node);
a point strictly inside both panels is a point where they pass through each other. This
samples the line over both panels' extent (2,000 points) and reports, per pair, the deepest
such point's distance to the nearer outline over the smaller panel's diameter.

Usage: panel_crossings.py PANELS.obj [...]   (flatfacet remesh --out PANELS.obj)
Only pairs that share an edge are checked; panels that do not touch are not.
"""
import math
import sys


def load(path):
    vertices, faces = [], []
    for line in open(path):
        t = line.split()
        if not t:
            continue
        if t[0] == 'v':
            vertices.append(tuple(map(float, t[1:4])))
        elif t[0] == 'f':
            faces.append([int(x.split('/')[0]) - 1 for x in t[1:]])
    return vertices, faces


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a): return math.sqrt(dot(a, a))
def unit(a): return tuple(x / norm(a) for x in a)


def newell(points):
    n = [0.0, 0.0, 0.0]
    for i, a in enumerate(points):
        b = points[(i + 1) % len(points)]
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return unit(n)


def distance_to_outline(outline, q):
    best = math.inf
    for i, a in enumerate(outline):
        b = outline[(i + 1) % len(outline)]
        ab, aq = (b[0] - a[0], b[1] - a[1]), (q[0] - a[0], q[1] - a[1])
        length2 = ab[0] ** 2 + ab[1] ** 2
        t = max(0.0, min(1.0, (aq[0] * ab[0] + aq[1] * ab[1]) / length2)) if length2 > 0 else 0.0
        best = min(best, math.hypot(aq[0] - t * ab[0], aq[1] - t * ab[1]))
    return best


def inside(outline, q):
    odd = False
    for i, a in enumerate(outline):
        b = outline[(i + 1) % len(outline)]
        if (a[1] > q[1]) != (b[1] > q[1]) and a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]) > q[0]:
            odd = not odd
    return odd


class Panel:
    def __init__(self, points):
        self.points = points
        self.normal = newell(points)
        helper = (1.0, 0.0, 0.0) if abs(self.normal[0]) < 0.9 else (0.0, 1.0, 0.0)
        self.u = unit(cross(self.normal, helper))
        self.v = cross(self.normal, self.u)
        self.origin = points[0]
        self.outline = [self.to_2d(p) for p in points]
        self.diameter = max(norm(sub(p, q)) for p in points for q in points)

    def to_2d(self, p):
        d = sub(p, self.origin)
        return (dot(d, self.u), dot(d, self.v))


def crossings(path, samples=2000):
    vertices, faces = load(path)
    edge_faces = {}
    for i, f in enumerate(faces):
        for k, a in enumerate(f):
            b = f[(k + 1) % len(f)]
            edge_faces.setdefault((min(a, b), max(a, b)), []).append(i)
    pairs = {}
    for (a, _), fs in edge_faces.items():
        if len(fs) == 2:
            pairs.setdefault((min(fs), max(fs)), a)
    panels = [Panel([vertices[j] for j in f]) for f in faces]
    out = []
    for (a, b), shared in sorted(pairs.items()):
        pa, pb = panels[a], panels[b]
        direction = cross(pa.normal, pb.normal)
        if norm(direction) < 1e-9:
            continue
        direction = unit(direction)
        on_line = vertices[shared]
        ts = [dot(sub(p, on_line), direction) for p in pa.points + pb.points]
        lo, hi = min(ts), max(ts)
        deepest = 0.0
        for s in range(samples + 1):
            t = lo + (hi - lo) * s / samples
            q = tuple(on_line[k] + t * direction[k] for k in range(3))
            qa, qb = pa.to_2d(q), pb.to_2d(q)
            if inside(pa.outline, qa) and inside(pb.outline, qb):
                deepest = max(deepest, min(distance_to_outline(pa.outline, qa), distance_to_outline(pb.outline, qb)))
        relative = deepest / min(pa.diameter, pb.diameter)
        if relative > 1e-9:
            out.append((a + 1, b + 1, relative))
    return out


if __name__ == '__main__':
    for path in sys.argv[1:]:
        found = crossings(path)
        print(path + ': ' + (', '.join(f'P{a}/P{b} {r:.3f}' for a, b, r in found) if found else 'none'))
