// SPDX-License-Identifier: LGPL-2.1-or-later
// Asks for the algorithm that crashes Debian's Gmsh 4.8.4: must be rejected
// before meshing.
Point(1) = {0, 0, 0, 0.25};
Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 1, 0, 0.25};
Point(4) = {0, 1, 0, 0.25};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("rock") = {1};
Mesh.Algorithm = 8;
Mesh.RecombineAll = 1;
