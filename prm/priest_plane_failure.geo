// Plane failure with a water-filled tension crack (Priest 1993; Hoek & Bray):
// slope 30 m high, face at 60 degrees from the toe (0,0) to the crest edge
// (17.321, 30), flat crest beyond; failure plane dipping 30 degrees from the
// toe; vertical tension crack 15 m deep at x = 25.981. Units: m.
// The crack is a face between the two blocks that is not an interface: the
// program gives each block its own nodes there, so it is free on both sides.
// A point at the water level (y = 18.75) puts a node at the kink of the
// crack's water pressure.
h = 2.0;  // element size before the one subdivision into quadrilaterals
Point(1) = {0, 0, 0, h};                 // toe
Point(2) = {17.320508075688775, 30, 0, h};  // crest edge
Point(3) = {25.980762113533160, 30, 0, h};  // top of the tension crack
Point(4) = {25.980762113533160, 18.75, 0, h}; // water level in the crack
Point(5) = {25.980762113533160, 15, 0, h};  // bottom of the crack, on the plane
Point(6) = {-20, 0, 0, h};
Point(7) = {-20, -20, 0, h};
Point(8) = {60, -20, 0, h};
Point(9) = {60, 30, 0, h};

Line(1) = {1, 2};   // slope face
Line(2) = {2, 3};   // crest over the block
Line(3) = {3, 4};   // crack, above the water
Line(4) = {4, 5};   // crack, under water
Line(5) = {5, 1};   // failure plane
Line(6) = {6, 1};   // floor in front of the toe
Line(7) = {7, 6};
Line(8) = {7, 8};
Line(9) = {8, 9};
Line(10) = {9, 3};  // crest behind the crack

Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Curve Loop(2) = {6, -5, -4, -3, -10, -9, -8, 7};
Plane Surface(2) = {2};

Physical Surface("block") = {1};
Physical Surface("rock") = {2};
Physical Curve("failure plane") = {5};
Physical Curve("tension crack") = {3, 4};
Physical Curve("ground") = {1, 2, 6, 10};
Physical Curve("base") = {8};
Physical Curve("sides") = {7, 9};

Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1;
