// SPDX-License-Identifier: LGPL-2.1-or-later
// A .geo file that includes itself: Gmsh read it until it ran out of file
// handles and said "Unable to open file".
Include "includes_itself.geo";
Point(1) = {0, 0, 0};
