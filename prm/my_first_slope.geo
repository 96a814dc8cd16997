// My first slope (doc/build_your_own_model.md): a slope 15 m high in three
// horizontal soil layers, cut by a circular sliding surface. Units: m.
//
//   ground:  flat at y = 10 up to the toe (15, 10), face up to the crest
//            edge (35, 25), flat crest at y = 25; model from x = 0 to 60,
//            base at y = 0
//   layers:  sand below y = 12, clay from 12 to 18, fill above 18
//   surface: a circle of centre (20, 40) and radius 32, from where it
//            leaves the ground in front of the toe (A, y = 10) to where it
//            meets the crest (B, y = 25)
//
// Every place where two of these lines cross is a point of its own, so that
// each surface below is bounded by whole curves and the blocks and layers
// share their nodes.
h = 2.0;  // element size before the one subdivision into quadrilaterals

xc = 20; yc = 40; R = 32;                   // the circle
Point(1)  = {0, 0, 0, h};                   // base, left
Point(2)  = {60, 0, 0, h};                  // base, right
Point(3)  = {60, 25, 0, h};                 // crest, right
Point(4)  = {xc + Sqrt(R^2 - (25 - yc)^2), 25, 0, h};  // B: circle meets the crest
Point(5)  = {35, 25, 0, h};                 // crest edge
Point(6)  = {15 + (18 - 10) * 20 / 15, 18, 0, h};      // face meets y = 18
Point(7)  = {15 + (12 - 10) * 20 / 15, 12, 0, h};      // face meets y = 12
Point(8)  = {15, 10, 0, h};                 // toe
Point(9)  = {xc - Sqrt(R^2 - (10 - yc)^2), 10, 0, h};  // A: circle leaves the ground
Point(10) = {0, 10, 0, h};                  // ground, left
Point(13) = {xc + Sqrt(R^2 - (12 - yc)^2), 12, 0, h};  // circle crosses y = 12
Point(14) = {xc + Sqrt(R^2 - (18 - yc)^2), 18, 0, h};  // circle crosses y = 18
Point(15) = {60, 12, 0, h};                 // right side at y = 12
Point(16) = {60, 18, 0, h};                 // right side at y = 18
Point(20) = {xc, yc, 0, h};                 // centre of the circle (not meshed)

// The ground, toe to crest.
Line(1) = {10, 9};    // in front of the toe, outside the sliding mass
Line(2) = {9, 8};     // in front of the toe, on the sliding mass
Line(3) = {8, 7};     // slope face, in the sand
Line(4) = {7, 6};     // slope face, in the clay
Line(5) = {6, 5};     // slope face, in the fill
Line(6) = {5, 4};     // crest, on the sliding mass
Line(7) = {4, 3};     // crest, behind the sliding surface
// The sliding surface: three arcs (each < 180 degrees), cut by the layers.
Circle(8)  = {9, 20, 13};
Circle(9)  = {13, 20, 14};
Circle(10) = {14, 20, 4};
// The layer boundaries, cut by the sliding surface.
Line(11) = {7, 13};   // y = 12 in the sliding mass
Line(12) = {13, 15};  // y = 12 in the foundation
Line(13) = {6, 14};   // y = 18 in the sliding mass
Line(14) = {14, 16};  // y = 18 in the foundation
// The model's sides and base.
Line(15) = {1, 2};    // base
Line(16) = {2, 15};   // right side, sand
Line(17) = {15, 16};  // right side, clay
Line(18) = {16, 3};   // right side, fill
Line(19) = {1, 10};   // left side (sand only: the ground is at y = 10)

// Six surfaces: each block (sliding mass, foundation) in each layer.
Curve Loop(1) = {2, 3, 11, -8};          Plane Surface(1) = {1};  // mass, sand
Curve Loop(2) = {4, 13, -9, -11};        Plane Surface(2) = {2};  // mass, clay
Curve Loop(3) = {5, 6, -10, -13};        Plane Surface(3) = {3};  // mass, fill
Curve Loop(4) = {15, 16, -12, -8, -1, -19}; Plane Surface(4) = {4};  // foundation, sand
Curve Loop(5) = {12, 17, -14, -9};       Plane Surface(5) = {5};  // foundation, clay
Curve Loop(6) = {14, 18, -7, -10};       Plane Surface(6) = {6};  // foundation, fill

// Blocks: physical groups of dimension 2 named in the .prm's Blocks/Names.
Physical Surface("sliding mass") = {1, 2, 3};
Physical Surface("foundation")   = {4, 5, 6};
// Material regions: physical groups of dimension 2 named in Materials/Names.
// They overlap the blocks: every cell lies in one block and one layer.
Physical Surface("sand") = {1, 4};
Physical Surface("clay") = {2, 5};
Physical Surface("fill") = {3, 6};
// The interface: a physical group of dimension 1 between the two blocks,
// named in Interfaces/Names.
Physical Curve("sliding surface") = {8, 9, 10};
// Boundary parts: physical groups of dimension 1 named in Boundaries/Names.
Physical Curve("bottom") = {15};
Physical Curve("left")   = {19};
Physical Curve("right")  = {16, 17, 18};
// Not listed in the .prm, so free (no load, no support): named only so that
// it can be found in the mesh.
Physical Curve("ground") = {1, 2, 3, 4, 5, 6, 7};

// Quadrilaterals: triangles recombined, then each split once.
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1;
