// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/block_output.h>
#include <fdem/postprocess/output_files.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

namespace fdem
{
  namespace postprocess
  {
    using namespace dealii;

    template <int celldim>
    ReferencePatch<celldim>::ReferencePatch(const bool         simplex,
                                            const unsigned int degree)
    {
      AssertThrow(degree == 1 || degree == 2, ExcNotImplemented());
      using C = VtuWriter;
      if (!simplex || celldim == 1)
        {
          // The (degree + 1)^celldim grid, x fastest, cut into linear cells.
          const unsigned int n        = degree + 1;
          unsigned int       n_points = 1;
          for (unsigned int d = 0; d < celldim; ++d)
            n_points *= n;
          for (unsigned int i = 0; i < n_points; ++i)
            {
              Point<celldim> p;
              for (unsigned int d = 0, k = i; d < celldim; ++d, k /= n)
                p[d] = static_cast<double>(k % n) / degree;
              points.push_back(p);
            }
          const auto index = [n](const unsigned int i,
                                 const unsigned int j,
                                 const unsigned int k) {
            return i + n * (j + n * k);
          };
          for (unsigned int k = 0; k < (celldim > 2 ? degree : 1); ++k)
            for (unsigned int j = 0; j < (celldim > 1 ? degree : 1); ++j)
              for (unsigned int i = 0; i < degree; ++i)
                {
                  if (celldim == 1)
                    cells.push_back(
                      {C::vtk_line, {index(i, 0, 0), index(i + 1, 0, 0)}});
                  else if (celldim == 2)
                    cells.push_back({C::vtk_quad,
                                     {index(i, j, 0),
                                      index(i + 1, j, 0),
                                      index(i + 1, j + 1, 0),
                                      index(i, j + 1, 0)}});
                  else
                    cells.push_back({C::vtk_hexahedron,
                                     {index(i, j, k),
                                      index(i + 1, j, k),
                                      index(i + 1, j + 1, k),
                                      index(i, j + 1, k),
                                      index(i, j, k + 1),
                                      index(i + 1, j, k + 1),
                                      index(i + 1, j + 1, k + 1),
                                      index(i, j + 1, k + 1)}});
                }
          return;
        }
      // Simplices: the vertices, then (degree 2) the midpoints of the edges
      // in deal.II's order, which is VTK's for quadratic triangles (01, 12,
      // 20) and tetrahedra (01, 12, 20, 03, 13, 23).
      for (unsigned int v = 0; v <= celldim; ++v)
        {
          Point<celldim> p;
          if (v > 0)
            p[v - 1] = 1;
          points.push_back(p);
        }
      std::vector<std::pair<unsigned int, unsigned int>> edges = {{0, 1},
                                                                  {1, 2},
                                                                  {2, 0}};
      if (celldim == 3)
        edges.insert(edges.end(), {{0, 3}, {1, 3}, {2, 3}});
      if (degree == 2)
        for (const auto &[a, b] : edges)
          points.push_back(Point<celldim>((points[a] + points[b]) / 2));
      std::vector<unsigned int> nodes(points.size());
      for (unsigned int i = 0; i < nodes.size(); ++i)
        nodes[i] = i;
      cells.push_back(
        {celldim == 2 ?
           (degree == 2 ? C::vtk_quadratic_triangle : C::vtk_triangle) :
           (degree == 2 ? C::vtk_quadratic_tetra : C::vtk_tetra),
         nodes});
    }

