// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Soil layers and strength along the surface (issue 17): the slope
// generator gives every cell the material of its layer, and an interface
// with Strength = material gives the same node-pair strengths, and the same
// safety factor, as the same mesh with one interface per layer segment and
// each segment's c and phi given by hand.
#include "layered_cases.h"
#include "test_helpers.h"

#include <fdem/analyses/limit_equilibrium_model.h>
#include <fdem/geometry/cases/slope.h>
#include <fdem/geometry/gmsh_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>

using namespace fdem;
using dealii::Point;
using namespace fdem::test_support::layered_cases;

namespace
{
  /**
   * The same model as @p p, with its sliding surface split by hand into one
   * interface per material on the side of the sliding mass, each with its
   * material's c and phi given (Strength = given), read from a mesh file.
   */
  parameters::Parameters
  interfaces_by_hand(const parameters::Parameters       &p,
                     const geometry::MeshDescription<2> &mesh)
  {
    geometry::MeshDescription<2> split  = mesh;
    const auto                  &groups = split.face_group_names;
    const unsigned int           surface =
      std::find(groups.begin(), groups.end(), "sliding surface") -
      groups.begin();
    const unsigned int mass = std::find(split.block_names.begin(),
                                        split.block_names.end(),
                                        "sliding mass") -
                              split.block_names.begin();
    std::map<unsigned int, std::vector<unsigned int>> cells_at_vertex;
    for (unsigned int c = 0; c < split.cells.size(); ++c)
      if (split.cells[c].material_id == mass)
        for (const unsigned int v : split.cells[c].vertices)
          cells_at_vertex[v].push_back(c);
    std::map<unsigned int, unsigned int> group_of_material;
    auto                                 parameters = p;
    parameters.interface_names.clear();
    for (auto &face : split.faces)
      if (face.boundary_id == surface)
        {
          // The cell of the sliding mass that has both vertices of the face.
          unsigned int cell = dealii::numbers::invalid_unsigned_int;
          for (const unsigned int c : cells_at_vertex[face.vertices[0]])
            for (const unsigned int d : cells_at_vertex[face.vertices[1]])
              if (c == d)
                cell = c;
          EXPECT_NE(cell, dealii::numbers::invalid_unsigned_int);
          const unsigned int m = split.cell_materials.at(cell);
          if (group_of_material.count(m) == 0)
            {
              const std::string name = "surface in " + split.material_names[m];
              group_of_material[m]   = split.face_group_names.size();
              split.face_group_names.push_back(name);
              parameters.interface_names.push_back(name);
              auto        interface = p.interfaces.at("sliding surface");
              const auto &material  = p.materials.at(split.material_names[m]);
              interface.strength_from_material = false;
              interface.cohesion               = material.cohesion;
              interface.friction_angle         = material.friction_angle;
              parameters.interfaces[name]      = interface;
            }
          face.boundary_id = group_of_material[m];
        }
    EXPECT_GE(group_of_material.size(), 2u)
      << "the surface should cross a layer boundary";
    const std::string file = p.output.directory + "/by_hand.msh";
    geometry::write_gmsh_file(split, file);
    parameters.geometry.source =
      parameters::GeometryParameters::Source::mesh_file;
    parameters.geometry.mesh_file = file;
    parameters.output.directory += "/by_hand";
    return parameters;
  }

  /**
   * Runs @p p with Strength = material and by hand; compares the pair
   * strengths at full strength (the same pairs, found by position) and
   * returns the two safety factors.
   */
  struct Comparison
  {
    double K_material = 0, K_by_hand = 0;
    /** Full-strength cohesive force of the pairs open at the limit (material
     * run). */
    double open_cohesion = 0;
  };

