// A ground surface that does not cover the rectangle of its extent: a
// triangle in plan.
Point(1) = {0, 0, 25, 10};
Point(2) = {50, 0, 35, 10};
Point(3) = {0, 40, 30, 10};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
