#include <unilateral/base/input_error.h>

#include "scene_state.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    /**
     * Stress from the displacement gradient, cell by cell with the cell's
     * material (plane strain): the tensor sigma = lambda tr(eps) I + 2 mu eps
     * and the von Mises stress, with sigma_zz = lambda tr(eps) included.
     */
    class StressPostprocessor : public dealii::DataPostprocessor<2>
    {
    public:
      StressPostprocessor(const std::vector<MaterialClass> &classes,
                          const std::vector<unsigned int>  &class_of_block)
        : classes(classes)
        , class_of_block(class_of_block)
      {}

      void
      evaluate_vector_field(
        const dealii::DataPostprocessorInputs::Vector<2> &inputs,
        std::vector<dealii::Vector<double>> &computed_quantities) const override
      {
        const auto           cell = inputs.template get_cell<2>();
        const MaterialClass &material =
          classes[class_of_block[cell->material_id()]];
        const double lambda = material.lambda();
        const double mu     = material.mu();
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            const auto  &grad  = inputs.solution_gradients[q];
            const double e_xx  = grad[0][0];
            const double e_yy  = grad[1][1];
            const double e_xy  = 0.5 * (grad[0][1] + grad[1][0]);
            const double trace = e_xx + e_yy;
            const double s_xx  = lambda * trace + 2 * mu * e_xx;
            const double s_yy  = lambda * trace + 2 * mu * e_yy;
            const double s_xy  = 2 * mu * e_xy;
            const double s_zz  = lambda * trace;
            const double von_mises =
              std::sqrt(0.5 * ((s_xx - s_yy) * (s_xx - s_yy) +
                               (s_yy - s_zz) * (s_yy - s_zz) +
                               (s_zz - s_xx) * (s_zz - s_xx)) +
                        3 * s_xy * s_xy);
            dealii::Vector<double> &out = computed_quantities[q];
            out[0]                      = s_xx;
            out[1]                      = s_xy;
            out[2]                      = s_xy;
            out[3]                      = s_yy;
            out[4]                      = von_mises;
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"stress", "stress", "stress", "stress", "von_mises"};
      }

      std::vector<
        dealii::DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        using namespace dealii::DataComponentInterpretation;
        return {component_is_part_of_tensor,
                component_is_part_of_tensor,
                component_is_part_of_tensor,
                component_is_part_of_tensor,
                component_is_scalar};
      }

      dealii::UpdateFlags
      get_needed_update_flags() const override
      {
        return dealii::update_gradients;
      }

    private:
      const std::vector<MaterialClass> &classes;
      const std::vector<unsigned int>  &class_of_block;
    };
  } // namespace

  /*
   * The VTU/PVD output. Point data: displacement (a vector, for ParaView's
   * Warp By Vector), the stress tensor and von Mises stress, and at the
   * contact nodes the contact pressure, the normal gap and the active set
   * (zero elsewhere). Cell data: block id (= deal.II material_id) and
   * material class.
   *
   * The nodal fields live on a scalar quadratic element with the same nodes.
   * A node's pressure in a normal direction is the sum of its constraint
   * forces in that direction divided by its Simpson weight on its contact
   * faces with that normal (h/6 at a face end, 2h/3 at a midpoint), which is
   * exact for a uniform pressure. A block corner can carry a horizontal and
   * a vertical joint: there the output shows the larger pressure, the
   * smaller gap, and "active" if either constraint is.
   */
  void
  MasonryScene::output_results(const RunContext &context) const
  {
    context.stage(registered_name, "writing VTU/PVD");
    const Discretisation &discretisation = state->discretisation;
    const ContactSet     &contacts       = state->contacts;
    const auto            n_dofs         = discretisation.dof_handler.n_dofs();

    // Per physical DOF (a node and a normal direction): summed force,
    // smallest gap, any active, from the constraints acting on it.
    std::vector<double> force(n_dofs, 0.0);
    std::vector<double> gap(n_dofs, std::numeric_limits<double>::max());
    std::vector<char>   active(n_dofs, 0), constrained(n_dofs, 0);
    for (std::size_t k = 0; k < constraints.size(); ++k)
      {
        auto add = [&](const DofIndex dof) {
          force[dof] += constraints[k].contact_force;
          gap[dof]         = std::min(gap[dof], constraints[k].normal_gap);
          active[dof]      = active[dof] || constraints[k].active;
          constrained[dof] = 1;
        };
        const UnilateralConstraint &c = contacts.constraints[k];
        add(c.lower);
        if (c.kind != ConstraintKind::signorini)
          add(c.upper);
      }

    dealii::DoFHandler<2> node_handler(discretisation.triangulation);
    node_handler.distribute_dofs(*discretisation.scalar_fe);
    dealii::Vector<double> contact_pressure(node_handler.n_dofs());
    dealii::Vector<double> normal_gap(node_handler.n_dofs());
    dealii::Vector<double> active_set(node_handler.n_dofs());
    {
      const dealii::FiniteElement<2> &fe = *discretisation.fe;
      const unsigned int n_nodes = discretisation.scalar_fe->n_dofs_per_cell();
      std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::vector<dealii::types::global_dof_index> nodes(n_nodes);
      auto node_cell = node_handler.begin_active();
      for (const auto &cell :
           discretisation.dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          node_cell->get_dof_indices(nodes);
          ++node_cell;
          for (unsigned int k = 0; k < n_nodes; ++k)
            {
              double pressure = 0, smallest_gap = 0;
              bool   any = false, is_active = false;
              for (unsigned int d = 0; d < 2; ++d)
                {
                  const auto dof = dofs[fe.component_to_system_index(d, k)];
                  if (!constrained[dof])
                    continue;
                  const double weight = contacts.contact_weight[dof];
                  const double p      = weight > 0 ? force[dof] / weight : 0.0;
                  pressure            = any ? std::max(pressure, p) : p;
                  smallest_gap =
                    any ? std::min(smallest_gap, gap[dof]) : gap[dof];
                  is_active = is_active || active[dof];
                  any       = true;
                }
              contact_pressure[nodes[k]] = pressure;
              normal_gap[nodes[k]]       = smallest_gap;
              active_set[nodes[k]]       = is_active ? 1.0 : 0.0;
            }
        }
    }

    dealii::Vector<double> displacement(state->displacement.begin(),
                                        state->displacement.end());

    StressPostprocessor stress(parameters.materials.classes,
                               state->class_of_block);
    dealii::DataOut<2>  data_out;
    data_out.attach_triangulation(discretisation.triangulation);
    data_out.add_data_vector(
      discretisation.dof_handler,
      displacement,
      std::vector<std::string>{"displacement", "displacement"},
      std::vector<
        dealii::DataComponentInterpretation::DataComponentInterpretation>(
        2, dealii::DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(discretisation.dof_handler, displacement, stress);
    data_out.add_data_vector(node_handler,
                             contact_pressure,
                             "contact_pressure");
    data_out.add_data_vector(node_handler, normal_gap, "normal_gap");
    data_out.add_data_vector(node_handler, active_set, "active_set");
    // Two subdivisions per cell: the patch points are the quadratic nodes,
    // so ParaView shows the nodal values exactly.
    data_out.build_patches(*discretisation.mapping, 2);

    dealii::DataOutBase::VtkFlags flags;
    flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);

    // deal.II 9.4 writes cell data as (piecewise constant) point data; the
    // block and material ids go in as true VTK cell data instead, one value
    // per VTK cell (a deal.II cell is written as n_subdivisions^2 linear
    // quadrilaterals, or one quadratic triangle).
    std::ostringstream vtu_text;
    data_out.write_vtu(vtu_text);
    const unsigned int vtk_cells_per_cell =
      discretisation.element == ElementType::q2 ? 4 : 1;
    std::ostringstream cell_data;
    cell_data << "    <CellData Scalars=\"block_id\">\n";
    for (const std::string name : {"block_id", "material"})
      {
        cell_data << "    <DataArray type=\"Int32\" Name=\"" << name
                  << "\" format=\"ascii\">\n";
        for (const auto &cell :
             discretisation.triangulation.active_cell_iterators())
          {
            const unsigned int value =
              name == std::string("block_id") ?
                cell->material_id() :
                state->class_of_block[cell->material_id()];
            for (unsigned int k = 0; k < vtk_cells_per_cell; ++k)
              cell_data << value << ' ';
            cell_data << '\n';
          }
        cell_data << "    </DataArray>\n";
      }
    cell_data << "    </CellData>\n";
    std::string       text         = vtu_text.str();
    const std::size_t end_of_piece = text.rfind("</Piece>");
    AssertThrow(end_of_piece != std::string::npos,
                dealii::ExcMessage("unexpected VTU layout from DataOut"));
    text.insert(end_of_piece, cell_data.str());

    const std::string vtu_name  = "solution_000.vtu";
    const auto        directory = context.output_directory;
    {
      std::ofstream vtu(directory / vtu_name);
      vtu << text;
      if (!vtu)
        throw InputError("cannot write '" + (directory / vtu_name).string() +
                         "'");
    }
    std::ofstream pvd(directory / "solution.pvd");
    dealii::DataOutBase::write_pvd_record(pvd, {{0.0, vtu_name}});
  }
} // namespace unilateral::masonry