  Comparison
  compare_with_hand(const parameters::Parameters &p,
                    const bool                    same_friction_angle)
  {
    const auto material = run(p);
    const auto by_hand =
      run(interfaces_by_hand(p, material->model().get_mesh()));
    const auto strengths_material = material->model().pair_strengths(1.0);
    const auto strengths_by_hand  = by_hand->model().pair_strengths(1.0);
    // The pairs of the hand model by position; junction nodes of two
    // segments are paired in the first and marked.
    std::map<std::pair<double, double>, std::pair<unsigned int, bool>>
                                                    by_position;
    std::set<std::pair<unsigned int, unsigned int>> shared;
    for (const auto &interface : by_hand->model().get_interfaces())
      for (const auto &node : interface.shared_nodes)
        shared.emplace(node.interface, node.pair);
    unsigned int p_hand = 0;
    for (unsigned int i = 0; i < by_hand->model().get_interfaces().size(); ++i)
      for (unsigned int k = 0;
           k < by_hand->model().get_interfaces()[i].pairs.size();
           ++k, ++p_hand)
        {
          const auto &x =
            by_hand->model().get_interfaces()[i].pairs[k].position_J;
          by_position[{std::round(x[0] * 1e6), std::round(x[1] * 1e6)}] = {
            p_hand, shared.count({i, k}) == 1};
        }
    EXPECT_EQ(by_position.size(), strengths_material.size());
    unsigned int n_junctions  = 0;
    double       max_cohesion = 0, cohesion_error = 0, friction_error = 0;
    for (unsigned int k = 0;
         k < material->model().get_interfaces()[0].pairs.size();
         ++k)
      {
        const auto &x =
          material->model().get_interfaces()[0].pairs[k].position_J;
        const auto it =
          by_position.find({std::round(x[0] * 1e6), std::round(x[1] * 1e6)});
        EXPECT_TRUE(it != by_position.end());
        if (it == by_position.end())
          continue;
        const auto &a = strengths_material[k];
        const auto &b = strengths_by_hand[it->second.first];
        max_cohesion  = std::max(max_cohesion, std::abs(b.cohesion_force));
        cohesion_error =
          std::max(cohesion_error,
                   std::abs(a.cohesion_force - b.cohesion_force));
        n_junctions += it->second.second;
        // At a junction the hand model keeps the first segment's tan(phi),
        // Strength = material the area-weighted mean: equal only if the
        // friction angles are.
        if (!it->second.second || same_friction_angle)
          friction_error =
            std::max(friction_error,
                     std::abs(a.friction_coefficient - b.friction_coefficient));
      }
    EXPECT_GE(n_junctions, 1u);
    // The same faces and shape functions on the same mesh: round-off only.
    EXPECT_LT(cohesion_error, 1e-12 * max_cohesion);
    EXPECT_LT(friction_error, 1e-14);
    std::cout << "  K material " << std::setprecision(12)
              << material->results().safety_factor.safety_factor << ", by hand "
              << by_hand->results().safety_factor.safety_factor << "; "
              << n_junctions << " junction pairs" << std::endl;
    Comparison result{material->results().safety_factor.safety_factor,
                      by_hand->results().safety_factor.safety_factor};
    for (unsigned int k = 0; k < strengths_material.size(); ++k)
      if (material->model().get_contact_outcome().states[k].status ==
          contact::PairStatus::open)
        result.open_cohesion += strengths_material[k].cohesion_force;
    return result;
  }

  /** @p p with the named weak layer "seam" along @p line. */
  void
  add_seam(parameters::Parameters      &p,
           const double                 cohesion,
           const double                 phi,
           const std::vector<Point<2>> &line)
  {
    parameters::MaterialParameters seam;
    seam.has_strength   = true;
    seam.cohesion       = cohesion;
    seam.friction_angle = phi;
    seam.weak_layer     = line;
    p.material_names.push_back("seam");
    p.materials["seam"] = seam;
  }

} // namespace

TEST(Layers, EveryCellHasTheMaterialOfItsLayer)
{
  const auto  p     = test_support::case_parameters("layered_slope.prm");
  const auto &slope = p.geometry.slope;
  const auto  mesh  = geometry::make_slope_mesh(slope);
  ASSERT_EQ(mesh.cell_materials.size(), mesh.cells.size());
  std::set<std::pair<unsigned int, std::string>> block_materials;
  for (unsigned int c = 0; c < mesh.cells.size(); ++c)
    {
      Point<2> centre;
      for (const unsigned int v : mesh.cells[c].vertices)
        centre += mesh.vertices[v] / double(mesh.cells[c].vertices.size());
      unsigned int layer = 0;
      while (layer < slope.layer_boundaries.size() &&
             centre[1] < elevation(slope.layer_boundaries[layer], centre[0]))
        ++layer;
      ASSERT_NE(mesh.cell_materials[c], mesh.no_material);
      EXPECT_EQ(mesh.material_names[mesh.cell_materials[c]],
                slope.layers[layer])
        << "cell at " << centre;
      block_materials.emplace(mesh.cells[c].material_id, slope.layers[layer]);
    }
  // The sliding mass holds fill and clay, the foundation all three.
  EXPECT_EQ(block_materials.size(), 5u);
}

