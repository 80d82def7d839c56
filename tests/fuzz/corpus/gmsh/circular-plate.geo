// Circular plate of radius 50 mm centred at the origin, meshed with 9-node quadrilaterals, for
// examples/static-circular-clamped.toml and examples/impact-circular-clamped.toml (docs/mesh.md), refined
// toward the centre, where the impactor strikes. circular-plate.msh beside it was made from this
// file by gmsh 4.8.4 (Debian's gmsh), as the gmsh application does with
//   gmsh circular-plate.geo -2 -o circular-plate.msh
R = 0.05;        // radius [m]
lc = R / 6;      // element size at the rim [m]
lc_centre = 0.002; // element size at the centre, about the contact radius of an impact [m]
Point(1) = {0, 0, 0, lc_centre};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc};
Point(5) = {0, -R, 0, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Point{1} In Surface{1};          // a node at the centre, where the load acts and the impactor strikes
Physical Curve("rim") = {1, 2, 3, 4};
Physical Point("centre") = {1};
Physical Surface("plate") = {1};
Mesh.Algorithm = 6;              // Frontal-Delaunay triangles,
Mesh.RecombineAll = 1;           // recombined into quadrilaterals,
Mesh.ElementOrder = 2;           // second order
Mesh.SecondOrderIncomplete = 0;  // with the centre node: 9-node quadrilaterals (QUAD9)
