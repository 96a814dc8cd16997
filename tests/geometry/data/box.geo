// SPDX-License-Identifier: LGPL-2.1-or-later
// A unit cube of 2 x 2 x 2 hexahedra (extruded quadrilaterals).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{:} = 3;
Transfinite Surface{1};
Recombine Surface{1};
top[] = Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; };
Physical Volume("box") = {top[1]};
Physical Surface("base") = {1};
Physical Surface("top") = {top[0]};