// A planar sliding surface (10,25) -> (46,35) through three layer segments
// (fill, clay, fill), different cohesions and one friction angle, no water:
// a rigid translation is a mechanism, so at the limit every pair slips and
// statics gives K = (sum_i c_i L_i - C_open + tan(phi) W cos(a)) / (W sin(a)),
// C_open the cohesion of the pairs that open (the last at the crest), with
// the segment lengths L_i from the line and the layer boundary (not the
// mesh) and the weight W of the sliding mass from its load vector. The
// model with one interface per segment given by hand is the same discrete
// problem (the surface is straight, so a junction node has the same normal
// in both): K and the pair strengths agree to round-off.
TEST(Layers, MaterialStrengthEqualsOneInterfacePerLayerByHand)
{
  const auto p = layered_plane(25);
  const auto [K_material, K_by_hand, open_cohesion] =
    compare_with_hand(p, true);
  EXPECT_NEAR(K_material, K_by_hand, 1e-9 * K_by_hand);

  // The closed form, with the lengths where the plane crosses the
  // boundary's segments (10,24)-(30,31) and (30,31)-(50,33).
  const Point<2> start(10, 25),
    in(plane_crossing(Point<2>(10, 24), Point<2>(30, 31))),
    out(plane_crossing(Point<2>(30, 31), Point<2>(50, 33))), end(46, 35);
  const double L_fill = start.distance(in) + out.distance(end),
               L_clay = in.distance(out);
  std::ostringstream log;
  Model<2>           model(p, log);
  model.make_geometry();
  model.setup_blocks();
  model.assemble_and_factorize();
  const auto &mass = *model.get_blocks()[0];
  ASSERT_EQ(mass.name, "sliding mass");
  const double W     = weight_of(mass);
  const double alpha = std::atan(plane_slope);
  const double K_statics =
    (p.materials.at("fill").cohesion * L_fill +
     p.materials.at("clay").cohesion * L_clay - open_cohesion +
     std::tan(25 * dealii::numbers::PI / 180) * W * std::cos(alpha)) /
    (W * std::sin(alpha));
  std::cout << "  L_fill " << L_fill << ", L_clay " << L_clay << ", W " << W
            << ", open pairs' cohesion " << open_cohesion << ", K from statics "
            << std::setprecision(12) << K_statics << std::endl;
  // The iteration stops at Tolerance = 1e-11; the rest is round-off.
  EXPECT_NEAR(K_material, K_statics, 1e-9 * K_statics);
}

// Different friction angles: all pair strengths agree but at the nodes
// where two layers meet on the surface, which the hand model gives the
// first segment's tan(phi) and Strength = material the mean over the node's
// two half-faces; K moves by what those one or two nodes carry.
TEST(Layers, MaterialFrictionDiffersOnlyAtLayerJunctions)
{
  const auto [K_material, K_by_hand, open_cohesion] =
    compare_with_hand(layered(2.0), false);
  (void)open_cohesion;
  EXPECT_NEAR(K_material, K_by_hand, 2e-2 * K_by_hand);
}

