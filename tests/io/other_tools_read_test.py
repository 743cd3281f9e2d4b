#!/usr/bin/env python3
"""Every format cvtmesh writes, read by the tools users have: Debian's meshio (points, cells,
physical groups, cell data) and Gmsh itself (the gmsh Python module: element counts, physical
groups, the --quality views and the companion .opt).

Usage: other_tools_read_test.py CVTMESH_CLI SOURCE_DIR   (run with /usr/bin/python3)
"""
import math
import os
import subprocess
import sys
import tempfile
import warnings

import meshio
import gmsh

CLI, SRC = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
GEO = os.path.join(SRC, "geo")
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(*args):
    p = subprocess.run([CLI, *args], capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"cvtmesh {' '.join(args)} exited {p.returncode}: {p.stderr}")
    return p


def read_meshio(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return meshio.read(path)


def blocks(m):
    out = {}
    for c in m.cells:
        out[c.type] = out.get(c.type, 0) + len(c.data)
    return out


def gmsh_summary(path):
    """Counts of elements by dimension, physical groups and views as Gmsh sees them."""
    gmsh.initialize(["gmsh", "-nopopup"])
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.open(path)
        counts = {}
        for d in range(4):
            types, tags, _ = gmsh.model.mesh.getElements(d)
            counts[d] = sum(len(t) for t in tags)
        groups = {}
        for d, t in gmsh.model.getPhysicalGroups():
            groups[(d, t)] = gmsh.model.getPhysicalName(d, t)
        views = []
        for v in gmsh.view.getTags():
            name = gmsh.option.getString(f"View[{gmsh.view.getIndex(v)}].Name")
            visible = gmsh.option.getNumber(f"View[{gmsh.view.getIndex(v)}].Visible")
            views.append((name, visible,
                          gmsh.option.getNumber(f"View[{gmsh.view.getIndex(v)}].RangeType"),
                          gmsh.option.getNumber(f"View[{gmsh.view.getIndex(v)}].CustomMin"),
                          gmsh.option.getNumber(f"View[{gmsh.view.getIndex(v)}].CustomMax")))
        return counts, groups, views
    finally:
        gmsh.finalize()


def gmsh_clip(path):
    """What the .opt sets for the cut: (View[0].Clip, Mesh.Clip, [A, B, C, D], the direction
    toward the camera for Gmsh's view angles)."""
    gmsh.initialize(["gmsh", "-nopopup"])
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.open(path)
        plane = [gmsh.option.getNumber(f"General.Clip0{c}") for c in "ABCD"]
        rx, ry, rz = (math.radians(gmsh.option.getNumber(f"General.Rotation{c}")) for c in "XYZ")
        # The third row of Rx Ry Rz: the camera looks along -z in eye coordinates.
        toward = [-math.cos(rx) * math.sin(ry) * math.cos(rz) + math.sin(rx) * math.sin(rz),
                  math.cos(rx) * math.sin(ry) * math.sin(rz) + math.sin(rx) * math.cos(rz),
                  math.cos(rx) * math.cos(ry)]
        return (gmsh.option.getNumber("View[0].Clip"), gmsh.option.getNumber("Mesh.Clip"), plane,
                toward)
    finally:
        gmsh.finalize()


tmp = tempfile.mkdtemp(prefix="cvtmesh-tools-")
cs = os.path.join(GEO, "cube_sphere.geo")
quad = os.path.join(GEO, "quad.geo")

# ---- .msh from a .geo with physical groups: only the groups' elements, like Gmsh --------------
for version in ("4.1", "2.2"):
    for binary in ([], ["--binary"]):
        out = os.path.join(tmp, f"cs_{version}{'b' if binary else 'a'}.msh")
        run("convert", cs, out, "--msh-version", version, *binary)
        m = read_meshio(out)
        b = blocks(m)
        tag = f"cube_sphere MSH {version}{' binary' if binary else ''}"
        check(b.get("tetra", 0) > 20000, f"{tag}: tetra read by meshio ({b})")
        check("gmsh:physical" in m.cell_data, f"{tag}: gmsh:physical in meshio's cell data")
        names = set(m.field_data)
        check({"fluid", "ball_surface", "cube_faces"} <= names,
              f"{tag}: physical names {sorted(names)}")
        check(not any(n.startswith("cvtmesh") for n in names), f"{tag}: no invented group {names}")
        phys = {int(v) for arr in m.cell_data["gmsh:physical"] for v in arr}
        check(0 not in phys, f"{tag}: every element in a physical group ({sorted(phys)})")
        counts, groups, _ = gmsh_summary(out)
        check(counts[3] == b.get("tetra", -1), f"{tag}: Gmsh reads {counts[3]} tets, meshio "
              f"{b.get('tetra')}")
        check(set(groups.values()) == {"fluid", "ball_surface", "cube_faces"},
              f"{tag}: Gmsh's physical groups {groups}")

# Gmsh's own output of the same model: the same blocks.
gmsh.initialize(["gmsh", "-nopopup"])
gmsh.option.setNumber("General.Terminal", 0)
gmsh.open(cs)
gmsh.model.mesh.generate(3)
ref = os.path.join(tmp, "gmsh_own.msh")
gmsh.write(ref)
gmsh.finalize()
own, ours = blocks(read_meshio(ref)), blocks(read_meshio(os.path.join(tmp, "cs_4.1a.msh")))
check(set(own) == set(ours), f"cell types as Gmsh's own output: {own} vs {ours}")
check(own.get("triangle") == ours.get("triangle"),
      f"boundary triangles as Gmsh's own output: {own.get('triangle')} vs {ours.get('triangle')}")

# --save-all: every element, also those outside the groups (MSH 4.1 only).
out = os.path.join(tmp, "cs_all.msh")
run("convert", cs, out, "--save-all")
all_counts, _, _ = gmsh_summary(out)
some_counts, _, _ = gmsh_summary(os.path.join(tmp, "cs_4.1a.msh"))
check(all_counts[1] > some_counts[1], f"--save-all writes the curves too ({all_counts} vs "
      f"{some_counts})")

# ---- .msh input: the blocks it had and no others ---------------------------------------------
# A file with physical groups, saved by Gmsh (only the groups' elements): optimize and convert
# keep exactly its element types and counts of lower-dimensional elements (the free boundary's
# surface coarsening may remove surface triangles: none added; without it, the same count).
src = os.path.join(tmp, "cs_4.1a.msh")
src_blocks = blocks(read_meshio(src))
for version, extra in (("4.1", []), ("2.2", []), ("4.1", ["--coarsen-surface", "0"])):
    out = os.path.join(tmp, f"opt_{version}.msh")
    run("optimize", src, "-o", out, "--max-iterations", "3", "-q", "--msh-version", version, *extra)
    b = blocks(read_meshio(out))
    check(set(b) == set(src_blocks), f"optimize MSH {version}: cell types {b} vs input {src_blocks}")
    for t in ("vertex", "line", "triangle"):
        same = b.get(t) == src_blocks.get(t)
        if t == "triangle" and not extra:
            same = 0 < b.get(t) <= src_blocks.get(t)
        check(same, f"optimize MSH {version} {extra}: {t} count {b.get(t)} vs input "
              f"{src_blocks.get(t)}")
    m = read_meshio(out)
    check(not any(n.startswith("cvtmesh") for n in m.field_data),
          f"optimize MSH {version}: no invented group {list(m.field_data)}")

# A file of tets only (no boundary triangles): none are added.
tets_only = os.path.join(tmp, "tets_only.msh")
m = read_meshio(src)
meshio.write(tets_only, meshio.Mesh(m.points, [("tetra", m.cells_dict["tetra"])]),
             file_format="gmsh22", binary=False)
out = os.path.join(tmp, "tets_only_out.msh")
run("convert", tets_only, out)
b = blocks(read_meshio(out))
check(set(b) == {"tetra"}, f"a tets-only .msh stays tets only: {b}")

# ---- --quality: cell data meshio reads per block, views Gmsh shows with the .opt --------------
for version in ("4.1", "2.2"):
    for binary in ([], ["--binary"]):
        for model in (cs, quad):
            out = os.path.join(tmp, f"q_{os.path.basename(model)}_{version}{'b' if binary else ''}.msh")
            run("convert", model, out, "--quality", "--msh-version", version, *binary)
            tag = f"--quality {os.path.basename(model)} MSH {version}{' binary' if binary else ''}"
            main = "tetra" if model == cs else "triangle"
            if version == "2.2":
                # meshio 5.0 (Debian 12) cannot read any $ElementData of MSH 2.2: its 2.2 reader
                # splits the data by len() of (type, array) tuples, i.e. by 2. Gmsh only here.
                counts, _, views = gmsh_summary(out)
                check(len(views) == 3 and views[0][1] == 1 and views[1][1] == 0,
                      f"{tag}: Gmsh reads 3 views, Q alone visible ({views})")
                continue
            m = read_meshio(out)
            qkey = [k for k in m.cell_data if k.startswith("Q")]
            check(len(qkey) == 1, f"{tag}: one Q field in meshio's cell data ({list(m.cell_data)})")
            if qkey:
                for c, v in zip(m.cells, m.cell_data[qkey[0]]):
                    check(len(v) == len(c.data), f"{tag}: Q per {c.type} block")
                    if c.type == main:
                        check(all(0 < x <= 1 + 1e-12 for x in v), f"{tag}: Q of the {main}s in (0, 1]")
                    else:
                        check(all(math.isnan(x) for x in v), f"{tag}: Q of {c.type} is NaN")
            counts, _, views = gmsh_summary(out)
            check(len(views) == 3, f"{tag}: Gmsh reads 3 views ({views})")
            if len(views) == 3:
                check(views[0][1] == 1 and views[1][1] == 0 and views[2][1] == 0,
                      f"{tag}: the .opt shows the Q view alone ({views})")
                qs = [x for c, v in zip(m.cells, m.cell_data[qkey[0]]) if c.type == main for x in v]
                check(views[0][2] == 2 and abs(views[0][3] - min(qs)) < 1e-5 and
                      abs(views[0][4] - max(qs)) < 1e-5,
                      f"{tag}: the .opt fits the colour range to Q ({views[0]}, data "
                      f"[{min(qs)}, {max(qs)}])")
            check(os.path.exists(out + ".opt"), f"{tag}: companion .opt written")
            view_clip, mesh_clip, plane, toward = gmsh_clip(out)
            if model == cs:
                # The cut faces the camera: its normal is the view direction (the far half kept,
                # A x + B y + C z + D >= 0), through the centre of the cube [0, 1]^3.
                check(view_clip == 1 and mesh_clip == 1, f"{tag}: the .opt cuts the Q view and "
                      f"the mesh ({view_clip}, {mesh_clip})")
                check(all(abs(plane[k] + toward[k]) < 1e-9 for k in range(3)),
                      f"{tag}: the cut faces the camera ({plane}, toward the camera {toward})")
                centre = [0.5, 0.5, 0.5]
                check(abs(sum(plane[k] * centre[k] for k in range(3)) + plane[3]) < 1e-6,
                      f"{tag}: the cut goes through the centre ({plane})")
            else:
                check(view_clip == 0, f"{tag}: a planar mesh is not cut ({view_clip})")

# Writing again without --quality removes our stale .opt.
out = os.path.join(tmp, "q_cube_sphere.geo_4.1.msh")
run("convert", cs, out)
check(not os.path.exists(out + ".opt"), "a stale .opt of ours is removed")

# ---- The other formats -----------------------------------------------------------------------
for ext, quality in ((".vtk", True), (".vtu", True), (".node", False), (".mesh", False),
                     (".stl", False), (".off", False), (".obj", False), (".ply", False)):
    out = os.path.join(tmp, "cs" + ext)
    run("convert", cs, out, *(["--quality"] if quality else []))
    path = out if ext != ".node" else os.path.join(tmp, "cs.ele")
    try:
        m = read_meshio(path)
    except Exception as e:  # noqa: BLE001 - the failure is what this test reports
        check(False, f"{ext}: meshio cannot read it: {e}")
        continue
    b = blocks(m)
    surface = ext in (".stl", ".off", ".obj", ".ply")
    check(b.get("triangle" if surface else "tetra", 0) > (1000 if surface else 20000),
          f"{ext}: cells read by meshio {b}")
    check(len(m.points) > 1000, f"{ext}: points read by meshio")
    if quality:
        for key in m.cell_data:
            for c, v in zip(m.cells, m.cell_data[key]):
                check(len(v) == len(c.data), f"{ext}: cell data {key} per block")
        check(any(k.startswith("Q") for k in m.cell_data), f"{ext}: Q in cell data {list(m.cell_data)}")
    if ext in (".mesh", ".stl", ".vtk"):  # the ones Gmsh opens (not .vtu, .off, .obj, .ply)
        counts, _, _ = gmsh_summary(out)
        check(counts[2 if surface else 3] > 0, f"{ext}: Gmsh reads its elements ({counts})")

# --quality on TetGen output is refused before anything is written (meshio reads its attributes
# as integers).
p = subprocess.run([CLI, "convert", cs, os.path.join(tmp, "q.node"), "--quality"],
                   capture_output=True, text=True)
check(p.returncode != 0 and "meshio" in p.stderr and not os.path.exists(os.path.join(tmp, "q.ele")),
      f".node --quality refused: {p.returncode} {p.stderr}")

# ---- Input views ($NodeData / $ElementData): carried onto the optimized mesh ------------------
# A box meshed by Gmsh with a vector node field (affine: interpolated exactly) over two time
# steps and an element field (the element centroid's x), saved with the mesh as Gmsh users do
# (gmsh.view.write). optimize carries them onto its mesh; Gmsh reads them by tag, meshio by
# position; convert keeps them as they are.
def affine(p):
    return [1.5 * p[0] - 2 * p[1] + 3, p[2] - 0.5 * p[0], 2.0]


views_in = os.path.join(tmp, "views.msh")
gmsh.initialize(["gmsh", "-nopopup"])
gmsh.option.setNumber("General.Terminal", 0)
try:
    gmsh.model.add("views")
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 0.5)
    gmsh.model.occ.synchronize()
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.2)
    gmsh.model.mesh.generate(3)
    ntags, xyz, _ = gmsh.model.mesh.getNodes()
    nv = gmsh.view.add("velocity")
    for step, scale in enumerate((1.0, 2.0)):
        gmsh.view.addModelData(nv, step, "views", "NodeData", ntags,
                               [[scale * x for x in affine(xyz[3 * i:3 * i + 3])]
                                for i in range(len(ntags))], time=0.5 * step, numComponents=3)
    etags, enodes = gmsh.model.mesh.getElementsByType(4)
    nodes_xyz = {t: xyz[3 * i:3 * i + 3] for i, t in enumerate(ntags)}
    ev = gmsh.view.add("cell_x")
    gmsh.view.addModelData(ev, 0, "views", "ElementData", etags,
                           [[sum(nodes_xyz[n][0] for n in enodes[4 * e:4 * e + 4]) / 4]
                            for e in range(len(etags))])
    gmsh.view.write(nv, views_in)
    gmsh.option.setNumber("PostProcessing.SaveMesh", 0)
    gmsh.view.write(ev, views_in, append=True)
