// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/parameters/geometry_parameters.h>
#include <fdem/parameters/numbers.h>

#include <deal.II/base/utilities.h>

#include <filesystem>
#include <map>

namespace fdem
{
  namespace parameters
  {
    namespace case_input = geometry::case_input;

    namespace
    {
      GeometryParameters::Source
      source_from_name(const std::string &name)
      {
        using Source = GeometryParameters::Source;
        const std::map<std::string, Source> sources = {
          {"mesh file", Source::mesh_file},
          {"slope", Source::slope},
          {"hertz", Source::hertz},
          {"inclined block", Source::inclined_block},
          {"wedge", Source::wedge},
          {"block on plane", Source::block_on_plane},
          {"hertz sphere", Source::hertz_sphere},
          {"slope 3d", Source::slope_3d}};
        return sources.at(name);
      }
    } // namespace



    void
    GeometryParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        prm.declare_entry(
          "Source",
          "slope",
          Patterns::Selection(
            "mesh file|slope|hertz|inclined block|wedge|block on plane|"
            "hertz sphere|slope 3d"),
          "Where the mesh comes from: a Gmsh file (see Mesh file) or one of "
          "the built-in generators, whose data are in the subsection of the "
          "same name: slope, hertz and inclined block build 2D models "
          "(Dimension = 2), wedge, block on plane, hertz sphere and slope 3d "
          "(subsection Slope 3D) 3D models "
          "(Dimension = 3).");
        prm.declare_entry(
          "Mesh file",
          "",
          Patterns::FileName(),
          "Gmsh file for Source = mesh file: a mesh (.msh, ASCII or binary, "
          "format 2 or 4) or a geometry (.geo, meshed by Gmsh in the model's "
          "dimension). Physical groups of the model's dimension are the "
          "blocks, those one dimension lower the face groups. A relative path "
          "is relative to the folder of the file that sets it.");
        prm.declare_entry(
          "Memory limit",
          "0",
          Patterns::Double(0),
          "Largest memory a run may need (MiB), checked twice. Before "
          "meshing, the mesh of a built-in generator or a .geo file is "
          "estimated (about 3 kB "
          "per degree of freedom and 1 kB per pair squared with the dense "
          "mixed system, 300 kB per pair with the iterative one, as "
          "measured in doc/scaling.md) and a finer mesh is refused with the "
          "estimate. Before each factorisation by MUMPS (MUMPS_Schur, MUMPS; "
          "also the Dirichlet preconditioner's), MUMPS's analysis estimates "
          "its memory, and a factorisation that would take the run beyond "
          "the limit is refused. 0 "
          "means the physical memory of this machine, or the address space "
          "limit (ulimit -v) if smaller; set a larger value to override. "
          "A .geo file is estimated from Gmsh's mesh of its boundaries; a "
          ".msh file is not (it is already meshed), but its factorisations "
          "are.");
        prm.declare_entry(
          "Time limit",
          "600",
          Patterns::Double(0),
          "Longest time making the mesh may take (s): Gmsh reading a .geo "
          "file (a loop that does not end) or meshing. Past it the run ends "
          "with an error. The default, 10 minutes, is about twice the mesh and "
          "setup of the largest model of doc/scaling.md (4.1 million dofs, "
          "288 s); raise it for a mesh known to take longer. 0 means no "
          "limit.");
        prm.declare_entry(
          "Time budget",
          "86400",
          Patterns::Double(0),
          "Longest time the work of an analysis whose size the input sets may "
          "be estimated to take (s), checked before that work starts: the "
          "circles of Surface search (from the screening's measured time per "
          "slice) and the samples of Probabilistic (from the time of the "
          "safety factor at the variables' means). Work estimated to take "
          "longer, or to need more memory than Geometry/Memory limit, is "
          "refused with the estimate. The default is a day; 0 means no "
          "limit.");
        prm.declare_entry(
          "Scale factor",
          "1",
          Patterns::Double(0),
          "Factor s of the transformation x -> R (s x) + t applied to every "
          "mesh after it is made (dimensionless, positive).");
        prm.declare_entry(
          "Rotation angle",
          "0",
          Patterns::Double(-360, 360),
          "Angle of the rotation R in x -> R (s x) + t, applied to every mesh "
          "after it is made (degrees, counter-clockwise about the z axis in "
          "2D, right-handed about Rotation axis in 3D).");
        prm.declare_entry("Rotation axis",
                          "0,0,1",
                          Patterns::List(Patterns::Double(), 3, 3, ","),
                          "Axis of the rotation R in 3D (any non-zero length, "
                          "dimensionless; ignored in 2D).");
        prm.declare_entry(
          "Translation",
          "0,0",
          Patterns::List(Patterns::Double(), 2, 3, ","),
          "Translation t in x -> R (s x) + t, applied to every mesh after it "
          "is made (model length unit): 2 or 3 components, and in 2D a third "
          "component must be 0.");

        Slope::declare_parameters(prm);
        Hertz::declare_parameters(prm);
        InclinedBlock::declare_parameters(prm);
        Wedge::declare_parameters(prm);
        BlockOnPlane::declare_parameters(prm);
        HertzSphere::declare_parameters(prm);
        Slope3D::declare_parameters(prm);
      }
      prm.leave_subsection();
    }



    void
    GeometryParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        source         = source_from_name(prm.get("Source"));
        mesh_file      = prm.get("Mesh file");
        scale_factor   = prm.get_double("Scale factor");
        memory_limit   = prm.get_double("Memory limit");
        time_limit     = prm.get_double("Time limit");
        time_budget    = prm.get_double("Time budget");
        rotation_angle = prm.get_double("Rotation angle");

        const std::vector<double> axis = parameters::finite_numbers(
          Utilities::split_string_list(prm.get("Rotation axis"), ','));
        rotation_axis = Tensor<1, 3>({axis[0], axis[1], axis[2]});
        translation   = parameters::finite_numbers(
          Utilities::split_string_list(prm.get("Translation"), ','));

        case_input::require(
          source != Source::mesh_file || !mesh_file.empty(),
          "Geometry/Mesh file: must be given when Source is 'mesh file'.");
        case_input::require(scale_factor > 0,
                            "Geometry/Scale factor: must be positive.");
        case_input::require(
          rotation_axis.norm() > 0,
          "Geometry/Rotation axis: must not be the zero vector.");
        rotation_axis /= rotation_axis.norm();

        slope.parse_parameters(prm);
        hertz.parse_parameters(prm);
        inclined_block.parse_parameters(prm);
        wedge.parse_parameters(prm);
        block_on_plane.parse_parameters(prm);
        hertz_sphere.parse_parameters(prm);
        slope_3d.parse_parameters(prm);
      }
      prm.leave_subsection();

      switch (source)
        {
          case Source::mesh_file:
            break;
          case Source::slope:
            slope.validate();
            break;
          case Source::hertz:
            hertz.validate();
            break;
          case Source::inclined_block:
            inclined_block.validate();
            break;
          case Source::wedge:
            wedge.validate();
            break;
          case Source::block_on_plane:
            block_on_plane.validate();
            break;
          case Source::hertz_sphere:
            hertz_sphere.validate();
            break;
          case Source::slope_3d:
            slope_3d.load_terrain();
            slope_3d.validate();
            break;
        }
    }



    bool
    GeometryParameters::source_is_3d() const
    {
      return source == Source::wedge || source == Source::block_on_plane ||
             source == Source::hertz_sphere || source == Source::slope_3d;
    }

  } // namespace parameters
} // namespace fdem
