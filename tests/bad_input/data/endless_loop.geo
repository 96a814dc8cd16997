// SPDX-License-Identifier: LGPL-2.1-or-later
// A loop that does not end in any reasonable time: Gmsh's parser spun forever.
x = 0;
For i In {1:1e12}
  x = x + 1;
EndFor
Point(1) = {0, 0, 0};
