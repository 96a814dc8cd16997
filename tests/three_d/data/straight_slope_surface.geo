// The ground of tests/three_d/slope_3d.prm (the paper's section: toe at
// z = 25 up to x = 10, the face rising 1:2 to the crest at x = 30, z = 35,
// 40 m along y) as a Gmsh surface of three planes, for
// Geometry/Slope 3D/Terrain file: Gmsh meshes it into triangles, which the
// program samples on a grid.
lc = 5;
Point(1) = {0, 0, 25, lc};
Point(2) = {10, 0, 25, lc};
Point(3) = {30, 0, 35, lc};
Point(4) = {50, 0, 35, lc};
Point(5) = {0, 40, 25, lc};
Point(6) = {10, 40, 25, lc};
Point(7) = {30, 40, 35, lc};
Point(8) = {50, 40, 35, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {5, 6};
Line(5) = {6, 7};
Line(6) = {7, 8};
Line(7) = {1, 5};
Line(8) = {2, 6};
Line(9) = {3, 7};
Line(10) = {4, 8};
Curve Loop(1) = {1, 8, -4, -7};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 9, -5, -8};
Plane Surface(2) = {2};
Curve Loop(3) = {3, 10, -6, -9};
Plane Surface(3) = {3};
