// The quadrilateral of Du & Wang, Section 3, example 1: a 60-degree parallelogram with sides
// of length L, which can be meshed with equilateral triangles only. Its regular mesh (every
// triangle equilateral, edge L/n) is made by a structured (transfinite) triangulation whose
// diagonals follow the short diagonal of each cell; with regular = 0 Gmsh's Frontal-Delaunay
// algorithm (advancing-front-like, as in the paper) meshes it with the uniform size L/n, which
// on this domain also gives the regular mesh.
DefineConstant[ n = {12, Name "Parameters/divisions per side n"} ];
DefineConstant[ regular = {1, Name "Parameters/structured regular mesh"} ];
L = 1;
h = L / n;
Point(1) = {0, 0, 0, h};
Point(2) = {L, 0, 0, h};
Point(3) = {1.5 * L, Sqrt(3) / 2 * L, 0, h};
Point(4) = {0.5 * L, Sqrt(3) / 2 * L, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (regular)
  Transfinite Curve{1, 2, 3, 4} = n + 1;
  Transfinite Surface{1} = {1, 2, 3, 4} Left;
EndIf
Mesh.Algorithm = 6;  // Frontal-Delaunay
