// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/block_output.h>
#include <fdem/postprocess/output_files.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fstream>

namespace fdem
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      /** Cauchy stress from the displacement gradient, per material. */
      template <int dim>
      class StressPostprocessor : public DataPostprocessor<dim>
      {
      public:
        explicit StressPostprocessor(
          const std::map<unsigned int, parameters::MaterialParameters> &materials)
          : materials(materials)
        {}

        void
        evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                              std::vector<Vector<double>> &computed) const override
        {
          const auto cell = inputs.template get_cell<dim>();
          const parameters::MaterialParameters &m = materials.at(cell->material_id());
          const double E = m.youngs_modulus, nu = m.poissons_ratio;
          const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
          const double mu     = E / (2 * (1 + nu));
          for (unsigned int q = 0; q < computed.size(); ++q)
            {
              Tensor<2, dim> grad;
              for (unsigned int d = 0; d < dim; ++d)
                grad[d] = inputs.solution_gradients[q][d];
              const Tensor<2, dim> strain = 0.5 * (grad + transpose(grad));
              const Tensor<2, dim> stress =
                lambda * trace(strain) * unit_symmetric_tensor<dim>() + 2 * mu * strain;
              unsigned int k = 0;
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  computed[q][k++] = stress[i][j];
              // Plane strain: sigma_zz = lambda tr(eps); in 3D it is listed above.
              computed[q][k] = (dim == 2 ? lambda * trace(strain) : stress[dim - 1][dim - 1]);
            }
        }

        std::vector<std::string>
        get_names() const override
        {
          std::vector<std::string> names(dim * dim, "stress");
          names.push_back("stress_zz");
          return names;
        }

        std::vector<DataComponentInterpretation::DataComponentInterpretation>
        get_data_component_interpretation() const override
        {
          std::vector<DataComponentInterpretation::DataComponentInterpretation>
            interpretation(dim * dim,
                           DataComponentInterpretation::component_is_part_of_tensor);
          interpretation.push_back(DataComponentInterpretation::component_is_scalar);
          return interpretation;
        }

        UpdateFlags
        get_needed_update_flags() const override
        {
          return update_gradients;
        }

      private:
        const std::map<unsigned int, parameters::MaterialParameters> &materials;
      };
    } // namespace

    template <int dim>
    std::string
    write_block_vtu(const blocks::ElasticBlock<dim> &block,
                    const unsigned int               block_index,
                    const Vector<double> &           displacement,
                    const std::string &              directory,
                    const std::string &              suffix)
    {
      const StressPostprocessor<dim> stress(block.materials);
      DataOut<dim>                   data_out;
      data_out.attach_dof_handler(block.dof_handler);
      // All cells, not only this rank's: the block's triangulation is
      // shared, and rank 0 writes the whole block.
      data_out.set_cell_selection(
        [](const typename Triangulation<dim>::cell_iterator &cell) { return cell->is_active(); });
      const std::vector<DataComponentInterpretation::DataComponentInterpretation>
        vector_field(dim, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(displacement,
                               std::vector<std::string>(dim, "displacement"),
                               DataOut<dim>::type_dof_data,
                               vector_field);
      data_out.add_data_vector(displacement, stress);
      Vector<float> block_id(block.triangulation.n_active_cells());
      block_id = static_cast<float>(block_index);
      data_out.add_data_vector(block_id, "block_id");
      data_out.build_patches(block.mapping, block.fe.degree);

      // Rank 0 writes: add_data_vector() above is collective on a shared
      // triangulation (it makes a ghosted vector), so every rank comes here.
      const std::string name = "block-" + file_stem(block.name) + suffix + ".vtu";
      if (Utilities::MPI::this_mpi_process(block.triangulation.get_communicator()) != 0)
        return name;
      std::ofstream     out(directory + "/" + name);
      AssertThrow(out.good(), ExcMessage("Cannot write '" + directory + "/" + name + "'."));
      data_out.write_vtu(out);
      return name;
    }

    template std::string
    write_block_vtu(const blocks::ElasticBlock<2> &, const unsigned int,
                    const Vector<double> &, const std::string &, const std::string &);
    template std::string
    write_block_vtu(const blocks::ElasticBlock<3> &, const unsigned int,
                    const Vector<double> &, const std::string &, const std::string &);
  } // namespace postprocess
} // namespace fdem
