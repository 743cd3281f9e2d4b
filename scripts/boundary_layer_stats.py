#!/usr/bin/env python3
"""The quality of a tet mesh by distance to the boundary (issue 13's diagnosis of the femur).

Reads a Gmsh .msh 4.1 ASCII file (tets and boundary triangles) and prints: the mean Q (the
paper's 72*sqrt(3)*V/(sum L^2)^(3/2)) of the tets by their number of boundary vertices (0-4), with
each group's share of the mesh and of the total shortfall sum(1 - Q); the tets standing on a
boundary triangle against the others; the boundary triangles' Q; the mean edge lengths on the
surface, in the interior and from the surface inwards; and the height of the tets on the boundary
triangles over the height of a regular tet on the same triangle (> 1: tall tets, the interior too
far from a surface finer than it).
Usage: scripts/boundary_layer_stats.py MESH.msh
"""
import math
import statistics
import sys
from collections import defaultdict


def read_msh41(path):
    lines = open(path).read().split("\n")
    xyz, tris, tets = {}, [], []
    i = 0
    while i < len(lines):
        if lines[i] == "$Nodes":
            nb = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(nb):
                n = int(lines[i].split()[3])
                i += 1
                ids = [int(lines[i + k]) for k in range(n)]
                i += n
                for k in range(n):
                    xyz[ids[k]] = tuple(map(float, lines[i + k].split()[:3]))
                i += n
        elif lines[i] == "$Elements":
            nb = int(lines[i + 1].split()[0])
            i += 2
            for _ in range(nb):
                _, _, etype, n = map(int, lines[i].split())
                i += 1
                for k in range(n):
                    v = list(map(int, lines[i + k].split()))[1:]
                    if etype == 2:
                        tris.append(v)
                    elif etype == 4:
                        tets.append(v)
                i += n
        else:
            i += 1
    return xyz, tris, tets


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def d2(a, b):
    s = sub(a, b)
    return dot(s, s)


def tet_q(a, b, c, d):
    v = dot(cross(sub(b, a), sub(c, a)), sub(d, a)) / 6
    s = d2(a, b) + d2(a, c) + d2(a, d) + d2(b, c) + d2(b, d) + d2(c, d)
    return 72 * math.sqrt(3) * v / s**1.5


def tri_q(a, b, c):
    n = cross(sub(b, a), sub(c, a))
    return 4 * math.sqrt(3) * 0.5 * math.sqrt(dot(n, n)) / (d2(a, b) + d2(b, c) + d2(c, a))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    xyz, tris, tets = read_msh41(sys.argv[1])
    bv = {v for t in tris for v in t}
    faces = {tuple(sorted(t)) for t in tris}
    by = defaultdict(list)
    on_face, other = [], []
    for t in tets:
        q = tet_q(*[xyz[v] for v in t])
        by[sum(v in bv for v in t)].append(q)
        f = any(tuple(sorted(t[i] for i in range(4) if i != j)) in faces for j in range(4))
        (on_face if f else other).append(q)
    n = len(tets)
    shortfall = sum(1 - q for g in by.values() for q in g)
    print(f"tets {n}  mean Q {sum(sum(g) for g in by.values()) / n:.4f}  "
          f"boundary vertices {len(bv)} of {len(xyz)}")
    for k in range(5):
        g = sorted(by[k])
        if g:
            print(f"  {k} boundary vertices: {len(g):6d} tets ({100 * len(g) / n:5.1f} %)  "
                  f"mean Q {sum(g) / len(g):.4f}  min {g[0]:.3f}  median {g[len(g) // 2]:.3f}  "
                  f"share of the shortfall {sum(1 - q for q in g) / shortfall:.3f}")
    print(f"  on a boundary triangle: {len(on_face)} tets, mean Q "
          f"{sum(on_face) / len(on_face):.4f}; the others {sum(other) / len(other):.4f}")
    tq = sorted(tri_q(*[xyz[v] for v in t]) for t in tris)
    print(f"boundary triangles {len(tris)}  mean Q {sum(tq) / len(tq):.4f}  min {tq[0]:.3f}  "
          f"10th percentile {tq[len(tq) // 10]:.3f}")
    edges, surface = set(), set()
    for t in tets:
        for i in range(4):
            for j in range(i + 1, 4):
                edges.add((min(t[i], t[j]), max(t[i], t[j])))
    for t in tris:
        for i in range(3):
            a, b = t[i], t[(i + 1) % 3]
            surface.add((min(a, b), max(a, b)))
    length = lambda e: math.sqrt(d2(xyz[e[0]], xyz[e[1]]))
    ls = [length(e) for e in surface]
    li = [length(e) for e in edges if e[0] not in bv and e[1] not in bv]
    lx = [length(e) for e in edges if (e[0] in bv) != (e[1] in bv)]
    mean = lambda x: statistics.mean(x) if x else float("nan")
    print(f"mean edge length: surface {mean(ls):.5g}, interior {mean(li):.5g}, "
          f"surface to interior {mean(lx):.5g} (interior / surface {mean(li) / mean(ls):.2f})")
    r = []
    for t in tets:
        for j in range(4):
            f = tuple(sorted(t[i] for i in range(4) if i != j))
            if f in faces:
                a, b, c = (xyz[v] for v in f)
                nrm = cross(sub(b, a), sub(c, a))
                h = abs(dot(nrm, sub(xyz[t[j]], a))) / math.sqrt(dot(nrm, nrm))
                side = (math.sqrt(d2(a, b)) + math.sqrt(d2(b, c)) + math.sqrt(d2(c, a))) / 3
                r.append(h / (math.sqrt(2 / 3) * side))
    r.sort()
    if r:
        print(f"tets on boundary triangles, height / a regular tet's: mean {mean(r):.3f}  "
              f"10th percentile {r[len(r) // 10]:.3f}  median {r[len(r) // 2]:.3f}  "
              f"90th {r[9 * len(r) // 10]:.3f}")


if __name__ == "__main__":
    main()
