// The paper's section with a planar sliding surface (the circle's chord)
// extruded along z: tests/three_d/plane_strain_planar.prm.
planar = 1;
Include "paper_section_extruded.geo";
