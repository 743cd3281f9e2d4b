// The .geo route: mesh a model, hand its mesh to the cvtmesh CLI with SystemCall, and merge the
// optimized, quality-annotated result back in place of the model.
//
//   gmsh optimize_with_cli.geo                       (GUI; cvtmesh on PATH)
//   gmsh optimize_with_cli.geo -setstring cvtmesh_exe /path/to/cvtmesh -setstring model /path/m.geo -
//
// Files go next to this .geo: <model>_init.msh (Gmsh's mesh), <model>_cvt.msh (optimized, with
// the per-element views "Q (Du-Wang)", "Radius ratio 3r/R", "Min dihedral angle").
DefineConstant[
  cvtmesh_exe = {"cvtmesh", Name "cvtmesh/CLI executable"},
  model = {"../../geo/cube_sphere.geo", Name "cvtmesh/Model"},
  method = {"cvdt+swap", Name "cvtmesh/Method"},
  iterations = {20, Name "cvtmesh/Max iterations"}
];
Include Str(model);
Mesh 3;
name = StrPrefix(StrRelative(model));
init = StrCat(CurrentDir, name, "_init.msh");
result = StrCat(CurrentDir, name, "_cvt.msh");
Save Str(init);
// (.geo strings cannot hold a double quote: the shell gets single-quoted paths.)
SystemCall StrCat("'", cvtmesh_exe, "' optimize '", init, "' -o '", result,
                  "' --quality --quiet --method ", method, " --max-iterations ",
                  Sprintf("%g", iterations));
Delete Model;
Merge Str(result);
