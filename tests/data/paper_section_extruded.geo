// The paper's section (paper_section.geo) extruded along z over the width w
// in n layers of hexahedra: the plane-strain model of
// tests/three_d/plane_strain.prm (gravity along -y). Its section's mesh is
// paper_section_2d.geo's, so the 3D and 2D models differ by the third
// dimension only. h: element size (m); w: width (m); n: layers; planar = 1:
// the circle's chord (plane_section_extruded.geo).
DefineConstant[h = 2, w = 4, n = 2, planar = 0];
Include "paper_section.geo";
mass[] = Extrude {0, 0, w} {Surface{1}; Layers{n}; Recombine;};
foundation[] = Extrude {0, 0, w} {Surface{2}; Layers{n}; Recombine;};
// Extrude returns the top surface, the volume, then one face per curve of
// the surface's loop in its order: {4, 5, sliding[]} and {1, 2, 3,
// -sliding[] reversed, 6, 7, 8}, with s = #sliding[] curves of the
// sliding surface.
s = #sliding[];
Physical Volume("sliding mass") = {mass[1]};
Physical Volume("foundation") = {foundation[1]};
Physical Surface("sliding surface") = {mass[{4:3 + s}]};
Physical Surface("ground") = {mass[2], mass[3], foundation[4], foundation[5 + s], foundation[6 + s]};
Physical Surface("left") = {foundation[7 + s]};
Physical Surface("right") = {foundation[3]};
Physical Surface("bottom") = {foundation[2]};
Physical Surface("ends") = {1, 2, mass[0], foundation[0]};
