// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/newmark.h>
#include <fdem/analyses/seismic.h>
#include <fdem/analyses/yield_acceleration.h>
#include <fdem/postprocess/output_file.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace fdem
{
  namespace analyses
  {
    template <int dim>
    Tensor<1, dim>
    seismic_direction(const Model<dim> &model, std::string &from)
    {
      const parameters::LoadParameters &loads = model.get_parameters().loads;
      Tensor<1, dim>                    g, h;
      for (unsigned int d = 0; d < dim; ++d)
        g[d] = loads.gravity_direction[d];
      if (!loads.seismic_direction.empty())
        {
          for (unsigned int d = 0; d < dim; ++d)
            h[d] = loads.seismic_direction[d];
          from = "given";
          return h;
        }
      // The downslope component of gravity along the sliding surfaces,
      // weighted by the pairs' areas: on a plane the dip direction, on a
      // slip surface the way the mass slides (the steep rear part outweighs
      // the rising toe). Its sign only matters; it rotates with the model.
      double area = 0;
      for (const auto &interface : model.get_interfaces())
        if (model.get_parameters()
              .interfaces.at(interface.name)
              .sliding_surface)
          for (const auto &pair : interface.pairs)
            {
              Tensor<1, dim> n;
              for (unsigned int d = 0; d < dim; ++d)
                n[d] = pair.frame[0][d];
              h += pair.area * (g - (g * n) * n);
              area += pair.area;
            }
      h -= (h * g) * g;
      AssertThrow(
        h.norm() > 1e-8 * area,
        ExcMessage(
          "Loads/Seismic direction: the sliding surfaces have no downslope "
          "direction to point kh towards the free face; give the direction."));
      from = "towards free face";
      return h / h.norm();
    }

    template <int dim>
    void
    set_seismic_load(Model<dim> &model, const SeismicLoad<dim> &load)
    {
      // W (g (1 - kv) + kh h) = gravity + W (kh h - kv g): the assembled
      // load plus the body-force cases with coefficients kh h_d - kv g_d.
      const std::vector<unsigned int> cases =
        model.body_force_cases(load.on_pore_water);
      std::vector<double> coefficients(model.get_mixed_system().n_load_cases(),
                                       0.0);
      for (unsigned int d = 0; d < dim; ++d)
        coefficients[cases[d]] =
          load.kh * load.direction[d] -
          load.kv * model.get_parameters().loads.gravity_direction[d];
      model.set_load_combination(1, coefficients);
    }

    namespace
    {
      bool
      writes_files()
      {
        return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      }

      void
      write_curve_csv(const std::string             &file,
                      const YieldAccelerationResult &yield)
      {
        postprocess::OutputFile out(file);
        out << "kh,K,certified\n" << std::setprecision(12);
        for (const auto &point : yield.curve)
          out << point.kh << ',' << point.K << ',' << (point.certified ? 1 : 0)
              << '\n';
        out.close();
      }

      void
      write_newmark_csv(const std::string &file, const NewmarkResult &newmark)
      {
        postprocess::OutputFile out(file);
        out << "time_s,acceleration_m_s2,velocity_m_s,displacement_m\n"
            << std::setprecision(12);
        for (unsigned int i = 0; i < newmark.time.size(); ++i)
          out << newmark.time[i] << ',' << newmark.acceleration[i] << ','
              << newmark.velocity[i] << ',' << newmark.displacement[i] << '\n';
        out.close();
      }
    } // namespace

    template <int dim>
    SeismicResults
    seismic_analyses(Model<dim> &model)
    {
      const parameters::LoadParameters  &loads = model.get_parameters().loads;
      const YieldAccelerationParameters &yield =
        model.get_parameters().yield_acceleration;
      SeismicResults results;
      results.kh            = loads.horizontal_seismic_coefficient;
      results.kv            = loads.vertical_seismic_coefficient;
      results.on_pore_water = loads.seismic_on_pore_water;
      results.active        = loads.seismic() || yield.compute;
      if (!results.active)
        return results;
      // The record is read first: a bad file is an error before any work.
      AccelerationRecord record;
      if (!yield.acceleration_record.empty())
        record = read_acceleration_record(yield.acceleration_record,
                                          yield.acceleration_unit);
      SeismicLoad<dim> load;
      load.kv            = results.kv;
      load.on_pore_water = results.on_pore_water;
      load.direction     = seismic_direction(model, results.direction_from);
      for (unsigned int d = 0; d < dim; ++d)
        results.direction.push_back(load.direction[d]);
      model.brief << "Seismic load: kh = " << results.kh << " towards ("
                  << load.direction << "), " << results.direction_from
                  << "; kv = " << results.kv << " (positive upwards)"
                  << std::endl;
      if (yield.compute)
        {
          results.yield = yield_acceleration(model, load, yield);
          const std::string directory =
            model.get_parameters().output_directory();
          if (writes_files() && std::filesystem::is_directory(directory))
            write_curve_csv(directory + "/yield_acceleration.csv",
                            results.yield);
          if (!yield.acceleration_record.empty())
            {
              results.newmark =
                newmark_displacement(record,
                                     results.yield.k_y,
                                     yield.two_directional ?
                                       results.yield.k_y_backward :
                                       std::numeric_limits<double>::infinity());
              results.newmark.record = yield.acceleration_record;
              results.newmark.unit   = yield.acceleration_unit;
              results.newmark.mode =
                yield.two_directional ? "two-directional" : "one-directional";
              if (writes_files() && std::filesystem::is_directory(directory) &&
                  results.newmark.computed)
                write_newmark_csv(directory + "/newmark.csv", results.newmark);
              if (results.newmark.computed)
                model.brief << "Newmark displacement (" << results.newmark.mode
                            << "): " << std::setprecision(4)
                            << results.newmark.max_displacement << " m"
                            << std::endl;
            }
        }
      // The load the safety factor is asked for.
      load.kh = results.kh;
      set_seismic_load(model, load);
      model.forget_warm_start();
      return results;
    }

    template Tensor<1, 2>
    seismic_direction(const Model<2> &, std::string &);
    template Tensor<1, 3>
    seismic_direction(const Model<3> &, std::string &);
    template void
    set_seismic_load(Model<2> &, const SeismicLoad<2> &);
    template void
    set_seismic_load(Model<3> &, const SeismicLoad<3> &);
    template SeismicResults
    seismic_analyses(Model<2> &);
    template SeismicResults
    seismic_analyses(Model<3> &);
  } // namespace analyses
} // namespace fdem
