// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/parameters/model_parameters.h>
#include <fdem/parameters/numbers.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <utility>

namespace fdem
{
  namespace parameters
  {
    using namespace dealii;

    bool
    expression_parses(const std::string &expression,
                      const unsigned int dim,
                      const unsigned int n_components)
    {
      // muparser writes its own diagnostics to std::cerr; the caller reports
      // the error in one line instead.
      std::ostringstream quiet;
      std::streambuf    *cerr_buffer = std::cerr.rdbuf(quiet.rdbuf());
      const auto         restore     = [&]() { std::cerr.rdbuf(cerr_buffer); };
      try
        {
          // Evaluating once makes the parser report unknown names now.
          if (dim == 2)
            {
              FunctionParser<2> f(n_components);
              f.initialize("x,y", expression, {{"pi", numbers::PI}});
              f.value(Point<2>());
              restore();
              return true;
            }
          FunctionParser<3> f(n_components);
          f.initialize("x,y,z", expression, {{"pi", numbers::PI}});
          f.value(Point<3>());
          restore();
          return true;
        }
      catch (...)
        {
          restore();
          return false;
        }
    }

    std::vector<double>
    parse_vector(const std::string &text,
                 const unsigned int n_components,
                 const std::string &path)
    {
      std::vector<double> values;
      for (const std::string &item : Utilities::split_string_list(text, ','))
        {
          const std::string problem = number_problem(item);
          AssertThrow(problem.empty(), ExcMessage(path + ": " + problem + "."));
          values.push_back(finite_number(item));
        }
      AssertThrow(values.size() == n_components,
                  ExcMessage(path + ": expected " +
                             std::to_string(n_components) +
                             " comma-separated numbers, got '" + text + "'."));
      return values;
    }

    std::vector<std::array<double, 2>>
    parse_piezometric_line(const std::string &text, const std::string &path)
    {
      std::vector<std::array<double, 2>> line;
      for (const std::string &point : Utilities::split_string_list(text, ';'))
        {
          const std::vector<double> xy = parse_vector(point, 2, path);
          line.push_back({{xy[0], xy[1]}});
          AssertThrow(line.size() == 1 || xy[0] > line[line.size() - 2][0],
                      ExcMessage(path + ": the x coordinates must increase."));
        }
      AssertThrow(line.size() != 1,
                  ExcMessage(path + ": give at least two points."));
      return line;
    }

