// The paper's section (paper_section.geo) as a 2D model: the reference for
// tests/three_d/plane_strain.prm, meshed exactly as the extruded model's
// section (paper_section_extruded.geo). h: element size (m); planar = 1:
// the circle's chord (plane_section_2d.geo).
DefineConstant[h = 2, planar = 0];
Include "paper_section.geo";
Physical Surface("sliding mass") = {1};
Physical Surface("foundation") = {2};
Physical Curve("sliding surface") = {sliding[]};
Physical Curve("ground") = {3, 4, 5, 6, 7};
Physical Curve("left") = {8};
Physical Curve("right") = {2};
Physical Curve("bottom") = {1};
