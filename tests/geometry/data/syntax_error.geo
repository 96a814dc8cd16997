// SPDX-License-Identifier: LGPL-2.1-or-later
// Refers to a point that does not exist: Gmsh reports an error.
Point(1) = {0, 0, 0};
Line(1) = {1, 2};
