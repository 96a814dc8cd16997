// A triangular block standing on its apex on a base: the face group holds
// the block's two lower sides and the base's top, which meet at one point.
h = 0.5;
Point(1) = {0, 0, 0, h}; Point(2) = {20, 0, 0, h}; Point(3) = {20, 5, 0, h};
Point(4) = {10, 5, 0, h}; Point(5) = {0, 5, 0, h};
Point(6) = {14, 9, 0, h}; Point(7) = {6, 9, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 1}; Line(6) = {4, 6}; Line(7) = {6, 7}; Line(8) = {7, 4};
Curve Loop(1) = {1, 2, 3, 4, 5}; Plane Surface(1) = {1};
Curve Loop(2) = {6, 7, 8}; Plane Surface(2) = {2};
Physical Surface("base") = {1};
Physical Surface("block") = {2};
Physical Curve("contact") = {3, 4, 6, 8};
Physical Curve("bottom") = {1};
Physical Curve("sides") = {2, 5};
Mesh.Algorithm = 6; Mesh.RecombineAll = 1; Mesh.SubdivisionAlgorithm = 1;
