// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The supports of an ElasticBlock: its Dirichlet conditions, the rigid
// modes they leave free (eq. 1) and the minimal support that holds those
// for the FE solves (doc/theory.md, "What each block contributes").
#include <fdem/blocks/elastic_block.h>
#include <fdem/blocks/rigid_modes.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace fdem
{
  namespace blocks
  {
    template <int dim>
    void
    ElasticBlock<dim>::setup_constraints(
      const std::map<types::boundary_id, parameters::BoundaryParameters>
                                            &boundary_conditions,
      const std::vector<types::boundary_id> &interface_group_ids)
    {
      interface_ids = interface_group_ids;
      AffineConstraints<double>    fixed, normal, plate;
      std::set<types::boundary_id> normal_ids;
      for (const auto &[id, condition] : boundary_conditions)
        {
          if (condition.constraint == parameters::Constraint::fixed)
            VectorTools::interpolate_boundary_values(
              mapping,
              dof_handler,
              id,
              Functions::ZeroFunction<dim>(dim),
              fixed);
          else if (condition.constraint == parameters::Constraint::normal)
            normal_ids.insert(id);
          else if (condition.constraint == parameters::Constraint::plate)
            add_plate_constraints(id, plate);
        }
      if (!normal_ids.empty())
        VectorTools::compute_no_normal_flux_constraints(
          dof_handler, 0, normal_ids, normal, mapping);

      // Where a fixed part meets a roller or a plate, the fixed condition
      // wins; where a roller meets a plate, the roller.
      dirichlet_constraints.clear();
      dirichlet_constraints.merge(plate);
      dirichlet_constraints.merge(
        normal,
        AffineConstraints<double>::MergeConflictBehavior::right_object_wins);
      dirichlet_constraints.merge(
        fixed,
        AffineConstraints<double>::MergeConflictBehavior::right_object_wins);
      dirichlet_constraints.close();
      constraints.copy_from(dirichlet_constraints);
    }

    template <int dim>
    void
    ElasticBlock<dim>::add_plate_constraints(
      const types::boundary_id   id,
      AffineConstraints<double> &plate) const
    {
      // The part's normal must be one coordinate axis: its dofs along that
      // axis all follow the first one.
      int                                  axis = -1;
      std::set<types::global_dof_index>    dofs;
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == id)
            {
              const Tensor<1, dim> n = cell->face(f)->center() - cell->center();
              int                  face_axis = 0;
              for (unsigned int d = 1; d < dim; ++d)
                if (std::abs(n[d]) > std::abs(n[face_axis]))
                  face_axis = d;
              AssertThrow(axis < 0 || axis == face_axis,
                          ExcMessage(
                            "Block '" + name +
                            "': a boundary part with Constraint = plate "
                            "must be flat and normal to a coordinate axis."));
              axis = face_axis;
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                if (fe.face_system_to_component_index(i).first ==
                    static_cast<unsigned int>(axis))
                  dofs.insert(face_dofs[i]);
            }
      if (dofs.size() < 2)
        return;
      const types::global_dof_index master = *dofs.begin();
      for (const types::global_dof_index dof : dofs)
        if (dof != master)
          {
            plate.add_line(dof);
            plate.add_entry(dof, master, 1.0);
          }
    }

    template <int dim>
    FullMatrix<double>
    ElasticBlock<dim>::rigid_modes_at_dofs() const
    {
      FullMatrix<double> modes(dof_handler.n_dofs(), n_rigid_modes<dim>);
      for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
        for (unsigned int m = 0; m < n_rigid_modes<dim>; ++m)
          modes(i, m) = rigid_mode(m,
                                   dof_support_points[i],
                                   centre,
                                   length_scale)[dof_components[i]];
      return modes;
    }

    template <int dim>
    void
    ElasticBlock<dim>::find_free_rigid_modes()
    {
      const FullMatrix<double> modes = rigid_modes_at_dofs();
      free_modes = free_rigid_modes(dirichlet_constraints, modes);
      support_dofs.clear();
      constraints.clear();
      constraints.copy_from(dirichlet_constraints);
      if (free_modes.n() == 0)
        return;

      // Candidate support dofs: neither constrained nor on an interface,
      // starting at the node nearest the centroid, then the farthest ones,
      // which gives a well-conditioned pin-and-roller support.
      const std::set<types::boundary_id> interfaces(interface_ids.begin(),
                                                    interface_ids.end());
      const IndexSet                     on_interface =
        interfaces.empty() ? IndexSet(dof_handler.n_dofs()) :
                                                 DoFTools::extract_boundary_dofs(dof_handler,
                                                             ComponentMask(),
                                                             interfaces);
      std::vector<types::global_dof_index> candidates;
      for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
        if (!dirichlet_constraints.is_constrained(i) &&
            !on_interface.is_element(i))
          candidates.push_back(i);
      AssertThrow(!candidates.empty(),
                  ExcMessage("Block '" + name +
                             "': no node is free to hold its rigid modes."));
      const auto nearest =
        *std::min_element(candidates.begin(),
                          candidates.end(),
                          [&](const auto a, const auto b) {
                            return dof_support_points[a].distance(centre) <
                                   dof_support_points[b].distance(centre);
                          });
      const Point<dim> pin = dof_support_points[nearest];
      std::stable_sort(candidates.begin(),
                       candidates.end(),
                       [&](const auto a, const auto b) {
                         const bool a_pin = dof_support_points[a] == pin;
                         const bool b_pin = dof_support_points[b] == pin;
                         if (a_pin != b_pin)
                           return a_pin;
                         return dof_support_points[a].distance(pin) >
                                dof_support_points[b].distance(pin);
                       });
      support_dofs = minimal_support_dofs(free_modes, modes, candidates);
      AssertThrow(support_dofs.size() == free_modes.n(),
                  ExcMessage("Block '" + name +
                             "': cannot find a support that holds its free "
                             "rigid modes."));
      // constraints is a copy of the closed Dirichlet constraints: lines
      // cannot be added to it (close() would return at once and leave them
      // unsorted; deal.II's debug library stops there). Merge them instead.
      AffineConstraints<double> support;
      for (const types::global_dof_index dof : support_dofs)
        support.add_line(dof);
      support.close();
      constraints.merge(support);
    }

    template <int dim>
    Tensor<1, dim>
    ElasticBlock<dim>::free_mode_displacement(const unsigned int k,
                                              const Point<dim>  &x) const
    {
      Tensor<1, dim> u;
      for (unsigned int m = 0; m < n_rigid_modes<dim>; ++m)
        u += free_modes(m, k) * rigid_mode(m, x, centre, length_scale);
      return u;
    }

    template <int dim>
    void
    ElasticBlock<dim>::add_rigid_motion(const Vector<double> &gamma,
                                        Vector<double>       &u) const
    {
      for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
        for (unsigned int k = 0; k < gamma.size(); ++k)
          u[i] +=
            gamma[k] *
            free_mode_displacement(k, dof_support_points[i])[dof_components[i]];
    }

    template <int dim>
    double
    ElasticBlock<dim>::free_mode_load(const unsigned int k) const
    {
      return free_mode_load(k, load_vector);
    }

    template <int dim>
    double
    ElasticBlock<dim>::free_mode_load(const unsigned int    k,
                                      const Vector<double> &nodal_forces) const
    {
      double work = 0;
      for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
        work +=
          nodal_forces[i] *
          free_mode_displacement(k, dof_support_points[i])[dof_components[i]];
      return work;
    }

    template void
    ElasticBlock<2>::setup_constraints(
      const std::map<types::boundary_id, parameters::BoundaryParameters> &,
      const std::vector<types::boundary_id> &);
    template void
    ElasticBlock<2>::find_free_rigid_modes();
    template Tensor<1, 2>
    ElasticBlock<2>::free_mode_displacement(const unsigned int,
                                            const Point<2> &) const;
    template void
    ElasticBlock<2>::add_rigid_motion(const Vector<double> &,
                                      Vector<double> &) const;
    template double
    ElasticBlock<2>::free_mode_load(const unsigned int) const;
    template double
    ElasticBlock<2>::free_mode_load(const unsigned int,
                                    const Vector<double> &) const;
    template void
    ElasticBlock<3>::setup_constraints(
      const std::map<types::boundary_id, parameters::BoundaryParameters> &,
      const std::vector<types::boundary_id> &);
    template void
    ElasticBlock<3>::find_free_rigid_modes();
    template Tensor<1, 3>
    ElasticBlock<3>::free_mode_displacement(const unsigned int,
                                            const Point<3> &) const;
    template void
    ElasticBlock<3>::add_rigid_motion(const Vector<double> &,
                                      Vector<double> &) const;
    template double
    ElasticBlock<3>::free_mode_load(const unsigned int) const;
    template double
    ElasticBlock<3>::free_mode_load(const unsigned int,
                                    const Vector<double> &) const;
  } // namespace blocks
} // namespace fdem
