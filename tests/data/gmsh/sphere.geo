SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Physical Volume("body") = {1};
Physical Surface("skin") = {1};
