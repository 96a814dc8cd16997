// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The Solver and Output subsections: how the model is solved and what a run
// writes (the other subsections of the model are in model_parameters.cc).
#include <fdem/parameters/model_parameters.h>

#include <deal.II/base/exceptions.h>

#include <array>
#include <string>
#include <utility>

namespace fdem
{
  namespace parameters
  {
    using namespace dealii;

    namespace
    {
      /** Every direct solver with its .prm string, in the Selection's order. */
      const std::array<std::pair<DirectSolverType, const char *>, 6>
        direct_solver_names = {
          {{DirectSolverType::mumps_schur, "MUMPS_Schur"},
           {DirectSolverType::mumps, "MUMPS"},
           {DirectSolverType::cholmod, "CHOLMOD"},
           {DirectSolverType::amesos_klu, "Amesos_Klu"},
           {DirectSolverType::amesos_mumps, "Amesos_Mumps"},
           {DirectSolverType::umfpack, "UMFPACK"}}};

      /** "MUMPS_Schur|MUMPS|...": the names for Patterns::Selection. */
      std::string
      direct_solver_selection()
      {
        std::string selection;
        for (const auto &[type, name] : direct_solver_names)
          selection += (selection.empty() ? "" : "|") + std::string(name);
        return selection;
      }
    } // namespace

    std::string
    direct_solver_name(const DirectSolverType type)
    {
      for (const auto &[t, name] : direct_solver_names)
        if (t == type)
          return name;
      Assert(false, ExcInternalError());
      return "";
    }

    DirectSolverType
    parse_direct_solver_type(const std::string &name)
    {
      for (const auto &[type, t_name] : direct_solver_names)
        if (name == t_name)
          return type;
      AssertThrow(false,
                  ExcMessage("Solver/Direct solver: '" + name +
                             "' is not one of " + direct_solver_selection() +
                             "."));
      return DirectSolverType::mumps_schur;
    }

    void
    SolverParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      prm.declare_entry(
        "Direct solver",
        "MUMPS_Schur",
        Patterns::Selection(direct_solver_selection()),
        "Sparse direct solver that factorises each block's "
        "stiffness matrix once. MUMPS_Schur: MUMPS (C "
        "interface, L D L^T) with the interface dofs eliminated "
        "last, so their flexibility is the inverse of the "
        "dense Schur complement (no solves). MUMPS: the same "
        "factorisation without the Schur complement. "
        "CHOLMOD: SuiteSparse's supernodal Cholesky (one MPI "
        "rank). "
        "Amesos_Klu, Amesos_Mumps: Trilinos Amesos (LU). "
        "UMFPACK: deal.II's SparseDirectUMFPACK (LU, one "
        "right-hand side at a time). "
        "Except for MUMPS_Schur the interface flexibility is "
        "solved with blocks of 64 right-hand sides. See "
        "doc/flexibility_solvers.md for timings.");
      prm.declare_entry("Mixed system",
                        "dense",
                        Patterns::Selection("dense|iterative"),
                        "How the mixed system of the contact forces (eq. 9) is "
                        "solved in each status iteration. dense: the interface "
                        "flexibility C is formed (memory (dim x pairs)^2) and "
                        "the system LU-factorised; fastest for up to about a "
                        "thousand pairs. iterative: C is never formed but "
                        "applied through the blocks' factorisations (one solve "
                        "per block and GMRES iteration), preconditioned as "
                        "Mixed preconditioner says; memory grows as the FE "
                        "model. "
                        "For large 3D interfaces, see doc/scaling.md for the "
                        "crossover. It needs no Schur complement: MUMPS_Schur "
                        "then factorises as MUMPS does.");
      prm.declare_entry("GMRES tolerance",
                        "1e-12",
                        Patterns::Double(1e-16, 1e-4),
                        "Mixed system = iterative: GMRES stops when the "
                        "preconditioned residual (in force units) is this "
                        "fraction of the preconditioned right-hand side "
                        "(dimensionless). The forces, and K, carry what is "
                        "left: on prm/paper_slope.prm 1e-8, 1e-6 and 1e-4 "
                        "moved K by 1e-9, 2e-6 and 3e-5 relative to 1e-12.");
      prm.declare_entry(
        "Mixed preconditioner",
        "Dirichlet",
        Patterns::Selection("Dirichlet|pairs"),
        "Mixed system = iterative: the preconditioner of GMRES. "
        "Dirichlet: FETI's Dirichlet preconditioner, the inverse of the "
        "interface flexibility approximated by the blocks' Schur "
        "complements on their interface dofs (one more sparse "
        "factorisation per block, of its stiffness with the interface "
        "dofs fixed, so twice the factors' memory), fitted to the "
        "pairs' rows and the rigid unknowns: 0.4-0.5 of the GMRES "
        "iterations of pairs on the 3D block on a plane (49 to 1681 "
        "pairs), at two block solves per iteration instead of one. "
        "pairs: the pairs' own blocks of the flexibility with a coarse "
        "correction on groups of neighbouring pairs (no second "
        "factorisation). With more than one MPI rank pairs is used. See "
        "doc/scaling.md for measurements and when each was the faster.");
      prm.declare_entry(
        "Block low-rank tolerance",
        "0",
        Patterns::Double(0, 1e-2),
        "Direct solver = MUMPS_Schur or MUMPS only: MUMPS's block "
        "low-rank (BLR) factorisation of each block's stiffness "
        "matrix, with this dropping parameter (MUMPS's CNTL(7), "
        "relative to MUMPS's scaled matrix, dimensionless): blocks of "
        "the fronts are stored as products of low rank whose error is "
        "about this fraction of the matrix, which saves flops on "
        "large 3D fronts (1e-6: a third of the factorisation time at "
        "2e5 dofs; no peak memory saved there). The factors, and so the "
        "flexibility, the forces and K, become approximate at about "
        "this relative level (on prm/slope_3d.prm 1e-4 moved K by "
        "1e-7; 1e-2 made a Schur complement indefinite, an error). "
        "0: full rank, "
        "exact up to round-off. The Schur complement of the "
        "interface dofs stays a full-rank dense matrix. See "
        "doc/scaling.md for when it pays.");
      prm.leave_subsection();
    }

