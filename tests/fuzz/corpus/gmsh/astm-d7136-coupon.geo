// The ASTM D7136/D7136M drop-weight coupon: a 150 x 100 mm plate resting on a support with a
// 125 x 75 mm window, held down by four clamps (docs/mesh.md, "Test rigs"). The plate's corner is at
// the origin, its long side along x; the window is centred. The clamp tips are at (75 ± 50, 50 ± 43.75)
// mm, over the support, 12.5 mm in from the window's short edges: the positions of R. Kok's public
// Abaqus model of the test (github.com/rutger-kok/ap_ply_model_creation), since the standard's figure
// was not at hand. Used by examples/static-astm-d7136-window.toml, which meshes it on the fly
// ([mesh] geo), and by the tests of the window support.
a = 0.150;  b = 0.100;   // plate [m]
wa = 0.125; wb = 0.075;  // window [m]
lc = 0.005;              // element size [m] (a deck's mesh.size_at_impact / max_size override it)
x0 = (a - wa) / 2; x1 = x0 + wa; y0 = (b - wb) / 2; y1 = y0 + wb;
Point(1) = {0, 0, 0, lc}; Point(2) = {a, 0, 0, lc}; Point(3) = {a, b, 0, lc}; Point(4) = {0, b, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
// The window's edge, a line of nodes in the plate where it rests on the support.
Point(11) = {x0, y0, 0, lc}; Point(12) = {x1, y0, 0, lc}; Point(13) = {x1, y1, 0, lc}; Point(14) = {x0, y1, 0, lc};
Line(11) = {11, 12}; Line(12) = {12, 13}; Line(13) = {13, 14}; Line(14) = {14, 11};
Curve{11, 12, 13, 14} In Surface{1};
// The four clamp tips and the centre (the impact point), nodes of the mesh.
Point(21) = {a / 2 - 0.050, b / 2 - 0.04375, 0, lc}; Point(22) = {a / 2 + 0.050, b / 2 - 0.04375, 0, lc};
Point(23) = {a / 2 + 0.050, b / 2 + 0.04375, 0, lc}; Point(24) = {a / 2 - 0.050, b / 2 + 0.04375, 0, lc};
Point(25) = {a / 2, b / 2, 0, lc};
Point{21, 22, 23, 24, 25} In Surface{1};
Physical Curve("edges") = {1, 2, 3, 4};
Physical Curve("window") = {11, 12, 13, 14};
Physical Point("clamps") = {21, 22, 23, 24};
Physical Point("centre") = {25};
Physical Surface("plate") = {1};
