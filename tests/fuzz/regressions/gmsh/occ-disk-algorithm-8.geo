// the reliability audit: gmsh 4.8 segfaulted, and took plyimpact (and Python) with it
SetFactory("OpenCASCADE");
Disk(1) = {0.05, 0.05, 0, 0.04};
Mesh.Algorithm = 8;
Recombine Surface{1};
Physical Curve("edges") = {1};
Physical Surface("plate") = {1};
