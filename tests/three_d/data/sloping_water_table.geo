// The water table of sloping_water_table.csv as a Gmsh surface, for
// Water/Piezometric surface file: the plane
// z = 25.6 + 0.2 (x - 12) + 0.05 (y - 20) over 50 m x 40 m, in two
// surfaces that Gmsh meshes into triangles, which the program samples on
// a grid.
lc = 8;
Point(1) = {0, 0, 22.2, lc};
Point(2) = {20, 0, 26.2, lc};
Point(3) = {50, 0, 32.2, lc};
Point(4) = {0, 40, 24.2, lc};
Point(5) = {20, 40, 28.2, lc};
Point(6) = {50, 40, 34.2, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {4, 5};
Line(4) = {5, 6};
Line(5) = {1, 4};
Line(6) = {2, 5};
Line(7) = {3, 6};
Curve Loop(1) = {1, 6, -3, -5};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 7, -4, -6};
Plane Surface(2) = {2};
