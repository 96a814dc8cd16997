// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/cases/terrain.h>
#include <fdem/parameters/material_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace fdem
{
  namespace parameters
  {
    /** How a boundary part is supported. */
    enum class Constraint
    {
      none,
      fixed,
      normal,
      /** The same normal displacement at every node: a rigid loading plate. */
      plate
    };

    /**
     * Conditions on one named boundary part: subsection
     * "Boundaries/<face group name>".
     */
    struct BoundaryParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path,
                       const unsigned int        dim);

      /** Displacement constraint on the part. */
      Constraint constraint = Constraint::none;
      /**
       * Pressure (force/length^2, positive pushing into the body) as a
       * function of x, y (, z), or "piezometric" (Water/Piezometric line);
       * "0" for none.
       */
      std::string pressure = "0";
      /**
       * Traction vector (force/length^2) as functions of x, y (, z)
       * separated by ';'; "0" for none.
       */
      std::string traction = "0";
    };

    /** Geometric pairing and strength of one interface: "Interfaces/<name>". */
    struct InterfaceParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm,
                       const std::string        &path,
                       const unsigned int        dim);

      /**
       * Largest initial normal gap (length) at which a node of one side is
       * paired with the node of the other side found along the normal; 0
       * pairs coincident nodes only.
       */
      double search_distance = 0;
      /** Friction angle phi (degrees, 0 <= phi < 90). */
      double friction_angle = 30;
      /** Cohesion c (force/length^2). */
      double cohesion = 0;
      /** Tensile strength sigma_t (force/length^2): the tension cut-off. */
      double tensile_strength = 0;
      /** No friction and no cohesion: the tangential force is zero. */
      bool frictionless = false;
      /** Part of the sliding surface whose c and tan(phi) the safety factor
       * reduces. */
      bool sliding_surface = true;
      /**
       * Whether K divides c and tan(phi) (eq. 10): every sliding surface, and
       * the other interfaces of the mechanism (interslices), whose forces
       * do not enter eq. (11).
       */
      bool reduced_by_K = true;
      /**
       * Where c and phi come from: false, the entries above (one pair of
       * values for the whole interface); true ("Strength = material"), each
       * node pair takes the soil strength of the material of the cells it
       * runs through on the side of block I (the moving block).
       */
      bool strength_from_material = false;
      /**
       * Pore pressure (force/length^2) in the interface, a function of x, y
       * (, z), or "piezometric" for the hydrostatic pressure below
       * Water/Piezometric line; "0" for none. It pushes both sides apart, and
       * the contact law acts on the effective normal force.
       */
      std::string pore_pressure = "0";
    };

    /** The safety-factor iteration (eqs. 10-13): subsection "Safety factor". */
    struct SafetyFactorParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Compute the safety factor (else: one contact solve at full strength).
       */
      bool compute = true;
      /** K of the first iteration (eq. 10). */
      double initial_factor = 1.0;
      /** Stop when two successive K* agree to this relative tolerance (eq. 13).
       */
      double tolerance = 1e-6;
      /** Largest number of contact solves of the iteration. */
      unsigned int max_iterations = 60;
      /** Below this K the search for a statically admissible K gives up. */
      double minimum_factor = 1e-3;
      /** How far K* may exceed K_lo in a conservative bracket certificate. */
      double bracket_agreement = 0.01;
      /** Recompute K with the moving blocks stiffer and softer. */
      bool stiffness_check = true;
      /** By how much stiffer and softer (> 1). */
      double stiffness_check_factor = 10;
      /** Relative change of K beyond which the run warns. */
      double stiffness_check_warning = 0.01;
    };

    /** Water: subsection "Water". */
    struct WaterParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /** Reads the subsection; a surface file (its name resolved by the
       * handler, parameter_file.h) only in 3D (@p dim). */
      void
      parse_parameters(dealii::ParameterHandler &prm, const unsigned int dim);

      /** Whether a water table is given: the line or the surface. */
      bool
      has_water_table() const
      {
        return !piezometric_line.empty() || !piezometric_surface.empty();
      }

      /** Unit weight of water gamma_w (force/length^3). */
      double unit_weight = 9.81;
      /**
       * Piezometric line as points "x,y; x,y; ..." with increasing x (2D):
       * below it the pressure is gamma_w times the depth under it. Empty:
       * none. A material with a line of its own
       * (MaterialParameters::piezometric_line) uses that one instead.
       */
      std::vector<std::array<double, 2>> piezometric_line;
      /**
       * The water table as a surface over x and y (3D only): elevations z
       * on a rectangular grid or a Gmsh surface, read like the Terrain file
       * from Water/Piezometric surface file (kept here as given, relative
       * to the .prm's folder). Empty: none; not with a line.
       */
      std::string           piezometric_surface_file;
      geometry::TerrainGrid piezometric_surface;
    };

    /** The status iteration of the contact solver: subsection "Contact". */
    struct ContactParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Largest number of solves of the mixed system per contact problem. */
      unsigned int max_status_iterations = 100;
      /** Rigid motion beyond this many times the elastic scale is a runaway. */
      double runaway_factor = 1e6;
    };

    /** Gravity and the other loads common to all blocks: subsection "Loads". */
    struct LoadParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm, const unsigned int dim);

      /** Unit vector of gravity. */
      std::vector<double> gravity_direction = {0, -1};
      /** Gravitational acceleration (length/time^2), used with densities. */
      double gravitational_acceleration = 9.81;
      /**
       * Pseudo-static seismic coefficients (doc/theory.md, "Seismic load"):
       * a body force kh W in seismic_direction and kv W upwards (against
       * gravity), W the weight.
       */
      double horizontal_seismic_coefficient = 0;
      double vertical_seismic_coefficient   = 0;
      /** The horizontal direction of kh (normalised); empty: towards the free
       * face (found). */
      std::vector<double> seismic_direction;
      /** Whether the seismic force acts on the saturated weight below the water
       * table. */
      bool seismic_on_pore_water = false;

      /** Whether any seismic coefficient is set. */
      bool
      seismic() const
      {
        return horizontal_seismic_coefficient != 0 ||
               vertical_seismic_coefficient != 0;
      }
    };

    /**
     * The sparse direct solver of the block stiffness matrices, parsed once
     * from "Solver/Direct solver" (the .prm strings in the comments).
     */
    enum class DirectSolverType
    {
      /** "MUMPS_Schur": MUMPS, the interface dofs' Schur complement kept. */
      mumps_schur,
      /** "MUMPS": MUMPS's C interface, L D L^T. */
      mumps,
      /** "CHOLMOD": SuiteSparse's supernodal Cholesky (one MPI rank). */
      cholmod,
      /** "Amesos_Klu": Trilinos Amesos, KLU. */
      amesos_klu,
      /** "Amesos_Mumps": Trilinos Amesos, MUMPS. */
      amesos_mumps,
      /** "UMFPACK": deal.II's SparseDirectUMFPACK (one MPI rank). */
      umfpack
    };

    /** The .prm string of @p type ("MUMPS_Schur", ...). */
    std::string
    direct_solver_name(const DirectSolverType type);

    /** The type of a .prm string; throws naming Solver/Direct solver otherwise.
     */
    DirectSolverType
    parse_direct_solver_type(const std::string &name);

    /** Linear solvers: subsection "Solver". */
    struct SolverParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Direct solver that factorises each block stiffness once. */
      DirectSolverType direct_solver = DirectSolverType::mumps_schur;
      /**
       * How the mixed system (eq. 9) is solved: "dense" (C formed, LU) or
       * "iterative" (C applied through the factorisations inside GMRES).
       */
      std::string mixed_system = "dense";
      /** Relative tolerance of GMRES for the iterative mixed system. */
      double gmres_tolerance = 1e-12;
      /**
       * Preconditioner of the iterative mixed system: "Dirichlet" (FETI's
       * Dirichlet preconditioner from the blocks' Schur complements) or
       * "pairs" (the pairs' own blocks and groups of pairs).
       */
      std::string mixed_preconditioner = "Dirichlet";
      /**
       * MUMPS's block low-rank dropping parameter CNTL(7) for the blocks'
       * factorisations (MUMPS_Schur, MUMPS); 0: full rank.
       */
      double block_low_rank_tolerance = 0;
    };

    /** What the run writes: subsection "Output". */
    struct OutputParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Output folder; empty means "<case name>-output" in the working
       * directory. */
      std::string directory;
      /** Write VTU/PVD files for ParaView (the CSV and JSON files are always
       * written). */
      bool write_vtu = true;
      /** Make report.html at the end of the run (postprocess/report.h). */
      bool report = true;
      /**
       * Also write the VTU files of every safety-factor step with a static
       * solution, not only those of the final state.
       */
      bool write_steps = false;
    };

    /** True if @p expression is a valid function of x, y (, z) with @p
     * n_components components (separated by ';'). */
    bool
    expression_parses(const std::string &expression,
                      const unsigned int dim,
                      const unsigned int n_components = 1);

    /** Parses "a, b, c" into exactly n_components numbers, or throws naming
     * path. */
    std::vector<double>
    parse_vector(const std::string &text,
                 const unsigned int n_components,
                 const std::string &path);

    /**
     * Parses a piezometric line "x,y; x,y; ..." (at least two points, x
     * increasing; empty: none), or throws naming @p path.
     */
    std::vector<std::array<double, 2>>
    parse_piezometric_line(const std::string &text, const std::string &path);
  } // namespace parameters
} // namespace fdem