    void
    BoundaryParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Constraint",
                        "none",
                        Patterns::Selection("none|fixed|normal|plate"),
                        "Displacement constraint on this boundary part: none, "
                        "fixed (all components zero), normal (zero "
                        "displacement along the boundary normal, a roller) or "
                        "plate (the same displacement along the normal at "
                        "every node, as under a rigid loading plate; the part "
                        "must be flat and normal to a coordinate axis).");
      prm.declare_entry("Pressure",
                        "0",
                        Patterns::Anything(),
                        "Pressure on this boundary part (force/length^2), "
                        "positive when it pushes into the body, as a function "
                        "of the coordinates x, y (and z in 3D), e.g. "
                        "'9.81*max(0, 30-y)'.");
      prm.declare_entry("Traction",
                        "0",
                        Patterns::Anything(),
                        "Traction on this boundary part (force/length^2) as a "
                        "vector function of x, y (and z in 3D), components "
                        "separated by ';', e.g. '10; 0'; '0' for none.");
    }

    void
    BoundaryParameters::parse_parameters(ParameterHandler  &prm,
                                         const std::string &path,
                                         const unsigned int dim)
    {
      const std::string type = prm.get("Constraint");
      constraint             = (type == "fixed"  ? Constraint::fixed :
                                type == "normal" ? Constraint::normal :
                                type == "plate"  ? Constraint::plate :
                                                   Constraint::none);
      pressure               = prm.get("Pressure");
      AssertThrow(!Utilities::trim(pressure).empty(),
                  ExcMessage(path + "/Pressure: give an expression, '0' for "
                                    "none."));
      traction = prm.get("Traction");
      if (Utilities::trim(traction) == "0")
        traction = "0";
      AssertThrow(traction == "0" || expression_parses(traction, dim, dim),
                  ExcMessage(
                    path + "/Traction: cannot parse '" + traction + "' as " +
                    std::to_string(dim) +
                    " functions of the coordinates separated by ';'."));
      pressure = Utilities::trim(pressure);
      AssertThrow(pressure == "piezometric" ||
                    expression_parses(pressure, dim, 1),
                  ExcMessage(path + "/Pressure: cannot parse '" + pressure +
                             "' as a function of " +
                             (dim == 2 ? "x, y." : "x, y, z.")));
    }

    void
    InterfaceParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Search distance",
        "0",
        Patterns::Double(0),
        "Largest initial gap (length) between a node of one side and the node "
        "of the other side found along the interface normal; 0 pairs only "
        "coincident nodes.");
      prm.declare_entry(
        "Friction angle",
        "30",
        Patterns::Double(0, 90),
        "Friction angle phi of the interface (degrees, 0 <= "
        "phi < 90): Mohr-Coulomb |tau| <= c + sigma_n tan(phi).");
      prm.declare_entry(
        "Cohesion",
        "0",
        Patterns::Double(0),
        "Cohesion c of the interface (force/length^2, e.g. kPa).");
      prm.declare_entry(
        "Tensile strength",
        "0",
        Patterns::Double(0),
        "Tensile strength sigma_t of the interface "
        "(force/length^2): a closed pair opens when its tension "
        "exceeds sigma_t times its area.");
      prm.declare_entry(
        "Frictionless",
        "false",
        Patterns::Bool(),
        "A frictionless interface carries no tangential force "
        "(friction angle and cohesion are ignored; cohesion must "
        "be 0).");
      prm.declare_entry("Sliding surface",
                        "true",
                        Patterns::Bool(),
                        "Part of the sliding surface: the safety factor K "
                        "divides this interface's cohesion and tan(friction "
                        "angle) (eq. 10) and sums its forces (eq. 11).");
      prm.declare_entry(
        "Reduced by K",
        "false",
        Patterns::Bool(),
        "Only with Sliding surface = false: part of the "
        "mechanism but not of the sliding surface (an interslice "
        "between two blocks of the sliding mass). The safety "
        "factor K divides its cohesion and tan(friction angle) "
        "(eq. 10) as on the sliding surface, but its forces do "
        "not enter F_R and F_tau (eq. 11). A sliding surface is "
        "always reduced.");
      prm.declare_entry(
        "Strength",
        "given",
        Patterns::Selection("given|material"),
        "Where the interface's c and phi come from: given (the "
        "Cohesion and Friction angle above, the same all along) "
        "or material (each node pair takes the Cohesion and "
        "Friction angle of the material it runs through: that "
        "of the cells of the moving block, block I, at the "
        "pair; those above are then not used). Tensile strength "
        "and Frictionless stay the interface's.");
      prm.declare_entry(
        "Pore pressure",
        "0",
        Patterns::Anything(),
        "Pore (water) pressure in the interface (force/length^2) "
        "as a function of x, y (and z in 3D), or 'piezometric' "
        "for the hydrostatic pressure below Water/Piezometric "
        "line. It pushes both sides apart; friction acts on the "
        "effective normal force.");
    }

    void
    InterfaceParameters::parse_parameters(ParameterHandler  &prm,
                                          const std::string &path,
                                          const unsigned int dim)
    {
      search_distance  = prm.get_double("Search distance");
      friction_angle   = prm.get_double("Friction angle");
      cohesion         = prm.get_double("Cohesion");
      tensile_strength = prm.get_double("Tensile strength");
      frictionless     = prm.get_bool("Frictionless");
      AssertThrow(friction_angle < 90,
                  ExcMessage(path +
                             "/Friction angle: must be below 90 degrees."));
      AssertThrow(!(frictionless && cohesion > 0),
                  ExcMessage(path +
                             "/Cohesion: a frictionless interface cannot "
                             "have cohesion; set it to 0."));
      sliding_surface        = prm.get_bool("Sliding surface");
      reduced_by_K           = sliding_surface || prm.get_bool("Reduced by K");
      strength_from_material = prm.get("Strength") == "material";
      AssertThrow(!(frictionless && strength_from_material),
                  ExcMessage(path + "/Strength: a frictionless interface takes "
                                    "no strength from its materials; set it to "
                                    "'given'."));
      pore_pressure = Utilities::trim(prm.get("Pore pressure"));
      AssertThrow(pore_pressure == "piezometric" ||
                    expression_parses(pore_pressure, dim, 1),
                  ExcMessage(
                    path + "/Pore pressure: cannot parse '" + pore_pressure +
                    "' as a function of the coordinates (or 'piezometric')."));
    }

    void
    SafetyFactorParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Safety factor");
      prm.declare_entry("Compute",
                        "true",
                        Patterns::Bool(),
                        "Compute the safety factor by the iteration of eqs. "
                        "(10)-(13). If false, solve the contact problem once, "
                        "at full strength.");
      prm.declare_entry("Initial factor",
                        "1.0",
                        Patterns::Anything(),
                        "K of the first iteration, > 0 (dimensionless).");
      prm.declare_entry(
        "Tolerance",
        "1e-6",
        Patterns::Anything(),
        "Relative tolerance, > 0 (dimensionless): the iteration "
        "stops when K* reproduces K to it (eq. 13), and a K is "
        "reported only if a solved state shows that (its "
        "certificate).");
      prm.declare_entry("Maximum iterations",
                        "60",
                        Patterns::Integer(1),
                        "Largest number of contact solves in the iteration, "
                        "steps back included.");
      prm.declare_entry("Minimum factor",
                        "1e-3",
                        Patterns::Anything(),
                        "If no K down to this value has a static solution, the "
                        "model has none (> 0, dimensionless).");
      prm.declare_entry(
        "Bracket agreement",
        "0.01",
        Patterns::Double(0, 1),
        "A limit bracketed by a solved K_lo and a K_hi just above "
        "it whose solve fails as a mechanism is certified when K* "
        "at K_lo agrees with K_lo to Tolerance; or, conservatively, "
        "when K* exceeds K_lo, and the smallest K above it whose "
        "solve fails as a mechanism lies beyond K_lo, by at most "
        "this much (relative, dimensionless): equilibrium is then "
        "lost before eq. (12) reaches its limit (e.g. a wedge whose "
        "second plane lifts off), or solves between failed "
        "numerically; K_lo is reported and the run warns. Larger "
        "disagreements (an undeclared contact gives K* many times "
        "K) are refused. 0 asks for agreement to Tolerance.");
      prm.declare_entry(
        "Stiffness check",
        "true",
        Patterns::Bool(),
        "After the safety factor, compute it again with the "
        "moving blocks (those with free rigid modes) Stiffness "
        "check factor times stiffer and times softer: contact "
        "solves only, on the same factorisation. A K that "
        "changes by more than Stiffness check warning means the "
        "sliding surface is not a mechanism for a rigid block and "
        "K measures the blocks' elasticity. Dense mixed system "
        "only; set false to save its memory (one more matrix of "
        "the size of C) on large models.");
      prm.declare_entry(
        "Stiffness check factor",
        "10",
        Patterns::Double(1.0 + 1e-12, 1e6),
        "How much stiffer and softer the moving blocks are made "
        "for the stiffness check (dimensionless, > 1).");
      prm.declare_entry(
        "Stiffness check warning",
        "0.01",
        Patterns::Double(0, 1e6),
        "Relative change of K in the stiffness check beyond which "
        "the run warns (dimensionless, >= 0).");
      prm.leave_subsection();
    }

    void
    SafetyFactorParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Safety factor");
      compute = prm.get_bool("Compute");
      // Read as text so that a value <= 0 gets a message naming the entry.
      const auto positive = [&](const std::string &entry) {
        double value = 0;
        try
          {
            value = parameters::finite_number(prm.get(entry));
          }
        catch (...)
          {
            AssertThrow(false,
                        ExcMessage("Safety factor/" + entry + ": '" +
                                   prm.get(entry) + "' is not a number."));
          }
        AssertThrow(value > 0 && std::isfinite(value),
                    ExcMessage("Safety factor/" + entry +
                               ": must be > 0, got " + prm.get(entry) + "."));
        return value;
      };
      initial_factor          = positive("Initial factor");
      tolerance               = positive("Tolerance");
      minimum_factor          = positive("Minimum factor");
      max_iterations          = prm.get_integer("Maximum iterations");
      bracket_agreement       = prm.get_double("Bracket agreement");
      stiffness_check         = prm.get_bool("Stiffness check");
      stiffness_check_factor  = prm.get_double("Stiffness check factor");
      stiffness_check_warning = prm.get_double("Stiffness check warning");
      prm.leave_subsection();
    }

    void
    WaterParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Water");
      prm.declare_entry(
        "Unit weight of water",
        "9.81",
        Patterns::Double(0),
        "Unit weight of water gamma_w (force/length^3, e.g. kN/m^3).");
      prm.declare_entry("Piezometric line",
                        "",
                        Patterns::Anything(),
                        "Piezometric line as points 'x,y; x,y; ...' with "
                        "increasing x (length, in the coordinates before the "
                        "Geometry transformation, moved with the mesh like "
                        "the ground and the layers): below it the water "
                        "pressure is gamma_w times the depth under the line; "
                        "used where a pressure or pore pressure is "
                        "'piezometric'. In 3D the points are x and the "
                        "vertical z, the line running unchanged along y "
                        "(the 3D slope's section across its width). Empty: "
                        "none.");
      prm.declare_entry(
        "Piezometric surface file",
        "",
        Patterns::FileName(),
        "3D: the water table as a surface over x and y, a text file of "
        "lines 'x, y, z' (length, in the coordinates before the Geometry "
        "transformation) on a rectangular grid, in any order, as "
        "Geometry/Slope 3D/Terrain file: bilinear between the grid's "
        "points, constant beyond its edges. Below it the water pressure is "
        "gamma_w times the depth under the surface, used where a pressure "
        "or pore pressure is 'piezometric', and the saturated unit weight "
        "acts. Or a surface for Gmsh (.msh of triangles or quadrangles, "
        ".geo whose surfaces Gmsh meshes, .stl) covering a rectangle in x "
        "and y with one elevation at each point, sampled on a grid every "
        "Piezometric surface grid spacing. Relative to the folder of the "
        "file that sets it. Empty: none (or Piezometric line); not both.");
      prm.declare_entry(
        "Piezometric surface grid spacing",
        "0",
        Patterns::Double(0),
        "With a Gmsh surface as Piezometric surface file: the largest "
        "distance between the grid lines it is sampled on, in x and in y "
        "(length). The water table follows the surface to within the "
        "variation of its slope over a cell. 0: 200 steps along the "
        "surface's longer side.");
      prm.leave_subsection();
    }

    void
    WaterParameters::parse_parameters(ParameterHandler  &prm,
                                      const unsigned int dim)
    {
      prm.enter_subsection("Water");
      unit_weight      = prm.get_double("Unit weight of water");
      piezometric_line = parse_piezometric_line(prm.get("Piezometric line"),
                                                "Water/Piezometric line");
      piezometric_surface_file = prm.get("Piezometric surface file");
      const double spacing = prm.get_double("Piezometric surface grid spacing");
      prm.leave_subsection();
      piezometric_surface = geometry::TerrainGrid();
      if (piezometric_surface_file.empty())
        return;
      AssertThrow(dim == 3,
                  ExcMessage("Water/Piezometric surface file: a water surface "
                             "over x and y is for 3D models; in 2D give "
                             "Water/Piezometric line."));
      AssertThrow(piezometric_line.empty(),
                  ExcMessage("Water/Piezometric surface file: give either it "
                             "or Water/Piezometric line, not both."));
      const std::string &path  = piezometric_surface_file;
      const std::string  entry = "Water/Piezometric surface file";
      piezometric_surface =
        geometry::is_surface_mesh_file(piezometric_surface_file) ?
          geometry::terrain_grid_from_surface(path, entry, spacing) :
          geometry::terrain_grid_from_file(path, entry);
    }

    void
    ContactParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.declare_entry("Maximum status iterations",
                        "100",
                        Patterns::Integer(1),
                        "Largest number of solves of the mixed system in one "
                        "contact problem (status iteration).");
      prm.declare_entry("Runaway factor",
                        "1e6",
                        Patterns::Double(1),
                        "A solution whose rigid relative motion exceeds this "
                        "many times the elastic relative displacements has no "
                        "static equilibrium (dimensionless).");
      prm.leave_subsection();
    }

    void
    ContactParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      max_status_iterations = prm.get_integer("Maximum status iterations");
      runaway_factor        = prm.get_double("Runaway factor");
      prm.leave_subsection();
    }

    void
    LoadParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loads");
      prm.declare_entry("Gravity direction",
                        "",
                        Patterns::List(Patterns::Double(), 0, 3),
                        "Direction of gravity (any length; it is normalised), "
                        "2 or 3 comma-separated numbers as the dimension. "
                        "Empty: down, i.e. -y in 2D and -z in 3D.");
      prm.declare_entry("Gravitational acceleration",
                        "9.81",
                        Patterns::Double(0),
                        "Gravitational acceleration (length/time^2), used for "
                        "blocks given a density.");
      prm.declare_entry(
        "Horizontal seismic coefficient",
        "0",
        Patterns::Double(-1, 1),
        "Pseudo-static horizontal seismic coefficient kh "
        "(dimensionless, a fraction of g, -1 to 1): every block "
        "carries a horizontal body force kh times its weight, in "
        "the Seismic direction (by default towards the free face, "
        "the horizontal direction in which the sliding mass "
        "moves); a negative kh points the other way. Superposed "
        "on the gravity solution without a new factorisation.");
      prm.declare_entry(
        "Vertical seismic coefficient",
        "0",
        Patterns::Double(-1, 1),
        "Pseudo-static vertical seismic coefficient kv "
        "(dimensionless, -1 to 1, below 1): a body force kv times "
        "the weight, positive UPWARDS (against gravity: the "
        "weight becomes (1 - kv) W), negative downwards.");
      prm.declare_entry(
        "Seismic direction",
        "towards free face",
        Patterns::Anything(),
        "Direction of a positive kh: 'towards free face' (the "
        "horizontal part, perpendicular to gravity, of the "
        "downslope component of gravity along the sliding "
        "surfaces, summed over their node pairs with their areas: "
        "on a plane the dip direction, on a slip circle the way "
        "the mass slides), or 2 or 3 comma-separated numbers as "
        "the dimension (any length, normalised; its part along "
        "gravity is removed).");
      prm.declare_entry(
        "Seismic force on pore water",
        "false",
        Patterns::Bool(),
        "Whether kh and kv act on the saturated unit weight below "
        "the water table (the pore water moves with the soil), "
        "or on the unit weight everywhere (false: the pore "
        "water's extra weight carries no seismic force).");
      prm.leave_subsection();
    }

    void
    LoadParameters::parse_parameters(ParameterHandler  &prm,
                                     const unsigned int dim)
    {
      prm.enter_subsection("Loads");
      const std::string direction =
        Utilities::trim(prm.get("Gravity direction"));
      if (direction.empty())
        {
          gravity_direction.assign(dim, 0.0);
          gravity_direction[dim - 1] = -1;
        }
      else
        gravity_direction =
          parse_vector(direction, dim, "Loads/Gravity direction");
      double norm = 0;
      for (const double g : gravity_direction)
        norm += g * g;
      AssertThrow(norm > 0,
                  ExcMessage("Loads/Gravity direction: must not be zero."));
      for (double &g : gravity_direction)
        g /= std::sqrt(norm);
      gravitational_acceleration = prm.get_double("Gravitational acceleration");
      horizontal_seismic_coefficient =
        prm.get_double("Horizontal seismic coefficient");
      vertical_seismic_coefficient =
        prm.get_double("Vertical seismic coefficient");
      AssertThrow(
        vertical_seismic_coefficient < 1,
        ExcMessage(
          "Loads/Vertical seismic coefficient: must be below 1 (kv = 1 "
          "upwards cancels the weight)."));
      const std::string seismic = Utilities::trim(prm.get("Seismic direction"));
      seismic_direction.clear();
      if (seismic != "towards free face")
        {
          seismic_direction =
            parse_vector(seismic, dim, "Loads/Seismic direction");
          double along = 0, norm = 0;
          for (unsigned int d = 0; d < dim; ++d)
            along += seismic_direction[d] * gravity_direction[d];
          for (unsigned int d = 0; d < dim; ++d)
            {
              seismic_direction[d] -= along * gravity_direction[d];
              norm += seismic_direction[d] * seismic_direction[d];
            }
          AssertThrow(
            norm > 1e-20,
            ExcMessage(
              "Loads/Seismic direction: 'towards free face' or a "
              "direction with a horizontal part (not along gravity)."));
          for (double &h : seismic_direction)
            h /= std::sqrt(norm);
        }
      seismic_on_pore_water = prm.get_bool("Seismic force on pore water");
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace fdem
