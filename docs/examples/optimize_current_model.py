#!/usr/bin/python3
"""In-process scripting from Python: mesh a model with Debian's python3-gmsh, then optimize the
current model's mesh in place with cvtmesh (the same libgmsh, so one Gmsh, one model).

    PYTHONPATH=<build>/python /usr/bin/python3 optimize_current_model.py [model.geo] [out.msh]

Entities and physical groups stay; gmsh.write() afterwards sees the optimized mesh.
"""
import sys

import gmsh
import cvtmesh

model = sys.argv[1] if len(sys.argv) > 1 else "geo/cube_sphere.geo"
out = sys.argv[2] if len(sys.argv) > 2 else "cube_sphere_cvt.msh"

gmsh.initialize()
gmsh.option.setNumber("Mesh.MeshSizeFactor", 2)  # a coarse mesh: the example runs fast
gmsh.open(model)
gmsh.model.mesh.generate(3)

print("methods:", cvtmesh.methods(3))
table = cvtmesh.optimize(
    method=cvtmesh.methods(3)[0],  # the paper's best available: cvdt+swap once it is built in
    max_iterations=20,
    quality_views=True,  # adds ElementData views: Q, radius ratio, min dihedral angle
    progress=lambda p: print(f"  {p['phase']} {p['iteration']}: Q avg {p['q_avg']:.4f}"),
)
print(f"{table['method']}: {table['iterations']} iterations, {table['seconds']:.2f} s")
for row in ("number_of_elements", "q_min", "average_quality", "bad_elements_pct",
            "min_dihedral_angle"):
    print(f"  {row:20s} {table['before'][row]:>10.4g} -> {table['after'][row]:>10.4g}")

# The model holds the optimized mesh: write it, then append the quality views to the same file.
gmsh.write(out)
gmsh.option.setNumber("PostProcessing.SaveMesh", 0)  # the mesh is in the file already
gmsh.option.setNumber("PostProcessing.SaveInterpolationMatrices", 0)
for view in table["views"]:
    gmsh.view.write(view, out, append=True)
print("wrote", out)
gmsh.finalize()
