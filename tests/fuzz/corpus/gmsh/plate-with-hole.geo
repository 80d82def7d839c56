// A 250 x 150 mm panel with a central hole of 30 mm diameter (a cut-out for a fastener or a cable),
// for examples/impact-plate-with-hole.toml, which meshes it on the fly ([mesh] geo) with elements
// graded toward the impact point. Physical groups: "edges" (the panel's outer edges), "hole" and
// "plate".
a = 0.250; b = 0.150;  // panel [m]
r = 0.015;             // hole radius [m]
lc = 0.010;            // element size where the deck's size field does not set one [m]
Point(1) = {0, 0, 0, lc}; Point(2) = {a, 0, 0, lc}; Point(3) = {a, b, 0, lc}; Point(4) = {0, b, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(10) = {a / 2, b / 2, 0, lc};
Point(11) = {a / 2 + r, b / 2, 0, lc}; Point(12) = {a / 2, b / 2 + r, 0, lc};
Point(13) = {a / 2 - r, b / 2, 0, lc}; Point(14) = {a / 2, b / 2 - r, 0, lc};
Circle(11) = {11, 10, 12}; Circle(12) = {12, 10, 13}; Circle(13) = {13, 10, 14}; Circle(14) = {14, 10, 11};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(1) = {1, 2};
Physical Curve("edges") = {1, 2, 3, 4};
Physical Curve("hole") = {11, 12, 13, 14};
Physical Surface("plate") = {1};
