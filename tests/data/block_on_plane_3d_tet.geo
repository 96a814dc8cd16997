// tests/data/block_on_plane_3d.geo with tetrahedra: the same 10 x 6 x 5
// block on a 16 x 12 x 5 slab, the structured grid's quadrilaterals split
// into triangles and its extruded prisms into tetrahedra (no Recombine),
// conforming across the block's footprint.
xs[] = {-3, 0, 10, 13};
ys[] = {-3, 0, 6, 9};
nx[] = {2, 5, 2};
ny[] = {2, 3, 2};
For j In {0:3}
  For i In {0:3}
    Point(1 + i + 4 * j) = {xs[i], ys[j], 0};
  EndFor
EndFor
// Lines along x, then along y.
For j In {0:3}
  For i In {0:2}
    Line(100 + i + 3 * j) = {1 + i + 4 * j, 2 + i + 4 * j};
    Transfinite Curve{100 + i + 3 * j} = nx[i] + 1;
  EndFor
EndFor
For j In {0:2}
  For i In {0:3}
    Line(200 + i + 4 * j) = {1 + i + 4 * j, 1 + i + 4 * (j + 1)};
    Transfinite Curve{200 + i + 4 * j} = ny[j] + 1;
  EndFor
EndFor
For j In {0:2}
  For i In {0:2}
    Curve Loop(300 + i + 3 * j) = {100 + i + 3 * j, 201 + i + 4 * j, -(100 + i + 3 * (j + 1)), -(200 + i + 4 * j)};
    Plane Surface(300 + i + 3 * j) = {300 + i + 3 * j};
    Transfinite Surface{300 + i + 3 * j};
  EndFor
EndFor
block[] = Extrude{0, 0, 5}{Surface{304}; Layers{5};};
base[] = {};
slab[] = {};
For k In {0:8}
  out[] = Extrude{0, 0, -5}{Surface{300 + k}; Layers{3};};
  base[] += out[0];
  slab[] += out[1];
EndFor
Physical Volume("block") = {block[1]};
Physical Volume("foundation") = {slab[]};
Physical Surface("sliding surface") = {304};
Physical Surface("foundation base") = {base[]};
