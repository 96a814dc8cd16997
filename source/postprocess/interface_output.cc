// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/interface_output.h>
#include <fdem/postprocess/output_files.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/data_out.h>

#include <fstream>
#include <iomanip>

namespace fdem
{
  namespace postprocess
  {
    using namespace dealii;

    template <int dim>
    std::vector<PairResult<dim>>
    pair_results(const contact::Interface<dim> &         interface,
                 const unsigned int                      first_pair,
                 const contact::ContactSolution &           solution,
                 const std::vector<contact::PairState<dim>> &states)
    {
      std::vector<PairResult<dim>> results;
      for (unsigned int k = 0; k < interface.pairs.size(); ++k)
        {
          const contact::NodePair<dim> &pair = interface.pairs[k];
          const unsigned int            p    = first_pair + k;
          PairResult<dim>               r;
          r.position     = pair.position_J;
          r.normal_force = solution.forces[dim * p];
          double shear2 = 0, slip2 = 0;
          for (unsigned int i = 0; i + 1 < dim; ++i)
            {
              r.tangential_force[i] = solution.forces[dim * p + 1 + i];
              shear2 += r.tangential_force[i] * r.tangential_force[i];
              slip2 += std::pow(solution.relative_displacements[dim * p + 1 + i], 2);
            }
          r.normal_pressure = -r.normal_force / pair.area;
          r.shear_stress    = std::sqrt(shear2) / pair.area;
          r.gap             = solution.relative_displacements[dim * p];
          r.slip            = dim == 2 ? solution.relative_displacements[dim * p + 1] :
                                         std::sqrt(slip2);
          r.status          = states[p].status;
          r.area            = pair.area;
          r.initial_gap     = pair.initial_gap;
          results.push_back(r);
        }
      return results;
    }

    template <int dim>
    void
    write_interface_csv(const std::string &                              filename,
                        const std::vector<contact::Interface<dim>> &      interfaces,
                        const std::vector<std::vector<PairResult<dim>>> &results)
    {
      std::ofstream out(filename);
      AssertThrow(out.good(), ExcMessage("Cannot write '" + filename + "'."));
      out << "interface,pair,x,y" << (dim == 3 ? ",z" : "") << ",normal_force,"
          << (dim == 2 ? "tangential_force" : "tangential_force_1,tangential_force_2")
          << ",normal_pressure,shear_stress,gap,slip,status,area,initial_gap\n";
      out << std::setprecision(12);
      for (unsigned int i = 0; i < interfaces.size(); ++i)
        for (unsigned int k = 0; k < results[i].size(); ++k)
          {
            const PairResult<dim> &r = results[i][k];
            out << '"' << interfaces[i].name << "\"," << k;
            for (unsigned int d = 0; d < dim; ++d)
              out << ',' << r.position[d];
            out << ',' << r.normal_force;
            for (const double f : r.tangential_force)
              out << ',' << f;
            out << ',' << r.normal_pressure << ',' << r.shear_stress << ','
                << r.gap << ',' << r.slip << ',' << contact::status_name(r.status) << ','
                << r.area << ',' << r.initial_gap << '\n';
          }
    }

    template <int dim>
    std::string
    write_interface_vtu(const blocks::ElasticBlock<dim> &   block_J,
                        const contact::Interface<dim> &     interface,
                        const std::vector<PairResult<dim>> &results,
                        const std::string &                 directory,
                        const std::string &                 suffix)
    {
      // The interface as a mesh of dimension dim-1 cut from block J.
      Triangulation<dim - 1, dim> surface;
      GridGenerator::extract_boundary_mesh(block_J.triangulation,
                                           surface,
                                           {interface.face_group});
      const FE_Q<dim - 1, dim> fe(block_J.fe.degree);
      DoFHandler<dim - 1, dim> dof_handler(surface);
      dof_handler.distribute_dofs(fe);
      const MappingQ<dim - 1, dim> mapping(1);
      std::vector<Point<dim>>      support_points(dof_handler.n_dofs());
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, support_points);

      const std::vector<std::string> names = {"normal_force",
                                              "tangential_force",
                                              "normal_pressure",
                                              "shear_stress",
                                              "gap",
                                              "slip",
                                              "status",
                                              "paired"};
      std::vector<Vector<double>> fields(names.size(),
                                         Vector<double>(dof_handler.n_dofs()));
      for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
        for (const PairResult<dim> &r : results)
          if (r.position.distance(support_points[i]) <=
              1e-9 * (r.area + r.position.norm()))
            {
              double shear = 0;
              for (const double f : r.tangential_force)
                shear += f * f;
              fields[0][i] = r.normal_force;
              fields[1][i] = dim == 2 ? r.tangential_force[0] : std::sqrt(shear);
              fields[2][i] = r.normal_pressure;
              fields[3][i] = r.shear_stress;
              fields[4][i] = r.gap;
              fields[5][i] = r.slip;
              // 0 stick, 1 slip, 2 open.
              fields[6][i] = static_cast<double>(r.status);
              fields[7][i] = 1;
              break;
            }

      DataOut<dim - 1, dim> data_out;
      data_out.attach_dof_handler(dof_handler);
      for (unsigned int f = 0; f < names.size(); ++f)
        data_out.add_data_vector(fields[f], names[f]);
      data_out.build_patches(mapping, fe.degree);
      const std::string name = "interface-" + file_stem(interface.name) + suffix + ".vtu";
      std::ofstream     out(directory + "/" + name);
      AssertThrow(out.good(), ExcMessage("Cannot write '" + directory + "/" + name + "'."));
      data_out.write_vtu(out);
      return name;
    }

#define FDEM_INSTANTIATE(dim)                                                   \
  template std::vector<PairResult<dim>> pair_results(                           \
    const contact::Interface<dim> &, const unsigned int,                        \
    const contact::ContactSolution &, const std::vector<contact::PairState<dim>> &); \
  template void write_interface_csv(const std::string &,                        \
                                    const std::vector<contact::Interface<dim>> &, \
                                    const std::vector<std::vector<PairResult<dim>>> &); \
  template std::string write_interface_vtu(const blocks::ElasticBlock<dim> &,   \
                                           const contact::Interface<dim> &,     \
                                           const std::vector<PairResult<dim>> &, \
                                           const std::string &,                 \
                                           const std::string &);
    FDEM_INSTANTIATE(2)
    FDEM_INSTANTIATE(3)
#undef FDEM_INSTANTIATE
  } // namespace postprocess
} // namespace fdem
