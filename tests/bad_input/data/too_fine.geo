// SPDX-License-Identifier: LGPL-2.1-or-later
// A 100 m square meshed at 1 mm: some 10^10 triangles.
lc = 0.001;
Point(1) = {0, 0, 0, lc};
Point(2) = {100, 0, 0, lc};
Point(3) = {100, 100, 0, lc};
Point(4) = {0, 100, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("rock") = {1};
Physical Curve("base") = {1};
