// the hostile-input suite: a 1e9 m plate of 1e8 m elements aborts gmsh 4.8 (SIGABRT) in its child
lc = 1e8;
Point(1) = {0, 0, 0, lc}; Point(2) = {1e9, 0, 0, lc}; Point(3) = {1e9, 0.08, 0, lc}; Point(4) = {0, 0.08, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("edges") = {1, 2, 3, 4};
Physical Surface("plate") = {1};
