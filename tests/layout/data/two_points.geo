// The interface's face group holds the block's curved bottom and the
// base's flat top: the two sides meet only at their end points.
h = 0.5;
Point(1) = {0, 0, 0, h}; Point(2) = {20, 0, 0, h}; Point(3) = {20, 5, 0, h};
Point(4) = {15, 5, 0, h}; Point(6) = {5, 5, 0, h};
Point(7) = {0, 5, 0, h}; Point(8) = {15, 8, 0, h}; Point(9) = {5, 8, 0, h};
Point(10) = {10, 0, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 6};
Line(6) = {6, 7}; Line(7) = {7, 1};
Line(8) = {4, 8}; Line(9) = {8, 9}; Line(10) = {9, 6};
Circle(11) = {6, 10, 4};
Curve Loop(1) = {1, 2, 3, 4, 6, 7}; Plane Surface(1) = {1};
Curve Loop(2) = {11, 8, 9, 10}; Plane Surface(2) = {2};
Physical Surface("base") = {1};
Physical Surface("block") = {2};
Physical Curve("contact") = {4, 11};
Physical Curve("bottom") = {1};
Physical Curve("sides") = {2, 7};
Mesh.Algorithm = 6; Mesh.RecombineAll = 1; Mesh.SubdivisionAlgorithm = 1;
