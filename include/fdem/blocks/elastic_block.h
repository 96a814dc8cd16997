// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/block_factorization.h>
#include <fdem/blocks/element_family.h>
#include <fdem/blocks/interface_node.h>
#include <fdem/blocks/surface_loads.h>
#include <fdem/geometry/mesh_description.h>
#include <fdem/parameters/model_parameters.h>

#include <deal.II/base/function.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * One linear elastic body meshed with finite elements: its stiffness K
     * (factorised once), its load vector F (gravity and pressures), its
     * Dirichlet conditions, and the rigid motions those conditions leave free
     * (doc/theory.md). A block with free modes is held for the
     * FE solves by a minimal, statically determinate support that removes
     * exactly those modes; the mixed system then adds them back as unknowns.
     *
     * The merged mesh of a whole model is an ElasticBlock too (every cell
     * takes the material of its block): that is the plain FE model the mixed
     * method must reproduce when everything sticks.
     *
     * MPI: the triangulation is a parallel::shared::Triangulation on
     * MPI_COMM_WORLD without artificial cells, so every rank holds every
     * cell and every dof, and all passes over the cells other than the
     * assembly of K (interface nodes, residuals, rigid modes, output) run
     * the same on every rank on global-size vectors. Only K is distributed:
     * each rank assembles its own cells (METIS partition) into the rows of
     * the dofs it owns, and the factorisation and the solves run on all
     * ranks (BlockFactorization); they take and return global-size
     * vectors, the same on every rank. With one rank this is the serial
     * code.
     *
     * The members are defined in four files: elastic_block.cc (mesh,
     * assembly, factorisation, solves), supports.cc (Dirichlet conditions,
     * rigid modes, minimal support), interface_nodes.cc and
     * interface_flexibility.cc.
     */
    template <int dim>
    class ElasticBlock
    {
    public:
      /**
       * Builds the block from the cells of @p block_ids in @p mesh, with the
       * material of each material key (MeshDescription::material_key()) of
       * its cells in @p materials.
       */
      ElasticBlock(
        const std::string                                            &name,
        const geometry::MeshDescription<dim>                         &mesh,
        const std::vector<unsigned int>                              &block_ids,
        const std::map<unsigned int, parameters::MaterialParameters> &materials,
        const unsigned int fe_degree);

      /**
       * Applies the Dirichlet conditions, keyed by face-group index
       * (boundary id). @p interface_ids lists the face
       * groups that are interfaces (never used for supports).
       */
      void
      setup_constraints(
        const std::map<types::boundary_id, parameters::BoundaryParameters>
                                              &boundary_conditions,
        const std::vector<types::boundary_id> &interface_ids);

      /**
       * Surface loads by face group (boundary id): pressures (pushing into
       * the block) and traction vectors. Water in an interface is a pressure
       * on both sides' faces.
       */
      void
      set_surface_loads(
        const std::map<types::boundary_id, std::shared_ptr<const Function<dim>>>
          &pressures,
        const std::map<types::boundary_id, std::shared_ptr<const Function<dim>>>
          &tractions);

      /** Finds the free rigid modes and adds a minimal support for them. */
      void
      find_free_rigid_modes();

      /**
       * Assembles K and F, and factorises K with the back-end @p solver_type
       * (make_block_factorization(); with MUMPS_Schur the interface dofs
       * are eliminated last and their Schur complement kept, see
       * MumpsSchurSolver). Collective: every rank assembles its cells.
       */
      void
      assemble_and_factorize(const parameters::LoadParameters  &loads,
                             const parameters::DirectSolverType solver_type);

      /** Assembles K and F (the first half of assemble_and_factorize). */
      void
      assemble(const parameters::LoadParameters &loads);

      /**
       * Factorises the assembled K (the second half of
       * assemble_and_factorize); with @p block_low_rank_tolerance > 0 by
       * MUMPS's block low-rank factorisation (MUMPS_Schur, MUMPS only).
       * @p memory_limit_MiB > 0: MUMPS refuses a factorisation that would
       * not fit (make_block_factorization()).
       */
      void
      factorize(const parameters::DirectSolverType solver_type,
                const double                       block_low_rank_tolerance = 0,
                const double                       memory_limit_MiB = 0);

      /**
       * What the back-end reports of the factorisation of K (MUMPS: the
       * factors' size, flops and memory), one line; empty if nothing.
       */
      std::string
      factorization_statistics() const
      {
        return factorization != nullptr ? factorization->statistics() : "";
      }

      /**
       * Displacement u = K^{-1} (F_nodal) for a nodal force vector on this
       * block's dofs (Dirichlet and support dofs end with zero).
       * Collective; @p nodal_forces and the result are the same on every rank.
       */
      Vector<double>
      solve(const Vector<double> &nodal_forces) const;

      /**
       * The displacements for several nodal force vectors, solved in blocks
       * of right-hand sides (one pass through the factors for many).
       * Collective.
       */
      std::vector<Vector<double>>
      solve(const std::vector<Vector<double>> &nodal_forces) const;

      /** Right-hand sides solved together at most: see solve_blocked(). */
      static constexpr unsigned int max_rhs_per_solve = 64;

      /**
       * The blocked solve: the displacements for @p n_columns nodal force
       * vectors, at most @p max_columns in one pass through the factors (one
       * pass for many right-hand sides, and memory for that many solutions
       * only). @p set_load(c, f) adds the forces of column c to f (zero, of
       * this block's size); @p use_displacement(c, u) reads its displacement
       * (Dirichlet and support dofs zero). Collective.
       */
      template <typename SetLoad, typename UseDisplacement>
      void
      solve_blocked(const unsigned int     n_columns,
                    const SetLoad         &set_load,
                    const UseDisplacement &use_displacement,
                    const unsigned int max_columns = max_rhs_per_solve) const;

      /**
       * Flexibility matrix C(i,j) = (K^{-1})_{ij} restricted to @p dofs: the
       * displacement at dof i due to a unit force at dof j, through the
       * constraints (a force on a constrained dof acts on the dofs it
       * follows; a fixed dof does not move). With MUMPS_Schur it comes
       * from the inverse Schur complement on the interface dofs when they
       * hold every dof of @p dofs and its constraint's dofs; otherwise it is
       * solved with blocks of right-hand sides, the factorisation reused.
       */
      FullMatrix<double>
      flexibility(const std::vector<types::global_dof_index> &dofs) const;

      /**
       * The dim x dim blocks on the diagonal of the flexibility, one per node
       * of @p nodes (its dim dofs): what flexibility() gives for those dofs,
       * without the rest of C. With MUMPS (one rank) they are MUMPS's
       * selected entries of K^{-1}; with the other solvers, dim solves per
       * node.
       */
      std::vector<FullMatrix<double>>
      flexibility_diagonal_blocks(
        const std::vector<std::array<types::global_dof_index, dim>> &nodes)
        const;

      /**
       * The flexibility of @p dofs into @p C (n x n) from the inverse Schur
       * complement, if the block was factorised with MUMPS_Schur and its
       * Schur dofs hold every dof of @p dofs and its constraint's dofs;
       * false (and @p C untouched) otherwise.
       */
      bool
      flexibility_from_schur(const std::vector<types::global_dof_index> &dofs,
                             FullMatrix<double> &C) const;

      /** The nodes of this block on the face group @p group. */
      std::vector<InterfaceNode<dim>>
      interface_nodes(const types::boundary_id group) const;

      /**
       * Nodal forces sum over cells (K_e u_e - F_e) over the cells whose
       * material id is @p material_id (all cells for invalid_unsigned_int): at
       * a node on the boundary of that set, the force the rest of the world
       * exerts on it. Used for reactions and interface forces.
       */
      Vector<double>
      nodal_residual(
        const Vector<double> &u,
        const unsigned int material_id = numbers::invalid_unsigned_int) const;

      /**
       * The assembled stiffness matrix K, with the Dirichlet conditions and
       * the minimal support condensed (their rows and columns hold only a
       * diagonal entry): what the factorisation factorised. The iterative
       * mixed system's Dirichlet preconditioner builds the block's Schur
       * complement on its interface dofs from it.
       */
      const TrilinosWrappers::SparseMatrix &
      stiffness() const
      {
        return stiffness_matrix;
      }

      /** Number of free rigid modes. */
      unsigned int
      n_free_rigid_modes() const
      {
        return free_modes.n();
      }

      /**
       * Displacement at @p x of free mode @p k (the k-th column of omega
       * restricted to the free modes, eq. 1).
       */
      Tensor<1, dim>
      free_mode_displacement(const unsigned int k, const Point<dim> &x) const;

      /** Adds the rigid motion sum_k gamma_k omega_k (eq. 1) to the field @p u.
       */
      void
      add_rigid_motion(const Vector<double> &gamma, Vector<double> &u) const;

      /** Generalised load on free mode k: omega_k^T F (eq. 7). */
      double
      free_mode_load(const unsigned int k) const;

      /** The same for the nodal forces @p nodal_forces instead of F. */
      double
      free_mode_load(const unsigned int    k,
                     const Vector<double> &nodal_forces) const;

      /**
       * The nodal forces of the block's weight per unit coefficient in each
       * coordinate direction d: the integral of N gamma e_d, gamma the unit
       * weight of assemble()'s gravity (rho g). With @p saturated the
       * saturated weight below the water table, as the assembled gravity
       * has it; without, the material's weight everywhere (the soil without
       * the water in its pores' extra weight). Any body force proportional
       * to the weight (gravity, seismic coefficients, a factor on the unit
       * weight) is a linear combination of these dim vectors (load cases,
       * doc/theory.md). Needs assemble() first.
       */
      std::vector<Vector<double>>
      unit_body_force_loads(const bool saturated) const;

      /**
       * The nodal forces that a water table brings, given by its pressure
       * @p water_table (as #water_table): [0] that pressure on the faces of
       * the face groups @p faces, pushing into the block as assemble()
       * applies a pressure; [1 + d] the saturated weight's excess over the
       * weight where @p water_table is positive, per unit coefficient in
       * direction d. The same quadratures as assemble(), so that with the
       * block's own water table these are the parts of its F that the
       * water makes. Collective.
       */
      std::vector<Vector<double>>
      water_loads(const PiezometricPressure<dim>     &water_table,
                  const std::set<types::boundary_id> &faces) const;

      std::string                          name;
      parallel::shared::Triangulation<dim> triangulation;
      /** FE_Q or FE_SimplexP, by the shape of the mesh's cells. */
      ElementFamily<dim> element_family;
      FESystem<dim>      fe;
      /** Owns the mapping (MappingQ(1) or the linear MappingFE). */
      std::unique_ptr<const Mapping<dim>> mapping_object;
      const Mapping<dim>                 &mapping;
      DoFHandler<dim>                     dof_handler;
      /**
       * Material per material id of the cells (MeshDescription::material_key():
       * the block's own material, or the block's part of a material region).
       */
      std::map<unsigned int, parameters::MaterialParameters> materials;
      /**
       * Water pressure of the water table (Water/Piezometric line, or the
       * material's own line), if one is given: where it is positive in a
       * cell, the cell's weight is its material's saturated weight
       * (evaluated at each quadrature point).
       */
      std::shared_ptr<const PiezometricPressure<dim>> water_table;
      /** Dirichlet conditions of the block. */
      AffineConstraints<double> dirichlet_constraints;
      /** Dirichlet conditions plus the minimal support of the free modes. */
      AffineConstraints<double> constraints;
      /** Dofs of the minimal support. */
      std::vector<types::global_dof_index> support_dofs;
      /** Free rigid modes: n_rigid_modes x n_free coefficients of the modes. */
      FullMatrix<double> free_modes;
      /** Centre and length scale of the rigid modes (centroid, size). */
      Point<dim> centre;
      double     length_scale = 1;
      /** External nodal forces F (before constraints). */
      Vector<double> load_vector;
      /** Wall time of the assembly and of the factorisation of K (s, this
       * rank). */
      double assembly_seconds      = 0;
      double factorization_seconds = 0;

    private:
      std::map<types::boundary_id, std::shared_ptr<const Function<dim>>>
        pressures;
      std::map<types::boundary_id, std::shared_ptr<const Function<dim>>>
                                      tractions;
      std::vector<types::boundary_id> interface_ids;
      TrilinosWrappers::SparseMatrix  stiffness_matrix;
      /** The factorisation of stiffness_matrix. */
      std::unique_ptr<BlockFactorization> factorization;
      parameters::LoadParameters          loads;

      /** Support point and vector component of every dof. */
      std::vector<Point<dim>>   dof_support_points;
      std::vector<unsigned int> dof_components;

      /**
       * Constraints of a rigid loading plate on boundary part @p id: the
       * displacement along the part's normal (a coordinate axis) is the same
       * at all its nodes.
       */
      void
      add_plate_constraints(const types::boundary_id   id,
                            AffineConstraints<double> &plate) const;

      /**
       * The dofs whose Schur complement MUMPS_Schur keeps: the
       * unconstrained dofs on the interfaces and the dofs that constrained
       * ones follow.
       */
      std::vector<types::global_dof_index>
      interface_schur_dofs() const;

      /** Values of every rigid mode at every dof (n_dofs x n_rigid_modes). */
      FullMatrix<double>
      rigid_modes_at_dofs() const;

      /** FE evaluators and cell arrays for one pass over the cells. */
      struct CellScratch
      {
        CellScratch(const Mapping<dim>       &mapping,
                    const FiniteElement<dim> &fe,
                    const ElementFamily<dim> &family);
        FEValues<dim>                        fe_values;
        FEFaceValues<dim>                    fe_face_values;
        FullMatrix<double>                   matrix;
        Vector<double>                       rhs;
        std::vector<types::global_dof_index> dofs;
        /** Strains and divergences of the shape functions at one point. */
        std::vector<SymmetricTensor<2, dim>> strains;
        std::vector<double>                  divergences;
      };

      /** Element stiffness K_e and load F_e (gravity and pressures) into @p
       * scratch. */
      void
      assemble_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                    CellScratch &scratch) const;
    };


    template <int dim>
    template <typename SetLoad, typename UseDisplacement>
    void
    ElasticBlock<dim>::solve_blocked(const unsigned int     n_columns,
                                     const SetLoad         &set_load,
                                     const UseDisplacement &use_displacement,
                                     const unsigned int     max_columns) const
    {
      const std::size_t   n_dofs = dof_handler.n_dofs();
      Vector<double>      column(n_dofs);
      std::vector<double> columns;
      for (unsigned int first = 0; first < n_columns; first += max_columns)
        {
          const unsigned int n = std::min(max_columns, n_columns - first);
          columns.resize(n_dofs * n);
          for (unsigned int c = 0; c < n; ++c)
            {
              column = 0;
              set_load(first + c, column);
              constraints.condense(column);
              std::copy(column.begin(),
                        column.end(),
                        columns.begin() + c * n_dofs);
            }
          factorization->solve(columns, n);
          for (unsigned int c = 0; c < n; ++c)
            {
              std::copy(columns.begin() + c * n_dofs,
                        columns.begin() + (c + 1) * n_dofs,
                        column.begin());
              constraints.distribute(column);
              use_displacement(first + c,
                               static_cast<const Vector<double> &>(column));
            }
        }
    }
  } // namespace blocks
} // namespace fdem