// A named weak layer (Materials/seam/Weak layer) along the test plane from
// its toe to the surface vertex (28, 30), the rest of the plane through the
// layers (clay, then fill). One friction angle everywhere and a rigid
// translation as the mechanism: every pair slips at the limit, so statics
// gives K = (int c dGamma - C_open + tan(phi) W cos(a)) / (W sin(a)), with
// the seam's c along it and the layers' elsewhere (Strength = material
// weights each node's c by its shape function, so the pairs' cohesive
// forces sum to the integral exactly). Limit equilibrium slices the same
// section with a slice boundary at the vertex, opens nothing, and gives it
// with C_open = 0 for the same W (straight-sided cells: the FE weight is
// exact). Tolerances: the iteration's 1e-11 and the root search's 1e-14,
// with margin for round-off.
TEST(Layers, WeakLayerAlongPartOfThePlaneGivesTheClosedForm)
{
  const double   phi = 25, c_seam = 1;
  auto           p = layered_plane(phi);
  const Point<2> start(10, 25), P(28, 30), end(46, 35);
  add_seam(p, c_seam, phi, {Point<2>(0, 25 - 10 * plane_slope), P});
  p.geometry.slope.sliding_surface_polyline = {start, P, end};
  p.limit_equilibrium.n_slices              = 40;
  const Point<2> in  = plane_crossing(Point<2>(10, 24), Point<2>(30, 31)),
                 out = plane_crossing(Point<2>(30, 31), Point<2>(50, 33));
  ASSERT_LT(in[0], P[0]);
  ASSERT_LT(P[0], out[0]);
  const double cohesion_integral =
    c_seam * start.distance(P) +
    p.materials.at("clay").cohesion * P.distance(out) +
    p.materials.at("fill").cohesion * out.distance(end);

  const auto   material   = run(p);
  const auto  &model      = material->model();
  const double K          = material->results().safety_factor.safety_factor;
  const double W          = weight_of(*model.get_blocks()[0]);
  const auto   strengths  = model.pair_strengths(1.0);
  double       seam_force = 0, seam_area = 0;
  for (unsigned int k = 0; k < strengths.size(); ++k)
    {
      const auto &pair = model.get_interfaces()[0].pairs[k];
      if (pair.position_J[0] < P[0] - 1e-6) // inside the seam's part
        {
          seam_force += strengths[k].cohesion_force;
          seam_area += pair.area;
        }
    }
  // Each pair inside the seam's part has the seam's c over its area.
  EXPECT_NEAR(seam_force, c_seam * seam_area, 1e-12 * seam_force);
  const double alpha       = std::atan(plane_slope);
  const auto   closed_form = [&](const double open) {
    return (cohesion_integral - open +
            std::tan(phi * dealii::numbers::PI / 180) * W * std::cos(alpha)) /
           (W * std::sin(alpha));
  };
  const double open = open_cohesion(model);
  std::cout << "  int c dGamma " << cohesion_integral << ", W " << W
            << ", open pairs' cohesion " << open << ", K "
            << std::setprecision(12) << K << ", from statics "
            << closed_form(open) << std::endl;
  EXPECT_NEAR(K, closed_form(open), 1e-9 * K);

  expect_every_method_gives(p, closed_form(0), 1e-9);
}

// The seam along the whole test plane with a friction angle of its own
// (15 degrees against the layers' 25): every pair takes the seam's c and
// phi, so K is the planar closed form with them alone, whatever the layers
// are; the iteration's tolerance as above.
TEST(Layers, WeakLayerAlongTheWholePlaneTakesItsFrictionAngle)
{
  const double   c_seam = 2, phi_seam = 15;
  auto           p = layered_plane(25);
  const Point<2> start(10, 25), end(46, 35);
  add_seam(p,
           c_seam,
           phi_seam,
           {Point<2>(0, 25 - 10 * plane_slope),
            Point<2>(50, 25 + 40 * plane_slope)});
  const auto   seam  = run(p);
  const auto  &model = seam->model();
  const double K     = seam->results().safety_factor.safety_factor;
  const double W     = weight_of(*model.get_blocks()[0]);
  const double alpha = std::atan(plane_slope);
  const double K_statics =
    (c_seam * start.distance(end) - open_cohesion(model) +
     std::tan(phi_seam * dealii::numbers::PI / 180) * W * std::cos(alpha)) /
    (W * std::sin(alpha));
  std::cout << "  K " << std::setprecision(12) << K << ", from statics "
            << K_statics << std::endl;
  EXPECT_NEAR(K, K_statics, 1e-9 * K);

  // The seam is given in the input's coordinates and moves with the mesh:
  // the model translated and rotated by -40 degrees, gravity with it, gives
  // the same K (the invariance of SafetyFactor.InvariantUnderTranslation-
  // RotationAndUnits; units and a common stiffness:
  // invariance.weak_layer_slope).
  auto moved                    = p;
  moved.geometry.translation    = {1000, -250};
  moved.geometry.rotation_angle = -40;
  moved.loads.gravity_direction = {-std::sin(40 * dealii::numbers::PI / 180),
                                   -std::cos(40 * dealii::numbers::PI / 180)};
  moved.output.directory += "/moved";
  EXPECT_NEAR(run(moved)->results().safety_factor.safety_factor, K, 1e-8 * K);
}
