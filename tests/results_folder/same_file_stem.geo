// SPDX-License-Identifier: LGPL-2.1-or-later
// Two unit squares side by side on a fixed base line, named so that both
// names give the file stem 'rock_1' ('rock/1' and 'rock 1').
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {2, 0, 0};
Point(4) = {0, 1, 0};
Point(5) = {1, 1, 0};
Point(6) = {2, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 6};
Line(4) = {6, 5};
Line(5) = {5, 4};
Line(6) = {4, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Transfinite Curve{:} = 3;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Surface("rock/1") = {1};
Physical Surface("rock 1") = {2};
Physical Curve("joint") = {7};
Physical Curve("bottom") = {1, 2};