    template <int dim>
    std::string
    write_block_vtu(const blocks::ElasticBlock<dim> &block,
                    const unsigned int               block_index,
                    const Vector<double>            &displacement,
                    const Vector<double>            *mechanism,
                    const OutputState               &state,
                    const std::string               &directory,
                    const std::string               &suffix)
    {
      const std::string name =
        "block-" + file_stem(block.name) + suffix + ".vtu";
      if (Utilities::MPI::this_mpi_process(
            block.triangulation.get_communicator()) != 0)
        return name;

      const ReferencePatch<dim>        patch(block.element_family.simplex,
                                      block.fe.degree);
      FEValues<dim>                    fe_values(block.mapping,
                              block.fe,
                              Quadrature<dim>(patch.points),
                              update_values | update_gradients |
                                update_quadrature_points);
      const FEValuesExtractors::Vector u(0);
      const unsigned int               n = patch.points.size();
      std::vector<Tensor<1, dim>>      values(n), mechanism_values(n);
      std::vector<Tensor<2, dim>>      gradients(n);

      VtuWriter                 writer;
      std::vector<double>       u_out, mechanism_out, stress_out, stress_zz;
      std::vector<std::int32_t> block_id;
      for (const auto &cell : block.dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_values(displacement, values);
          fe_values[u].get_function_gradients(displacement, gradients);
          if (mechanism != nullptr)
            fe_values[u].get_function_values(*mechanism, mechanism_values);
          const parameters::MaterialParameters &m =
            block.materials.at(cell->material_id());
          const double E = m.youngs_modulus, nu = m.poissons_ratio;
          const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
          const double mu     = E / (2 * (1 + nu));

          const std::uint64_t first = writer.n_points();
          for (unsigned int q = 0; q < n; ++q)
            {
              const Point<dim> &x = fe_values.quadrature_point(q);
              writer.add_point(x[0], x[1], dim == 3 ? x[dim - 1] : 0.0);
              const Tensor<2, dim> strain =
                0.5 * (gradients[q] + transpose(gradients[q]));
              const Tensor<2, dim> stress =
                lambda * trace(strain) * unit_symmetric_tensor<dim>() +
                2 * mu * strain;
              for (unsigned int i = 0; i < 3; ++i)
                {
                  u_out.push_back(i < dim ? values[q][i] : 0.0);
                  mechanism_out.push_back(i < dim ? mechanism_values[q][i] :
                                                    0.0);
                }
              // Plane strain: eps_zz = 0 and sigma_zz = lambda tr(eps), in
              // the tensor so that its invariants (ParaView's magnitude, a
              // von Mises filter) are right.
              const double zz =
                dim == 2 ? lambda * trace(strain) : stress[dim - 1][dim - 1];
              for (unsigned int i = 0; i < 3; ++i)
                for (unsigned int j = 0; j < 3; ++j)
                  stress_out.push_back(i < dim && j < dim ?
                                         stress[i][j] :
                                         (i == 2 && j == 2 ? zz : 0.0));
              stress_zz.push_back(zz);
            }
          for (const auto &[type, nodes] : patch.cells)
            {
              std::vector<std::uint64_t> global(nodes.size());
              for (unsigned int i = 0; i < nodes.size(); ++i)
                global[i] = first + nodes[i];
              writer.add_cell(type, global);
              block_id.push_back(block_index);
            }
        }
      writer.add_point_data("displacement", 3, u_out);
      if (mechanism != nullptr)
        writer.add_point_data("mechanism_displacement", 3, mechanism_out);
      writer.add_point_data("stress", 9, stress_out, true);
      writer.add_point_data("stress_zz", 1, stress_zz, true);
      writer.add_cell_data("block_id", block_id);
      add_common_field_data(writer, block.name, state);
      writer.write(directory + "/" + name);
      return name;
    }

    template struct ReferencePatch<1>;
    template struct ReferencePatch<2>;
    template struct ReferencePatch<3>;
    template std::string
    write_block_vtu(const blocks::ElasticBlock<2> &,
                    const unsigned int,
                    const Vector<double> &,
                    const Vector<double> *,
                    const OutputState &,
                    const std::string &,
                    const std::string &);
    template std::string
    write_block_vtu(const blocks::ElasticBlock<3> &,
                    const unsigned int,
                    const Vector<double> &,
                    const Vector<double> *,
                    const OutputState &,
                    const std::string &,
                    const std::string &);
  } // namespace postprocess
} // namespace fdem
