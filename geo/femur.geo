// The femur of the paper's second 3D example (Du & Wang, Figs. 10-11 / Table 7).
// Surface: a right femur segmented from the Visible Human Project female CT (BMFToolkit,
// zlib licence); see ../shared/data/PROVENANCE.md. The data stays outside this repository:
// pass its path with  -setstring stl /path/to/femur_bmf_vhp_female_R.stl  (gmsh) or
// --set-string stl=... ; the default is the project's sibling shared/ folder.
// The segmentation surface (min angle 5 deg) is remeshed: it is classified into patches by
// the feature angle, re-parametrized (CreateGeometry) and meshed with size h (metres).
stl = DefineString[StrCat(CurrentDir, "/../../shared/data/femur_bmf_vhp_female_R.stl"), Name "cvtmesh/Geometry/femur STL"];
DefineConstant[
  h = {0.0048, Name "cvtmesh/Geometry/h (m)"},
  angle = {40, Name "cvtmesh/Geometry/feature angle (deg)"},
  surface_algorithm = {5, Name "cvtmesh/Geometry/surface mesher (5 Delaunay, 6 Frontal-Delaunay)"}
];
Merge StrCat(stl);
ClassifySurfaces{angle * Pi / 180, 1, 1, Pi};
CreateGeometry;
Surface Loop(1) = Surface{:};
Volume(1) = {1};
Physical Surface("bone_surface", 1) = Surface{:};
Physical Volume("bone", 2) = {1};
Mesh.MeshSizeMin = 0;
Mesh.MeshSizeMax = h;
Mesh.MeshSizeFromCurvature = 0;
// Delaunay (5) for the re-parametrized patches is ~15x faster than Frontal-Delaunay (6), which
// gives somewhat better surface triangles (min Q 0.10 vs 0.05).
Mesh.Algorithm = surface_algorithm;
