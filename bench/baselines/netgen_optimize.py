#!/usr/bin/env python3
# Netgen's volume optimizer (Mesh.OptimizeVolumeMesh of Debian's python3-netgen: combine, split,
# swap and smooth; surface points and surface elements kept) on a mesh passed by cvtmesh's
# bench/baselines/netgen_optimize.cpp. Not part of the library: a comparison baseline.
#
# Usage: netgen_optimize.py IN OUT   (binary files, little-endian; layout below)
#   IN : int64 nv, nt, nf; float64 xyz[nv*3]; int32 tets[nt*4] (0-based, cvtmesh/Gmsh
#        orientation); int32 tet_region[nt]; int32 tris[nf*3]; int32 tri_surface[nf]
#   OUT: float64 seconds; int64 nv, nt, nf; the same arrays.
# Exit 3 when netgen cannot be imported (the caller leaves the column out).
import sys
import time

import numpy as np

try:
    from netgen.meshing import Element2D, Element3D, FaceDescriptor, Mesh, MeshPoint
    from netgen.csg import Pnt
except Exception as e:  # pragma: no cover - depends on the machine
    print("netgen_optimize: cannot import netgen (python3-netgen): %s" % e, file=sys.stderr)
    sys.exit(3)


def read_input(path):
    with open(path, "rb") as f:
        nv, nt, nf = np.fromfile(f, dtype="<i8", count=3)
        xyz = np.fromfile(f, dtype="<f8", count=3 * nv).reshape(-1, 3)
        tets = np.fromfile(f, dtype="<i4", count=4 * nt).reshape(-1, 4)
        tet_region = np.fromfile(f, dtype="<i4", count=nt)
        tris = np.fromfile(f, dtype="<i4", count=3 * nf).reshape(-1, 3)
        tri_surface = np.fromfile(f, dtype="<i4", count=nf)
    return xyz, tets, tet_region, tris, tri_surface


def main():
    xyz, tets, tet_region, tris, tri_surface = read_input(sys.argv[1])
    m = Mesh(dim=3)
    pids = [m.Add(MeshPoint(Pnt(float(p[0]), float(p[1]), float(p[2])))) for p in xyz]
    # Netgen numbers regions and face descriptors from 1; its tet orientation is the opposite of
    # Gmsh's (swap the last two vertices), and so is its triangle orientation.
    regions = sorted(set(int(r) for r in tet_region))
    region_index = {r: i + 1 for i, r in enumerate(regions)}
    surfaces = sorted(set(int(s) for s in tri_surface))
    fd_index = {}
    for i, s in enumerate(surfaces):
        fd_index[s] = m.Add(FaceDescriptor(surfnr=i + 1, domin=1, domout=0, bc=i + 1))
    for t, s in zip(tris, tri_surface):
        m.Add(Element2D(fd_index[int(s)], [pids[t[0]], pids[t[2]], pids[t[1]]]))
    for t, r in zip(tets, tet_region):
        m.Add(Element3D(region_index[int(r)], [pids[t[0]], pids[t[1]], pids[t[3]], pids[t[2]]]))
    t0 = time.perf_counter()
    m.OptimizeVolumeMesh()
    seconds = time.perf_counter() - t0

    pts = np.array([[p[0], p[1], p[2]] for p in m.Points()], dtype="<f8")
    e3 = m.Elements3D()
    out_tets = np.array([[v.nr - 1 for v in e.vertices] for e in e3], dtype="<i4").reshape(-1, 4)
    out_tets = out_tets[:, [0, 1, 3, 2]]
    out_region = np.array([regions[e.index - 1] for e in e3], dtype="<i4")
    e2 = m.Elements2D()
    out_tris = np.array([[v.nr - 1 for v in e.vertices] for e in e2], dtype="<i4").reshape(-1, 3)
    out_tris = out_tris[:, [0, 2, 1]]
    out_surface = np.array([surfaces[e.index - 1] for e in e2], dtype="<i4")
    with open(sys.argv[2], "wb") as f:
        np.array([seconds], dtype="<f8").tofile(f)
        np.array([len(pts), len(out_tets), len(out_tris)], dtype="<i8").tofile(f)
        pts.tofile(f)
        out_tets.tofile(f)
        out_region.tofile(f)
        out_tris.tofile(f)
        out_surface.tofile(f)


if __name__ == "__main__":
    main()
