System "touch pwned";
lc = 0.02;
Point(1) = {0, 0, 0, lc}; Point(2) = {0.1, 0, 0, lc}; Point(3) = {0.1, 0.08, 0, lc}; Point(4) = {0, 0.08, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("edges") = {1, 2, 3, 4};
Physical Surface("plate") = {1};