    void
    SolverParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      direct_solver        = parse_direct_solver_type(prm.get("Direct solver"));
      mixed_system         = prm.get("Mixed system");
      gmres_tolerance      = prm.get_double("GMRES tolerance");
      mixed_preconditioner = prm.get("Mixed preconditioner");
      block_low_rank_tolerance = prm.get_double("Block low-rank tolerance");
      prm.leave_subsection();
      // Only MUMPS has a low-rank mode: silently ignoring the entry would let
      // a user believe a run was approximated (or sped up) when it was not.
      AssertThrow(block_low_rank_tolerance == 0 ||
                    direct_solver == DirectSolverType::mumps_schur ||
                    direct_solver == DirectSolverType::mumps,
                  ExcMessage("Solver/Block low-rank tolerance: MUMPS's block "
                             "low-rank factorisation needs Solver/Direct "
                             "solver = MUMPS_Schur or MUMPS, not " +
                             direct_solver_name(direct_solver) + "."));
    }

    void
    OutputParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "",
                        Patterns::Anything(),
                        "Folder for the results (created if missing). Empty: "
                        "'<case name>-output' in the working directory.");
      prm.declare_entry("Write VTU",
                        "true",
                        Patterns::Bool(),
                        "Write VTU/PVD files for ParaView. The CSV tables and "
                        "summary.json are always written.");
      prm.declare_entry("Report",
                        "true",
                        Patterns::Bool(),
                        "At the end of the run, make report.html (with its "
                        "PNG pictures beside it) in the results folder by the "
                        "Python script fdem_report.py installed with the "
                        "program (needs python3 with matplotlib and numpy, "
                        "and python3-vtk9 for the blocks in the model "
                        "picture). Without them the run warns and "
                        "summary.json says that no report was made.");
      prm.declare_entry("Write steps",
                        "false",
                        Patterns::Bool(),
                        "With Write VTU: also write the VTU files of every "
                        "safety-factor step with a static solution "
                        "(safety_factor_steps.pvd lists them, the time being "
                        "the step's K). False: only the final state's files, "
                        "which safety_factor_steps.pvd then lists alone.");
      prm.leave_subsection();
    }

    void
    OutputParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory   = prm.get("Directory");
      write_vtu   = prm.get_bool("Write VTU");
      report      = prm.get_bool("Report");
      write_steps = prm.get_bool("Write steps");
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace fdem
