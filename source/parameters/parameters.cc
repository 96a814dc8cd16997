// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/parameters/parameter_file.h>
#include <fdem/parameters/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fdem
{
  namespace parameters
  {
    using namespace dealii;

    namespace
    {
      // The defaults describe the paper's slope (prm/paper_slope.prm).
      const std::string default_blocks     = "sliding mass, foundation";
      const std::string default_boundaries = "left, right, bottom, ground";
      const std::string default_interfaces = "sliding surface";

      void
      declare_name_lists(ParameterHandler &prm)
      {
        prm.enter_subsection("Blocks");
        prm.declare_entry("Names",
                          default_blocks,
                          Patterns::List(Patterns::Anything()),
                          "Names of the blocks: the physical groups of "
                          "dimension 'Dimension' in the mesh. Each gets a "
                          "subsection of this name with its material.");
        prm.leave_subsection();
        prm.enter_subsection("Materials");
        prm.declare_entry("Names",
                          "",
                          Patterns::List(Patterns::Anything(), 0),
                          "Names of the material regions: physical groups of "
                          "dimension 'Dimension' in a Gmsh model that may "
                          "overlap the blocks (a cell in one block and at most "
                          "one material), or the materials of the slope "
                          "generator's Layers. Each gets a subsection of this "
                          "name with its Young's modulus, Poisson's ratio, "
                          "weights and soil strength. A block's own subsection "
                          "is the material of its cells outside every region. "
                          "Empty: none.");
        prm.leave_subsection();
        prm.enter_subsection("Boundaries");
        prm.declare_entry("Names",
                          default_boundaries,
                          Patterns::List(Patterns::Anything(), 0),
                          "Names of the boundary parts that carry conditions: "
                          "physical groups of dimension 'Dimension'-1. Each "
                          "gets a subsection of this name. Unlisted boundary "
                          "is free.");
        prm.leave_subsection();
        prm.enter_subsection("Interfaces");
        prm.declare_entry(
          "Names",
          default_interfaces,
          Patterns::List(Patterns::Anything(), 0),
          "Names of the interfaces between blocks (possible "
          "sliding surfaces): physical groups of dimension "
          "'Dimension'-1. Each gets a subsection of this name.");
        prm.leave_subsection();
      }

      template <typename SubsectionParameters>
      void
      declare_named_subsections(ParameterHandler               &prm,
                                const std::string              &section,
                                const std::vector<std::string> &names)
      {
        prm.enter_subsection(section);
        for (const std::string &name : names)
          {
            prm.enter_subsection(name);
            SubsectionParameters::declare_parameters(prm);
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }

      std::vector<std::string>
      names_in(ParameterHandler &prm, const std::string &section)
      {
        prm.enter_subsection(section);
        std::vector<std::string> names =
          Utilities::split_string_list(prm.get("Names"), ',');
        prm.leave_subsection();
        for (unsigned int i = 0; i < names.size(); ++i)
          {
            AssertThrow(!names[i].empty(),
                        ExcMessage(section +
                                   "/Names: empty name in the list."));
            for (unsigned int j = 0; j < i; ++j)
              AssertThrow(names[i] != names[j],
                          ExcMessage(section + "/Names: '" + names[i] +
                                     "' is listed twice."));
          }
        return names;
      }

      /// Reads @p filename into @p prm (parameter_file.h: the checks that
      /// ParameterHandler does not make); ParameterHandler's own errors say
      /// the line and file, which is what a user needs.
      void
      parse_file(FileRelativeParameterHandler &prm,
                 const std::string            &filename,
                 const bool                    skip_undefined)
      {
        parse_parameter_file(prm, filename, skip_undefined);
      }
    } // namespace

    std::vector<std::string>
    input_file_entries()
    {
      return {"Geometry/Mesh file",
              "Geometry/Slope 3D/Terrain file",
              "Water/Piezometric surface file",
              "Yield acceleration/Acceleration record"};
    }

    void
    Parameters::declare_parameters(ParameterHandler               &prm,
                                   const std::vector<std::string> &blocks,
                                   const std::vector<std::string> &boundaries,
                                   const std::vector<std::string> &interfaces,
                                   const std::vector<std::string> &materials)
    {
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "Spatial dimension: 2 (plane strain, per unit "
                        "thickness) or 3.");
      prm.declare_entry(
        "Finite element degree",
        "1",
        Patterns::Integer(1, 2),
        "Polynomial degree of the block elements: 1 (Q1) or 2 "
        "(Q2). Interface node pairs sit on every support point.");
      GeometryParameters::declare_parameters(prm);
      LoadParameters::declare_parameters(prm);
      declare_name_lists(prm);
      declare_named_subsections<MaterialParameters>(prm, "Blocks", blocks);
      declare_named_subsections<MaterialParameters>(prm,
                                                    "Materials",
                                                    materials);
      declare_named_subsections<BoundaryParameters>(prm,
                                                    "Boundaries",
                                                    boundaries);
      declare_named_subsections<InterfaceParameters>(prm,
                                                     "Interfaces",
                                                     interfaces);
      ContactParameters::declare_parameters(prm);
      SafetyFactorParameters::declare_parameters(prm);
      WaterParameters::declare_parameters(prm);
      SolverParameters::declare_parameters(prm);
      OutputParameters::declare_parameters(prm);
      analyses::LimitEquilibriumParameters::declare_parameters(prm);
      analyses::YieldAccelerationParameters::declare_parameters(prm);
      analyses::AnchorParameters::declare_parameters(prm);
      analyses::ProbabilisticParameters::declare_parameters(prm);
      analyses::SurfaceSearchParameters::declare_parameters(prm);
    }

    void
    Parameters::parse_parameters(ParameterHandler &prm)
    {
      dimension = prm.get_integer("Dimension");
      fe_degree = prm.get_integer("Finite element degree");
      geometry.parse_parameters(prm);
      loads.parse_parameters(prm, dimension);
      contact.parse_parameters(prm);
      safety_factor.parse_parameters(prm);
      water.parse_parameters(prm, dimension);
      solver.parse_parameters(prm);
      output.parse_parameters(prm);
      limit_equilibrium.parse_parameters(prm);
      yield_acceleration.parse_parameters(prm);
      anchors.parse_parameters(prm);
      probabilistic.parse_parameters(prm);
      surface_search.parse_parameters(prm);

      block_names     = names_in(prm, "Blocks");
      boundary_names  = names_in(prm, "Boundaries");
      interface_names = names_in(prm, "Interfaces");
      material_names  = names_in(prm, "Materials");
      for (const std::string &name : material_names)
        AssertThrow(std::find(block_names.begin(), block_names.end(), name) ==
                      block_names.end(),
                    ExcMessage("Materials/Names: '" + name +
                               "' is also a "
                               "block; a physical group is either a block or "
                               "a material region."));
      for (const std::string &name : boundary_names)
        for (const std::string &other : interface_names)
          AssertThrow(name != other,
                      ExcMessage("Boundaries/Names and Interfaces/Names: '" +
                                 name + "' cannot be both."));

      prm.enter_subsection("Blocks");
      for (const std::string &name : block_names)
        {
          prm.enter_subsection(name);
          materials[name].parse_parameters(prm, "Blocks/" + name);
          prm.leave_subsection();
        }
      prm.leave_subsection();
      prm.enter_subsection("Materials");
      for (const std::string &name : material_names)
        {
          prm.enter_subsection(name);
          materials[name].parse_parameters(prm, "Materials/" + name);
          prm.leave_subsection();
        }
      prm.leave_subsection();
      prm.enter_subsection("Boundaries");
      for (const std::string &name : boundary_names)
        {
          prm.enter_subsection(name);
          boundaries[name].parse_parameters(prm,
                                            "Boundaries/" + name,
                                            dimension);
          prm.leave_subsection();
        }
      prm.leave_subsection();
      prm.enter_subsection("Interfaces");
      for (const std::string &name : interface_names)
        {
          prm.enter_subsection(name);
          interfaces[name].parse_parameters(prm,
                                            "Interfaces/" + name,
                                            dimension);
          prm.leave_subsection();
        }
      prm.leave_subsection();
      check_piezometric_pressures();
      probabilistic_check_targets();
    }

    bool
    Parameters::has_water_table() const
    {
      return water.has_water_table() ||
             std::any_of(materials.begin(),
                         materials.end(),
                         [](const auto &material) {
                           return !material.second.piezometric_line.empty();
                         });
    }

    void
    Parameters::check_piezometric_pressures() const
    {
      if (has_water_table())
        return;
      const std::string why =
        ": 'piezometric' needs a water table; give Water/Piezometric line "
        "or Piezometric surface file (or a material's own Piezometric "
        "line).";
      for (const auto &[name, boundary] : boundaries)
        AssertThrow(boundary.pressure != "piezometric",
                    ExcMessage("Boundaries/" + name + "/Pressure" + why));
      for (const auto &[name, interface] : interfaces)
        AssertThrow(interface.pore_pressure != "piezometric",
                    ExcMessage("Interfaces/" + name + "/Pore pressure" + why));
    }

    void
    Parameters::probabilistic_check_targets() const
    {
      std::map<std::string, bool> interfaces_without_own_strength,
        materials_with_strength;
      for (const auto &[name, interface] : interfaces)
        interfaces_without_own_strength[name] =
          interface.strength_from_material || interface.frictionless;
      for (const auto &[name, material] : materials)
        materials_with_strength[name] = material.has_strength;
      probabilistic.check_targets(interfaces_without_own_strength,
                                  materials_with_strength);
      for (const auto &variable : probabilistic.variables)
        AssertThrow(
          variable.owner != analyses::RandomVariable::Owner::water ||
            has_water_table(),
          ExcMessage(
            "Probabilistic/Variables: '" + variable.target +
            "' shifts the water table, but none is given (Water/Piezometric "
            "line or Piezometric surface file)."));
      AssertThrow(
        !probabilistic.compute || safety_factor.compute,
        ExcMessage(
          "Probabilistic/Compute: needs Safety factor/Compute = true (the "
          "samples start from the safety factor's state)."));
    }

    std::string
    Parameters::output_directory() const
    {
      return output.directory.empty() ? case_name + "-output" :
                                        output.directory;
    }

    Parameters
    read_parameters(const std::string &filename, std::string *expanded)
    {
      // First pass: only the name lists, to know which subsections exist.
      FileRelativeParameterHandler names_prm(input_file_entries());
      Parameters::declare_parameters(names_prm, {}, {}, {}, {});
      parse_file(names_prm, filename, true);

      Parameters parameters;
      parameters.material_names  = names_in(names_prm, "Materials");
      parameters.block_names     = names_in(names_prm, "Blocks");
      parameters.boundary_names  = names_in(names_prm, "Boundaries");
      parameters.interface_names = names_in(names_prm, "Interfaces");

      // Second pass: strict, every entry must be declared.
      FileRelativeParameterHandler prm(input_file_entries());
      Parameters::declare_parameters(prm,
                                     parameters.block_names,
                                     parameters.boundary_names,
                                     parameters.interface_names,
                                     parameters.material_names);
      parse_file(prm, filename, false);
      const std::filesystem::path path(filename);
      parameters.case_name = path.stem().string();
      parameters.parse_parameters(prm);
      if (expanded != nullptr)
        {
          std::ostringstream out;
          prm.print_parameters(out, ParameterHandler::PRM);
          *expanded = out.str();
        }
      return parameters;
    }

    void
    print_parameters(std::ostream &out, const std::string &filename)
    {
      std::vector<std::string>     blocks, boundaries, interfaces, materials;
      FileRelativeParameterHandler names_prm(input_file_entries());
      Parameters::declare_parameters(names_prm, {}, {}, {}, {});
      if (!filename.empty())
        parse_file(names_prm, filename, true);
      blocks     = names_in(names_prm, "Blocks");
      boundaries = names_in(names_prm, "Boundaries");
      interfaces = names_in(names_prm, "Interfaces");
      materials  = names_in(names_prm, "Materials");

      FileRelativeParameterHandler prm(input_file_entries());
      Parameters::declare_parameters(
        prm, blocks, boundaries, interfaces, materials);
      if (!filename.empty())
        parse_file(prm, filename, false);
      prm.print_parameters(out, ParameterHandler::Text);
    }
  } // namespace parameters
} // namespace fdem
