// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Gmsh alone: a rectangle cut by a disk and by a layer line, as the slope
// generator cuts its model; its 3D section extruded and cut by a sphere;
// a layered section extruded and cut by a cylinder; each meshed, then
// finalized. Whatever LeakSanitizer
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
  // The 3D generator with layers: the sliding mass cut out of the
  // extruded section by a cylinder, then split by slabs, one per layer (an
  // extruded strip wider than the model), the slabs' rest removed.
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("m3l");
  const auto extruded_polygon =
    [](const std::vector<std::pair<double, double>> &outline) {
      std::vector<int> corners, sides;
      for (const auto &[x, z] : outline)
        corners.push_back(gmsh::model::occ::addPoint(x, -5, z));
      for (unsigned int i = 0; i < corners.size(); ++i)
        sides.push_back(
          gmsh::model::occ::addLine(corners[i],
                                    corners[(i + 1) % corners.size()]));
      gmsh::vectorpair out;
      gmsh::model::occ::extrude({{2,
                                  gmsh::model::occ::addPlaneSurface(
                                    {gmsh::model::occ::addCurveLoop(sides)})}},
                                0,
                                30,
                                0,
                                out);
      for (const auto &dim_tag : out)
        if (dim_tag.first == 3)
          return dim_tag;
      return gmsh::vectorpair::value_type{};
    };
  const auto body =
    extruded_polygon({{0, 0}, {30, 0}, {30, 20}, {15, 20}, {5, 10}, {0, 10}});
  const int roller = gmsh::model::occ::addCylinder(15, -5, 25, 0, 30, 0, 18);
  mass.clear();
  gmsh::model::occ::intersect(
    {body}, {{3, roller}}, mass, origin, -1, false, true);
  gmsh::model::occ::fragment({body}, mass, pieces, origin);
  gmsh::vectorpair volumes;
  for (const auto &dim_tag : pieces)
    volumes.push_back(dim_tag);
  const auto upper =
    extruded_polygon({{-10, 12}, {40, 13}, {40, 40}, {-10, 40}});
  const auto lower =
    extruded_polygon({{-10, -10}, {40, -10}, {40, 13}, {-10, 12}});
  gmsh::model::occ::fragment(volumes, {upper, lower}, pieces, origin);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair outside;
  for (const auto &dim_tag : pieces)
    {
      double x0, y0, z0, x1, y1, z1;
      gmsh::model::getBoundingBox(3, dim_tag.second, x0, y0, z0, x1, y1, z1);
      if (x0 < -1 || x1 > 31 || z0 < -1)
        outside.push_back(dim_tag);
    }
  gmsh::model::occ::remove(outside, true);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 4.0);
  gmsh::model::mesh::generate(3);
  gmsh::finalize();
  return 0;
}
