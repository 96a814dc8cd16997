// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Gmsh alone: a rectangle cut by a disk and by a layer line, as the slope
// generator cuts its model, meshed, then finalized. Whatever LeakSanitizer
// reports here is Gmsh's own (tests/sanitizers/lsan.supp).
#include <gmsh.h>

#include <utility>
#include <vector>

int
main()
{
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("m");
  const int        domain = gmsh::model::occ::addRectangle(0, 0, 0, 50, 30);
  const int        disk   = gmsh::model::occ::addDisk(30, 40, 0, 25, 25);
  gmsh::vectorpair mass, pieces;
  std::vector<gmsh::vectorpair> origin;
  gmsh::model::occ::intersect(
    {{2, domain}}, {{2, disk}}, mass, origin, -1, false, true);
  gmsh::model::occ::fragment({{2, domain}}, mass, pieces, origin);
  gmsh::model::occ::synchronize();
  // A layer boundary: a line fragmenting the pieces.
  const int a        = gmsh::model::occ::addPoint(-1, 20, 0),
            b        = gmsh::model::occ::addPoint(51, 22, 0);
  const int        l = gmsh::model::occ::addLine(a, b);
  gmsh::vectorpair all;
  gmsh::model::getEntities(all, 2);
  gmsh::model::occ::fragment(all, {{1, l}}, pieces, origin);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 2.0);
  gmsh::model::mesh::generate(2);
  gmsh::finalize();

  // The 3D generator: a section extruded along y, cut by a sphere, meshed.
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("m3");
  std::vector<int> points, lines;
  for (const auto &[x, z] : std::vector<std::pair<double, double>>{
         {0, 0}, {30, 0}, {30, 20}, {15, 20}, {5, 10}, {0, 10}})
    points.push_back(gmsh::model::occ::addPoint(x, 0, z));
  for (unsigned int i = 0; i < points.size(); ++i)
    lines.push_back(
      gmsh::model::occ::addLine(points[i], points[(i + 1) % points.size()]));
  const int face =
    gmsh::model::occ::addPlaneSurface({gmsh::model::occ::addCurveLoop(lines)});
  gmsh::vectorpair extruded;
  gmsh::model::occ::extrude({{2, face}}, 0, 20, 0, extruded);
  const int        ball = gmsh::model::occ::addSphere(15, 10, 25, 18);
  gmsh::vectorpair solids;
  for (const auto &dim_tag : extruded)
    if (dim_tag.first == 3)
      solids.push_back(dim_tag);
  gmsh::model::occ::fragment(solids, {{3, ball}}, pieces, origin);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 4.0);
  gmsh::model::mesh::generate(3);
  gmsh::finalize();
  return 0;
}
