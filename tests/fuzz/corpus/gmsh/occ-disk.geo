SetFactory("OpenCASCADE");
Disk(1) = {0.05, 0.05, 0, 0.04};
Physical Curve("edges") = {1};
Physical Surface("plate") = {1};