finally:
    gmsh.finalize()


def gmsh_views(path):
    """name -> (kind, [(time, {tag: values})]) and node coordinates, as Gmsh reads them."""
    gmsh.initialize(["gmsh", "-nopopup"])
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.open(path)
        out = {}
        for t in gmsh.view.getTags():
            i = gmsh.view.getIndex(t)
            name = gmsh.option.getString(f"View[{i}].Name")
            steps = []
            for s in range(int(gmsh.option.getNumber(f"View[{i}].NbTimeStep"))):
                kind, tags, data, time, _ = gmsh.view.getModelData(t, s)
                steps.append((time, dict(zip(tags, [list(d) for d in data]))))
            out[name] = (kind, steps)
        ntags, xyz, _ = gmsh.model.mesh.getNodes()
        coords = {t: xyz[3 * i:3 * i + 3] for i, t in enumerate(ntags)}
        etags, enodes = gmsh.model.mesh.getElementsByType(4)
        centroid_x = {t: sum(coords[n][0] for n in enodes[4 * e:4 * e + 4]) / 4
                      for e, t in enumerate(etags)}
        return out, coords, centroid_x
    finally:
        gmsh.finalize()


for cmd, out in (("optimize", "views_opt.msh"), ("convert", "views_conv.msh")):
    out = os.path.join(tmp, out)
    p = run(cmd, views_in, *(["-o", out] if cmd == "optimize" else [out]))
    if cmd == "optimize":
        check("2 view(s) of the input carried" in p.stderr, f"optimize's note: {p.stderr[-400:]}")
    v, coords, centroid_x = gmsh_views(out)
    check(sorted(v) == ["cell_x", "velocity"], f"{cmd}: views {sorted(v)}")
    if "velocity" in v:
        kind, steps = v["velocity"]
        check(kind == "NodeData" and [s[0] for s in steps] == [0.0, 0.5],
              f"{cmd}: velocity is NodeData with times 0, 0.5 ({kind}, {[s[0] for s in steps]})")
        worst = max(abs(scale * a - b) for scale, (_, d) in zip((1.0, 2.0), steps)
                    for tag, vals in d.items() for a, b in zip(affine(coords[tag]), vals))
        check(worst < 1e-9, f"{cmd}: the affine node field interpolated exactly ({worst})")
        check(len(steps[0][1]) == len(coords), f"{cmd}: a value on every node")
    if "cell_x" in v:
        kind, steps = v["cell_x"]
        vals = {t: d[0] for t, d in steps[0][1].items() if not math.isnan(d[0])}
        check(kind == "ElementData" and set(vals) == set(centroid_x),
              f"{cmd}: cell_x on every tet ({kind}, {len(vals)} of {len(centroid_x)})")
        worst = max((abs(vals[t] - centroid_x[t]) for t in vals if t in centroid_x), default=1)
        check(worst < (1e-12 if cmd == "convert" else 0.25),
              f"{cmd}: cell_x is the x of an input tet around the centroid ({worst})")
    m = read_meshio(out)
    if "velocity" in m.point_data:
        pd = m.point_data["velocity"]  # meshio keeps the last step of a name (scale 2)
        worst = max(abs(2 * a - b) for i, pt in enumerate(m.points)
                    for a, b in zip(affine(pt), pd[i]))
        check(worst < 1e-9, f"{cmd}: meshio reads the node field at its points ({worst})")
    else:
        check(False, f"{cmd}: meshio point data {list(m.point_data)}")
    if "cell_x" in m.cell_data:
        for c, vals in zip(m.cells, m.cell_data["cell_x"]):
            if c.type != "tetra":
                continue
            cx = m.points[c.data].mean(axis=1)[:, 0]
            worst = max(abs(a - b) for a, b in zip(cx, vals))
            check(worst < (1e-12 if cmd == "convert" else 0.25),
                  f"{cmd}: meshio reads cell_x per tet in order ({worst})")
    else:
        check(False, f"{cmd}: meshio cell data {list(m.cell_data)}")
p = run("optimize", views_in, "-o", os.path.join(tmp, "views_opt.vtk"))
check("not written" in p.stderr, f"a .vtk output says the views are not written: {p.stderr[-300:]}")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
