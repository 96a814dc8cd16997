// The paper's section with a planar sliding surface (the circle's chord)
// as a 2D model: the reference for tests/three_d/plane_strain_planar.prm.
planar = 1;
Include "paper_section_2d.geo";
