// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/block_output.h>
#include <fdem/postprocess/interface_vtu.h>
#include <fdem/postprocess/output_files.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fdem
{
  namespace postprocess
  {
    using namespace dealii;

    std::string
    node_status_meaning()
    {
      return "status: 0 stick, 1 slip, 2 open (the pair's status); 3 a node of the interface "
             "without a pair; 4 a node paired on an interface listed before (where two "
             "interfaces meet; its pair is in that interface's file). The pair fields are NaN "
             "at nodes 3 and 4.";
    }

    namespace
    {
      /**
       * Finds points among given ones by position in O(log n): sorted by x,
       * a point is looked for among those within the tolerance in x.
       */
      template <int dim>
      class PointLookup
      {
      public:
        explicit PointLookup(std::vector<Point<dim>> points_in)
          : points(std::move(points_in))
          , order(points.size())
        {
          for (unsigned int i = 0; i < order.size(); ++i)
            order[i] = i;
          std::sort(order.begin(), order.end(), [&](auto a, auto b) {
            return points[a][0] < points[b][0];
          });
        }

        /** Index of the point within @p tolerance of @p x, or -1. */
        int
        find(const Point<dim> &x, const double tolerance) const
        {
          auto it =
            std::lower_bound(order.begin(),
                             order.end(),
                             x[0] - tolerance,
                             [&](const unsigned int i, const double value) {
                               return points[i][0] < value;
                             });
          for (; it != order.end() && points[*it][0] <= x[0] + tolerance; ++it)
            if (points[*it].distance(x) <= tolerance)
              return *it;
          return -1;
        }

      private:
        std::vector<Point<dim>>   points;
        std::vector<unsigned int> order;
      };
    } // namespace

    template <int dim>
    std::string
    write_interface_vtu(const blocks::ElasticBlock<dim>    &block_J,
                        const contact::Interface<dim>      &interface,
                        const std::vector<PairResult<dim>> &results,
                        const std::vector<Point<dim>>      &shared_positions,
                        const Vector<double>               &displacement_J,
                        const Vector<double>               *mechanism_J,
                        const OutputState                  &state,
                        const std::string                  &directory,
                        const std::string                  &suffix)
    {
      const std::string name =
        "interface-" + file_stem(interface.name) + suffix + ".vtu";
      if (Utilities::MPI::this_mpi_process(
            block_J.triangulation.get_communicator()) != 0)
        return name;

      // The faces of block J in the interface's face group, each on the
      // support points of its element: the nodes of the pairs, at which
      // block J's own displacement is evaluated.
      const ReferencePatch<dim - 1>    patch(block_J.element_family.simplex,
                                          block_J.fe.degree);
      FEFaceValues<dim>                fe_values(block_J.mapping,
                                  block_J.fe,
                                  Quadrature<dim - 1>(patch.points),
                                  update_values | update_quadrature_points);
      const FEValuesExtractors::Vector u(0);
      const unsigned int               n = patch.points.size();
      std::vector<Tensor<1, dim>>      values(n), mechanism_values(n);

      std::vector<Point<dim>> pair_positions;
      double                  scale = 0;
      for (const PairResult<dim> &r : results)
        {
          pair_positions.push_back(r.position);
          scale = std::max(scale, r.position.norm());
        }
      const PointLookup<dim> pairs(pair_positions), shared(shared_positions);

      const double        nan = std::numeric_limits<double>::quiet_NaN();
      VtuWriter           writer;
      std::vector<double> u_out, mechanism_out;
      // Per node: normal_force, tangential_force, normal_pressure,
      // shear_stress, gap, slip, local_safety_factor.
      const std::vector<std::string>   names = {"normal_force",
                                                "tangential_force",
                                                "normal_pressure",
                                                "shear_stress",
                                                "gap",
                                                "slip",
                                                "local_safety_factor"};
      std::vector<std::vector<double>> fields(names.size());
      std::vector<std::int32_t>        status, paired;
      for (const auto &cell : block_J.dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == interface.face_group)
            {
              fe_values.reinit(cell, f);
              fe_values[u].get_function_values(displacement_J, values);
              if (mechanism_J != nullptr)
                fe_values[u].get_function_values(*mechanism_J,
                                                 mechanism_values);
              const std::uint64_t first = writer.n_points();
              // Nodes a face apart are far more than this apart.
              const double tolerance =
                1e-9 * (cell->face(f)->diameter() + scale);
              for (unsigned int q = 0; q < n; ++q)
                {
                  const Point<dim> &x = fe_values.quadrature_point(q);
                  writer.add_point(x[0], x[1], dim == 3 ? x[dim - 1] : 0.0);
                  for (unsigned int i = 0; i < 3; ++i)
                    {
                      u_out.push_back(i < dim ? values[q][i] : 0.0);
                      mechanism_out.push_back(i < dim ? mechanism_values[q][i] :
                                                        0.0);
                    }
                  const int k = pairs.find(x, tolerance);
                  if (k < 0)
                    {
                      for (auto &field : fields)
                        field.push_back(nan);
                      status.push_back(static_cast<std::int32_t>(
                        shared.find(x, tolerance) >= 0 ?
                          NodeStatus::paired_elsewhere :
                          NodeStatus::unpaired));
                      paired.push_back(0);
                      continue;
                    }
                  const PairResult<dim> &r = results[k];
                  const double           shear =
                    dim == 2 ? r.tangential_force[0] :
                                         std::hypot(r.tangential_force[0],
                                          r.tangential_force[dim - 2]);
                  const double row[] = {r.normal_force,
                                        shear,
                                        r.normal_pressure,
                                        r.shear_stress,
                                        r.gap,
                                        r.slip,
                                        r.local_safety_factor};
                  for (unsigned int i = 0; i < fields.size(); ++i)
                    fields[i].push_back(row[i]);
                  status.push_back(static_cast<std::int32_t>(r.status));
                  paired.push_back(1);
                }
              for (const auto &[type, nodes] : patch.cells)
                {
                  std::vector<std::uint64_t> global(nodes.size());
                  for (unsigned int i = 0; i < nodes.size(); ++i)
                    global[i] = first + nodes[i];
                  writer.add_cell(type, global);
                }
            }
      writer.add_point_data("displacement", 3, u_out);
      if (mechanism_J != nullptr)
        writer.add_point_data("mechanism_displacement", 3, mechanism_out);
      for (unsigned int i = 0; i < fields.size(); ++i)
        writer.add_point_data_with_blanks(names[i], fields[i]);
      writer.add_point_data("status", status);
      writer.add_point_data("paired", paired);
      add_common_field_data(writer, interface.name, state);
      writer.add_field_data("status_meaning", node_status_meaning());
      writer.write(directory + "/" + name);
      return name;
    }

    template std::string
    write_interface_vtu(const blocks::ElasticBlock<2> &,
                        const contact::Interface<2> &,
                        const std::vector<PairResult<2>> &,
                        const std::vector<Point<2>> &,
                        const Vector<double> &,
                        const Vector<double> *,
                        const OutputState &,
                        const std::string &,
                        const std::string &);
    template std::string
    write_interface_vtu(const blocks::ElasticBlock<3> &,
                        const contact::Interface<3> &,
                        const std::vector<PairResult<3>> &,
                        const std::vector<Point<3>> &,
                        const Vector<double> &,
                        const Vector<double> *,
                        const OutputState &,
                        const std::string &,
                        const std::string &);
  } // namespace postprocess
} // namespace fdem
