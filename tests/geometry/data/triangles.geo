// SPDX-License-Identifier: LGPL-2.1-or-later
// A square meshed with triangles (no Recombine). The curve loop runs
// clockwise, so Gmsh's triangles do too: the reader turns them over.
Point(1) = {0, 0, 0, 0.25};
Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 1, 0, 0.25};
Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {-4, -3, -2, -1};
Plane Surface(1) = {1};
Physical Surface("rock") = {1};
