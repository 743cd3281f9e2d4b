#!/usr/bin/env python3
"""Independent check of cvtmesh's FE measures (core/quality/fe_measures.h) with scipy.

For each .msh given (tetrahedra, or triangles in the plane): assembles the P1 stiffness K and the
row-sum lumped mass M_L with numpy/scipy (its own code, not cvtmesh's), then prints
  time_step     2 / sqrt(lambda_max(M_L^-1 K))  (scipy.sparse.linalg.eigsh, tol 1e-8)
  element_time_step  min over the elements of 2 / sqrt(lambda_max(M_e^-1 K_e)) (numpy eigvalsh)
  cg_iterations Jacobi-preconditioned CG on K u = M_L 1 with the boundary vertices (on a face of
                one element) Dirichlet, from 0, to ||r|| <= 1e-8 ||b|| (scipy.sparse.linalg.cg)
as JSON, one object per file. Needs python3-numpy, python3-scipy, python3-meshio (Debian).
Usage: scripts/fe_check.py MESH.vtk...  (a .msh of ours: `cvtmesh convert X.msh X.vtk` first --
Debian's meshio 5.0 cannot read .msh 4.1 files with physical groups)
"""
import json
import sys

import meshio
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla


def simplices(mesh):
    for kind, dim in (("tetra", 3), ("triangle", 2)):
        blocks = [c.data for c in mesh.cells if c.type == kind]
        if blocks:
            return np.vstack(blocks), dim
    raise SystemExit("no tetrahedra or triangles")


def read(path):
    """The mesh without its $ElementData views (meshio wants cell data on every cell block)."""
    import re
    import tempfile

    with open(path, errors="surrogateescape") as f:
        text = f.read()
    text = re.sub(r"\$ElementData\n.*?\$EndElementData\n", "", text, flags=re.S)
    with tempfile.NamedTemporaryFile("w", suffix=".msh", errors="surrogateescape") as t:
        t.write(text)
        t.flush()
        return meshio.read(t.name, file_format="gmsh")


def check(path):
    mesh = read(path) if path.endswith(".msh") else meshio.read(path)
    T, d = simplices(mesh)
    used = np.unique(T)
    X = mesh.points[:, :d]
    n = X.shape[0]
    k = d + 1
    # Barycentric gradients: rows 1..d of inv([1 x]) per element.
    A = np.ones((T.shape[0], k, k))
    A[:, :, 1:] = X[T]
    C = np.linalg.inv(A)  # column i = coefficients of phi_i
    G = C[:, 1:, :].transpose(0, 2, 1)  # (#E, k, d): grad phi_i
    vol = np.abs(np.linalg.det(A)) / (6.0 if d == 3 else 2.0)
    Ke = vol[:, None, None] * np.einsum("eid,ejd->eij", G, G)
    rows = np.repeat(T, k, axis=1).ravel()
    cols = np.tile(T, (1, k)).ravel()
    K = sp.csr_matrix((Ke.ravel(), (rows, cols)), shape=(n, n))
    m = np.bincount(T.ravel(), weights=np.repeat(vol / k, k), minlength=n)
    # Global: symmetric M^-1/2 K M^-1/2 on the used vertices.
    w = 1.0 / np.sqrt(m[used])
    Ku = K[used][:, used]
    S = sp.diags(w) @ Ku @ sp.diags(w)
    lam = sla.eigsh(S, k=1, which="LA", tol=1e-8, return_eigenvectors=False)[0]
    # Element bound: lambda_max(M_e^-1 K_e) = k * lambda_max(G G^T).
    le = k * np.linalg.eigvalsh(np.einsum("eid,ejd->eij", G, G))[:, -1]
    # Boundary: faces of one element.
    faces = np.sort(np.vstack([np.delete(T, i, axis=1) for i in range(k)]), axis=1)
    uniq, counts = np.unique(faces, axis=0, return_counts=True)
    boundary = np.zeros(n, bool)
    boundary[uniq[counts == 1].ravel()] = True
    free = np.setdiff1d(used, np.nonzero(boundary)[0])
    Kf = K[free][:, free].tocsr()
    b = m[free]
    its = [0]

    def count(_):
        its[0] += 1

    Dinv = sp.diags(1.0 / Kf.diagonal())
    kw = {"rtol": 1e-8} if "rtol" in sla.cg.__code__.co_varnames else {"tol": 1e-8}
    x, info = sla.cg(Kf, b, M=Dinv, callback=count, atol=0.0, maxiter=100000, **kw)
    return {
        "file": path,
        "elements": int(T.shape[0]),
        "time_step": 2.0 / np.sqrt(lam),
        "element_time_step": float(np.min(2.0 / np.sqrt(le))),
        "cg_iterations": its[0],
        "cg_residual": float(np.linalg.norm(b - Kf @ x) / np.linalg.norm(b)),
    }


if __name__ == "__main__":
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    print(json.dumps([check(p) for p in sys.argv[1:]], indent=2))
