// The washer of Du & Wang, Section 3, example 2: an annulus with a nonuniform sizing, fine at
// the inner circle and growing linearly outward, meshed by Gmsh's Frontal-Delaunay algorithm
// (an advancing-front-like mesher, as in the paper).
//   size h(r) = h0 + g * (r - r0),  r0 <= r <= r1
// The same h is the analytic sizing field used by the 2D optimizers (docs/reproduction-2d.md).
DefineConstant[ r0 = {1.0, Name "Parameters/inner radius r0"} ];
DefineConstant[ r1 = {2.5, Name "Parameters/outer radius r1"} ];
DefineConstant[ h0 = {0.08, Name "Parameters/size h0 at the inner circle"} ];
DefineConstant[ g = {0.08, Name "Parameters/size gradient g"} ];

Point(1) = {0, 0, 0};
Point(2) = {r0, 0, 0};
Point(3) = {-r0, 0, 0};
Point(4) = {r1, 0, 0};
Point(5) = {-r1, 0, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 2};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 4};
Curve Loop(1) = {3, 4};
Curve Loop(2) = {1, 2};
Plane Surface(1) = {1, 2};

Field[1] = MathEval;
Field[1].F = Sprintf("%g + %g * (Sqrt(x * x + y * y) - %g)", h0, g, r0);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;  // Frontal-Delaunay
