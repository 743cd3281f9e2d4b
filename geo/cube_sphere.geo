// A cube containing a sphere: the paper's 3D example (Du & Wang, Fig. 8 / Table 6).
// The flow domain is the unit cube minus a ball of radius R at its centre (one volume).
// With two_regions = 1 the ball is meshed as a second region (BooleanFragments), sharing its
// surface with the outer region as an interface.
// Parameters (gmsh -setnumber NAME VALUE, or cvtmesh --set NAME=VALUE):
//   h            target edge length far from the ball (default gives ~25k tets, like Table 6)
//   h_ball       edge length on the ball surface
//   R            ball radius
//   two_regions  0: cube minus ball; 1: cube and ball as two regions
SetFactory("OpenCASCADE");
DefineConstant[
  h = {0.065, Name "cvtmesh/Geometry/h (far field)"},
  h_ball = {0.05, Name "cvtmesh/Geometry/h on the ball"},
  R = {0.25, Name "cvtmesh/Geometry/ball radius"},
  two_regions = {0, Choices{0, 1}, Name "cvtmesh/Geometry/ball as a region"}
];
Box(1) = {0, 0, 0, 1, 1, 1};
Sphere(2) = {0.5, 0.5, 0.5, R};
If (two_regions)
  v() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; };
  Physical Volume("fluid", 1) = {v(1)};
  Physical Volume("ball", 2) = {v(0)};
  Physical Surface("ball_surface", 3) = Boundary{ Volume{v(0)}; };
Else
  BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
  Physical Volume("fluid", 1) = {3};
  Physical Surface("ball_surface", 3) = {7};
  Physical Surface("cube_faces", 4) = {1, 2, 3, 4, 5, 6};
EndIf
ball() = Surface In BoundingBox{0.5-R-1e-3, 0.5-R-1e-3, 0.5-R-1e-3, 0.5+R+1e-3, 0.5+R+1e-3, 0.5+R+1e-3};
// Size: h_ball on the ball surface, growing linearly to h at distance 2R from it.
Field[1] = Distance;
Field[1].SurfacesList = {ball()};
Field[1].NumPointsPerCurve = 60;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_ball;
Field[2].SizeMax = h;
Field[2].DistMin = 0;
Field[2].DistMax = 2 * R;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
