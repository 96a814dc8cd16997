// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/anchor_parameters.h>
#include <fdem/analyses/limit_equilibrium_parameters.h>
#include <fdem/analyses/probabilistic_parameters.h>
#include <fdem/analyses/surface_search_parameters.h>
#include <fdem/analyses/yield_acceleration_parameters.h>
#include <fdem/parameters/geometry_parameters.h>
#include <fdem/parameters/model_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace fdem
{
  namespace parameters
  {
    /**
     * Everything a .prm file says. The numbers of blocks, boundary parts and
     * interfaces vary from case to case, so their subsections are declared
     * from the name lists "Blocks/Names", "Materials/Names",
     * "Boundaries/Names" and "Interfaces/Names": the file is read twice, first
     * for the names, then strictly (an unknown entry or subsection is an
     * error).
     */
    struct Parameters
    {
      /** Spatial dimension, 2 (plane strain) or 3. */
      unsigned int dimension = 2;
      /** Polynomial degree of the finite elements, 1 or 2. */
      unsigned int fe_degree = 1;
      /** Name of the case: the .prm file's name without extension. */
      std::string case_name;

      GeometryParameters     geometry;
      LoadParameters         loads;
      SolverParameters       solver;
      ContactParameters      contact;
      SafetyFactorParameters safety_factor;
      WaterParameters        water;
      OutputParameters       output;
      /** Limit equilibrium on the model's own sliding surface. */
      analyses::LimitEquilibriumParameters limit_equilibrium;
      /** The yield acceleration and the Newmark displacement. */
      analyses::YieldAccelerationParameters yield_acceleration;
      /** Active anchors across the sliding surface (analyses/anchors.h). */
      analyses::AnchorParameters anchors;
      /** The probabilistic safety factor (Monte Carlo on the soil strengths).
       */
      analyses::ProbabilisticParameters probabilistic;
      /** The search for the critical circle (analyses/surface_search.h). */
      analyses::SurfaceSearchParameters surface_search;

      std::vector<std::string> block_names;
      /** Names of the material regions (Materials/Names). */
      std::vector<std::string> material_names;
      /**
       * Materials by name: each block's own (Blocks/<name>) and each
       * material region's (Materials/<name>); no name is both.
       */
      std::map<std::string, MaterialParameters>  materials;
      std::vector<std::string>                   boundary_names;
      std::map<std::string, BoundaryParameters>  boundaries;
      std::vector<std::string>                   interface_names;
      std::map<std::string, InterfaceParameters> interfaces;

      /** Declares every entry, with subsections for the given names. */
      static void
      declare_parameters(dealii::ParameterHandler       &prm,
                         const std::vector<std::string> &block_names,
                         const std::vector<std::string> &boundary_names,
                         const std::vector<std::string> &interface_names,
                         const std::vector<std::string> &material_names = {});

      /** Reads the values from a handler declared by declare_parameters(). */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Probabilistic/Variables: each target exists and has a strength of its
       * own. */
      void
      probabilistic_check_targets() const;

      /** Whether a water table is given: Water/Piezometric line or
       * Piezometric surface file, or a material's own Piezometric line. */
      bool
      has_water_table() const;

      /** Throws naming the entry if a boundary's Pressure or an interface's
       * Pore pressure is 'piezometric' and no water table is given. */
      void
      check_piezometric_pressures() const;

      /** The output folder this run writes into. */
      std::string
      output_directory() const;
    };

    /**
     * The entries whose values name input files: each is read relative to
     * the file that sets it, as include statements are (parameter_file.h),
     * and holds the resolved name after read_parameters().
     */
    std::vector<std::string>
    input_file_entries();

    /**
     * Reads and checks a .prm file. Throws an exception with a one-sentence
     * message naming the file, line or parameter on any error.
     * @p expanded receives the full parameter set used (for the output folder).
     */
    Parameters
    read_parameters(const std::string &filename,
                    std::string       *expanded = nullptr);

    /**
     * Prints every parameter with its default, pattern and help text, for
     * the given file or, if @p filename is empty, for the default case.
     */
    void
    print_parameters(std::ostream &out, const std::string &filename);
  } // namespace parameters
} // namespace fdem
