// The plate scene's VTU/PVD output, in its own translation unit: DataOut is
// the slowest deal.II header to compile.
#include <unilateral/base/input_error.h>
#include <unilateral/base/output_file.h>
#include <unilateral/scenes/plate/bending.h>
#include <unilateral/scenes/plate/plate_scene.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace unilateral::plate
{
  namespace
  {
    /**
     * Fields derived from the deflection w (exactly represented in FE_Q(3),
     * so its derivatives inside a cell are exact): the slope (w_x, w_y), the
     * obstacle psi and the gap w - psi at the output points themselves (psi
     * evaluated there, not interpolated), and the bending moments of
     * bending.h (per cell: they jump across cell edges).
     */
    class DerivedFields : public dealii::DataPostprocessor<2>
    {
    public:
      DerivedFields(const dealii::Function<2, double> *obstacle,
                    const double                       rigidity,
                    const double                       poisson_ratio)
        : obstacle(obstacle)
        , rigidity(rigidity)
        , poisson_ratio(poisson_ratio)
      {}

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names = {"slope", "slope"};
        if (obstacle != nullptr)
          names.insert(names.end(), {"obstacle", "gap"});
        names.insert(names.end(),
                     {"bending_moment_xx",
                      "bending_moment_yy",
                      "bending_moment_xy"});
        return names;
      }

      std::vector<
        dealii::DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        using namespace dealii::DataComponentInterpretation;
        std::vector<DataComponentInterpretation> interpretation(
          get_names().size(), component_is_scalar);
        interpretation[0] = interpretation[1] = component_is_part_of_vector;
        return interpretation;
      }

      dealii::UpdateFlags
      get_needed_update_flags() const override
      {
        return dealii::update_values | dealii::update_gradients |
               dealii::update_hessians | dealii::update_quadrature_points;
      }

      void
      evaluate_scalar_field(
        const dealii::DataPostprocessorInputs::Scalar<2> &inputs,
        std::vector<dealii::Vector<double>> &computed) const override
      {
        for (unsigned int q = 0; q < computed.size(); ++q)
          {
            unsigned int c   = 0;
            computed[q](c++) = inputs.solution_gradients[q][0];
            computed[q](c++) = inputs.solution_gradients[q][1];
            if (obstacle != nullptr)
              {
                const double psi = obstacle->value(inputs.evaluation_points[q]);
                computed[q](c++) = psi;
                computed[q](c++) = inputs.solution_values[q] - psi;
              }
            for (const double moment : bending_moments(
                   inputs.solution_hessians[q], rigidity, poisson_ratio))
              computed[q](c++) = moment;
          }
      }

    private:
      const dealii::Function<2, double> *obstacle;
      const double                       rigidity;
      const double                       poisson_ratio;
    };

    /// name.vtu, written by @p write_vtu (given the VTK flags and the
    /// file), and name.pvd, which refers to it.
    template <typename Writer>
    void
    write_vtu_and_pvd(const Writer                &write_vtu,
                      const std::filesystem::path &directory,
                      const std::string           &name)
    {
      // deal.II's default zlib level (best compression) made writing the
      // file most of a run on meshes of 90 x 90 and up; the masonry scene
      // writes with the fastest level too.
      dealii::DataOutBase::VtkFlags flags;
      flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
      const std::string vtu   = name + ".vtu";
      {
        std::ofstream file(directory / vtu);
        if (!file)
          throw InputError("cannot write '" + (directory / vtu).string() + "'");
        write_vtu(flags, file);
        close_written_file(file, (directory / vtu).string());
      }
      const std::filesystem::path record = directory / (name + ".pvd");
      std::ofstream               pvd(record);
      if (!pvd)
        throw InputError("cannot write '" + record.string() + "'");
      dealii::DataOutBase::write_pvd_record(pvd, {{0.0, vtu}});
      close_written_file(pvd, record.string());
    }
  } // namespace

  /**
   * plate.vtu: the bicubic deflection, interpolated into FE_Q(3) on the same
   * mesh. Q3 contains the bicubics, and the interpolant at Q3's support
   * points reproduces a bicubic exactly, so what ParaView shows is the BFS
   * field itself, sampled at (Subdivisions + 1)^2 points per cell.
   *
   * nodes.vtu: the LCP at the mesh nodes, one point (a vertex cell) per
   * node: w, w_x, w_y, w_xy, psi, gap, contact (0/1) and the contact force
   * lambda (kg, zero off J1).
   */
  void
  PlateScene::output_results(const RunContext &context) const
  {
    const std::vector<unsigned int> bfs_index =
      fe::bfs_local_indices(dof_handler.get_fe());

    // The deflection in FE_Q(3).
    const dealii::FE_Q<2> fe_cubic(3);
    dealii::DoFHandler<2> cubic_dofs(triangulation);
    cubic_dofs.distribute_dofs(fe_cubic);
    dealii::Vector<double> deflection(cubic_dofs.n_dofs());
    {
      const std::vector<dealii::Point<2>> &unit_points =
        fe_cubic.get_unit_support_points();
      std::vector<dealii::types::global_dof_index> cubic_local(
        fe_cubic.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const fe::BognerFoxSchmit element = cell_element(cell);
          const auto                coefficients =
            cell_coefficients(cell, bfs_index, dof_values);
          const dealii::DoFHandler<2>::active_cell_iterator cubic_cell(
            &triangulation, cell->level(), cell->index(), &cubic_dofs);
          cubic_cell->get_dof_indices(cubic_local);
          for (unsigned int k = 0; k < unit_points.size(); ++k)
            {
              const dealii::Point<2> x(element.vertex(0)[0] +
                                         unit_points[k][0] * element.size(0),
                                       element.vertex(0)[1] +
                                         unit_points[k][1] * element.size(1));
              deflection[cubic_local[k]] = element.value(coefficients, x);
            }
        }
    }

    {
      const DerivedFields derived(obstacle.get(),
                                  rigidity,
                                  parameters.material.poisson_ratio);
      dealii::DataOut<2>  data_out;
      data_out.attach_dof_handler(cubic_dofs);
      data_out.add_data_vector(deflection, "deflection");
      data_out.add_data_vector(deflection, derived);
      data_out.build_patches(parameters.output.subdivisions);
      write_vtu_and_pvd(
        [&](const dealii::DataOutBase::VtkFlags &flags, std::ostream &file) {
          data_out.set_flags(flags);
          data_out.write_vtu(file);
        },
        context.output_directory,
        "plate");
    }

    // Nodal quantities, vertex by vertex; one point per vertex (a patch of
    // dimension 0 each), so that counts and sums over the points in
    // ParaView are the nodes' (a DataOut on the mesh repeats each node in
    // every cell around it: four times the contact force, a review).
    std::vector<std::string> names = {"deflection",
                                      "slope_x",
                                      "slope_y",
                                      "twist"};
    if (obstacle != nullptr)
      names.insert(names.end(), {"obstacle", "gap"});
    names.insert(names.end(), {"contact", "contact_force"});
    std::vector<double> force_at_vertex(triangulation.n_vertices(), 0.0);
    std::vector<char>   contact_at_vertex(triangulation.n_vertices(), 0);
    {
      std::vector<char> active(lcp_problem.size(), 0);
      for (const lcp::Index i : lcp_solution.active_set)
        active[i] = 1;
      for (std::size_t k = 0; k < bound_vertex.size(); ++k)
        {
          const lcp::Index i = lcp_problem.constrained[k];
          // An open node carries no force: its multiplier is the round-off
          // of A u - b (1e-13 kg, a review), as in the masonry output.
          force_at_vertex[bound_vertex[k]] =
            active[i] ? lcp_solution.lambda[i] * unit : 0.0;
          contact_at_vertex[bound_vertex[k]] = active[i];
        }
    }
    std::vector<char> written(triangulation.n_vertices(), 0);
    std::vector<dealii::DataOutBase::Patch<0, 2>> patches;
    patches.reserve(triangulation.n_used_vertices());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const auto coefficients =
          cell_coefficients(cell, bfs_index, dof_values);
        for (unsigned int v = 0; v < 4; ++v)
          {
            const unsigned int vertex = cell->vertex_index(v);
            if (written[vertex])
              continue;
            written[vertex]            = 1;
            using Element              = fe::BognerFoxSchmit;
            std::vector<double> values = {
              coefficients[Element::local_index(v, Element::deflection)],
              coefficients[Element::local_index(v, Element::slope_x)],
              coefficients[Element::local_index(v, Element::slope_y)],
              coefficients[Element::local_index(v, Element::twist)]};
            if (obstacle != nullptr)
              {
                const double psi = obstacle->value(cell->vertex(v));
                values.insert(values.end(), {psi, values[0] - psi});
              }
            values.insert(values.end(),
                          {static_cast<double>(contact_at_vertex[vertex]),
                           force_at_vertex[vertex]});
            dealii::DataOutBase::Patch<0, 2> patch;
            patch.vertices[0] = cell->vertex(v);
            patch.patch_index = static_cast<unsigned int>(patches.size());
            patch.data.reinit(values.size(), 1);
            for (unsigned int c = 0; c < values.size(); ++c)
              patch.data(c, 0) = static_cast<float>(values[c]);
            patches.push_back(std::move(patch));
          }
      }
    write_vtu_and_pvd(
      [&](const dealii::DataOutBase::VtkFlags &flags, std::ostream &file) {
        dealii::DataOutBase::write_vtu(patches, names, {}, flags, file);
      },
      context.output_directory,
      "nodes");
  }
} // namespace unilateral::plate
