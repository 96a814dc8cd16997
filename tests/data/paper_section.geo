// The section of the paper's slope (prm/paper_slope.prm; Liu, Li, Zhao & Hu
// 2012, Fig. 4) in the plane z = 0, x to the right, y up: ground (0,25) ->
// (10,25) toe -> (30,35) crest edge -> (50,35), base at y = 20, the circular
// sliding surface of centre (19.61, 46.32) and radius 21.32 (m), or with
// planar = 1 its chord, a plane (19.2 degrees). Geometry and mesh options
// only: paper_section_2d.geo and paper_section_extruded.geo include it and
// name the groups. h is the element size (m). The circle meets the slope
// face at (12.4654736, 26.2327368) and the crest at (37.6765437, 35); its
// lowest point (19.61, 25) splits the arc in two, each less than half a
// turn.
DefineConstant[h = 2, planar = 0];
xc = 19.61; yc = 46.32; r = 21.32;
xa = 12.465473610075865; ya = 25 + (xa - 10) / 2;
xe = xc + Sqrt(r^2 - (35 - yc)^2);
Point(1) = {0, 20, 0, h};
Point(2) = {50, 20, 0, h};
Point(3) = {50, 35, 0, h};
Point(4) = {xe, 35, 0, h};
Point(5) = {30, 35, 0, h};
Point(6) = {xa, ya, 0, h};
Point(7) = {10, 25, 0, h};
Point(8) = {0, 25, 0, h};
If (!planar)
  Point(9) = {xc, yc, 0, h};      // the circle's centre
  Point(10) = {xc, yc - r, 0, h}; // its lowest point
EndIf
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // ground: crest behind the sliding mass
Line(4) = {4, 5};   // ground: crest of the sliding mass
Line(5) = {5, 6};   // ground: face of the sliding mass
Line(6) = {6, 7};   // ground: face below the sliding mass
Line(7) = {7, 8};   // ground: toe
Line(8) = {8, 1};   // left
If (planar)
  Line(9) = {6, 4}; // sliding surface
  sliding[] = {9};
Else
  Circle(9) = {6, 9, 10};  // sliding surface
  Circle(10) = {10, 9, 4}; // sliding surface
  sliding[] = {9, 10};
EndIf
Curve Loop(1) = {4, 5, sliding[]};
Plane Surface(1) = {1};                     // sliding mass
Curve Loop(2) = {1, 2, 3, -sliding[{#sliding[] - 1:0:-1}], 6, 7, 8};
Plane Surface(2) = {2};                     // foundation
// Quadrilaterals only: Gmsh's Frontal-Delaunay triangles recombined by
// Blossom's full-quad algorithm (about 0.7 h). Not the slope generator's
// subdivision (gmsh_2d.cc), which Gmsh does not apply to a surface that is
// extruded: with it the 2D and the extruded sections would differ.
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 3;
Mesh.SubdivisionAlgorithm = 0;
