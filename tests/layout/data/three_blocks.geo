// Two-wedge slide: a sliding mass cut in two by a vertical interslice
// interface over a base block; the three blocks meet at (20, 10).
// Sliding surface: toe (5, 7.355) -> (20, 10) at 10 degrees, then
// (20, 10) -> (35, 25) at 45 degrees. Slope face from (5, 7.355) to the
// crest (28, 25). Units: m.
h = 1.0;
Point(1) = {0, 0, 0, h}; Point(2) = {45, 0, 0, h}; Point(3) = {45, 25, 0, h};
Point(4) = {35, 25, 0, h};        // top of the sliding surface
Point(5) = {20, 10, 0, h};        // the point where the three blocks meet
Point(6) = {5, 7.355, 0, h};      // toe
Point(7) = {0, 7.355, 0, h};
Point(8) = {28, 25, 0, h};        // crest edge
Point(9) = {20, 18.8620, 0, h};   // top of the interslice, on the slope face
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 1};
Line(8) = {4, 8}; Line(9) = {8, 9}; Line(10) = {9, 5}; Line(11) = {9, 6};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7}; Plane Surface(1) = {1};
Curve Loop(2) = {-4, 8, 9, 10}; Plane Surface(2) = {2};
Curve Loop(3) = {-5, -10, 11}; Plane Surface(3) = {3};
Physical Surface("base") = {1};
Physical Surface("upper wedge") = {2};
Physical Surface("lower wedge") = {3};
Physical Curve("upper sliding") = {4};
Physical Curve("lower sliding") = {5};
Physical Curve("interslice") = {10};
Physical Curve("bottom") = {1};
Physical Curve("sides") = {2, 7};
Mesh.Algorithm = 6; Mesh.RecombineAll = 1; Mesh.SubdivisionAlgorithm = 1;
