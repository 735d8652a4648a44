#include <unilateral/base/input_error.h>
#include <unilateral/base/output_file.h>
#include <unilateral/base/ranks.h>

#include "scene_state.h"

#include <deal.II/base/data_out_base.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    /**
     * Stress from the displacement gradient, cell by cell with the cell's
     * material: the tensor sigma = lambda tr(eps) I + 2 mu eps (in 2D plane
     * strain, whose sigma_zz = lambda tr(eps) enters the von Mises stress)
     * and the von Mises stress; in 2D also sigma_zz, which the tensor (in
     * the plane: ParaView pads it to 3 x 3 with zeros) cannot hold.
     */
    template <int dim>
    class StressPostprocessor : public dealii::DataPostprocessor<dim>
    {
    public:
      StressPostprocessor(const std::vector<MaterialClass> &classes,
                          const std::vector<unsigned int>  &class_of_block)
        : classes(classes)
        , class_of_block(class_of_block)
      {}

      void
      evaluate_vector_field(
        const dealii::DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<dealii::Vector<double>> &computed_quantities) const override
      {
        const auto           cell = inputs.template get_cell<dim>();
        const MaterialClass &material =
          classes[class_of_block[cell->material_id()]];
        const double lambda = material.lambda();
        const double mu     = material.mu();
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            const auto &grad = inputs.solution_gradients[q];
            // Full 3x3 strain and stress (plane strain: e_zz = 0).
            double e[3][3] = {};
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                e[i][j] = 0.5 * (grad[i][j] + grad[j][i]);
            const double trace = e[0][0] + e[1][1] + e[2][2];
            double       sigma[3][3];
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                sigma[i][j] = 2 * mu * e[i][j] + (i == j ? lambda * trace : 0);
            const double von_mises = std::sqrt(
              0.5 *
                ((sigma[0][0] - sigma[1][1]) * (sigma[0][0] - sigma[1][1]) +
                 (sigma[1][1] - sigma[2][2]) * (sigma[1][1] - sigma[2][2]) +
                 (sigma[2][2] - sigma[0][0]) * (sigma[2][2] - sigma[0][0])) +
              3 * (sigma[0][1] * sigma[0][1] + sigma[1][2] * sigma[1][2] +
                   sigma[0][2] * sigma[0][2]));
            dealii::Vector<double> &out = computed_quantities[q];
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                out[i * dim + j] = sigma[i][j];
            out[dim * dim] = von_mises;
            if (dim == 2)
              out[dim * dim + 1] = sigma[2][2];
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names(dim * dim, "stress");
        names.push_back("von_mises");
        if (dim == 2)
          names.push_back("stress_zz");
        return names;
      }

      std::vector<
        dealii::DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        using namespace dealii::DataComponentInterpretation;
        std::vector<DataComponentInterpretation> interpretation(
          dim * dim, component_is_part_of_tensor);
        interpretation.push_back(component_is_scalar);
        if (dim == 2)
          interpretation.push_back(component_is_scalar);
        return interpretation;
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

    /// Per node and direction class: summed force, smallest gap, any active.
    struct Load
    {
      double force = 0, weight = 0, gap = std::numeric_limits<double>::max();
      bool   active = false;
    };
    using Loads = std::map<std::pair<unsigned int, unsigned int>, Load>;

    /*
     * A corner of a quadratic triangle (P2 faces in 3D) has int phi = 0
     * over its face: its force says nothing of the pressure there (it is
     * zero for a uniform one), and force / weight would be round-off over
     * round-off. Such a node takes the mean pressure, in its direction, of
     * the midpoints of the cells' edges from it that have a weight and
     * lie on its contact plane: the neighbouring edge midpoints of its
     * contact faces (exact for a uniform pressure, like the rest), open or
     * closed.
     */
    template <int dim>
    std::map<std::pair<unsigned int, unsigned int>, double>
    pressures_without_weight(const Loads               &loads,
                             const ContactSet<dim>     &contacts,
                             const Discretisation<dim> &discretisation)
    {
      double largest = 0;
      for (const auto &entry : loads)
        largest = std::max(largest, std::abs(entry.second.weight));
      const auto weightless = [&](const Load &load) {
        return !(std::abs(load.weight) > 1e-10 * largest);
      };
      // Only the midpoints of the cell's edges from a (2 b - a is a node of
      // the cell): the midpoint of the opposite edge lies further off, and
      // where a joint opens at a it showed a pressure none of a's
      // neighbours has (a review). Such a midpoint with a weight in a's
      // direction lies on a's contact plane: one of another contact of
      // that direction would be inside the block.
      const auto midpoint_of_edge_from =
        [&](const unsigned int               a,
            const unsigned int               b,
            const std::vector<unsigned int> &nodes) {
          const auto &pa        = contacts.node_position[a];
          const auto &pb        = contacts.node_position[b];
          double      half_edge = 0;
          for (unsigned int c = 0; c < dim; ++c)
            half_edge += (pb[c] - pa[c]) * (pb[c] - pa[c]);
          half_edge = std::sqrt(half_edge);
          for (const unsigned int end : nodes)
            {
              double off = 0;
              for (unsigned int c = 0; c < dim; ++c)
                off = std::max(off,
                               std::abs(contacts.node_position[end][c] -
                                        (2 * pb[c] - pa[c])));
              if (off <= 1e-8 * half_edge)
                return true;
            }
          return false;
        };
      std::map<std::pair<unsigned int, unsigned int>, std::pair<double, int>>
        sums;
      for (const auto &[key, load] : loads)
        if (weightless(load))
          sums[key] = {0.0, 0};
      if (!sums.empty())
        {
          const auto                                  &fe = *discretisation.fe;
          std::vector<dealii::types::global_dof_index> dofs(
            fe.n_dofs_per_cell());
          std::vector<unsigned int> cell_nodes;
          for (const auto &cell :
               discretisation.dof_handler.active_cell_iterators())
            {
              cell->get_dof_indices(dofs);
              cell_nodes.clear();
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                if (fe.system_to_component_index(i).first == 0)
                  cell_nodes.push_back(contacts.node_of_dof[dofs[i]]);
              for (const unsigned int a : cell_nodes)
                for (auto it = sums.lower_bound({a, 0u});
                     it != sums.end() && it->first.first == a;
                     ++it)
                  for (const unsigned int b : cell_nodes)
                    {
                      const auto other = loads.find({b, it->first.second});
                      if (other != loads.end() && !weightless(other->second) &&
                          midpoint_of_edge_from(a, b, cell_nodes))
                        {
                          it->second.first +=
                            other->second.force / other->second.weight;
                          ++it->second.second;
                        }
                    }
            }
        }
      std::map<std::pair<unsigned int, unsigned int>, double> result;
      // Its own constraint, whose force is zero for any pressure near it,
      // may be open or closed by a gap of round-off size (a review: a base
      // corner under a column 1.8e-8 open): the neighbours decide, and
      // where the face has come off they carry none either.
      for (const auto &[key, sum] : sums)
        result[key] = sum.second > 0 ? sum.first / sum.second : 0.0;
      return result;
    }
  } // namespace

  /*
   * The VTU/PVD output. Point data: displacement (a vector, for ParaView's
   * Warp By Vector), the stress tensor and von Mises stress, and at the
   * contact nodes the contact pressure, the normal gap and the active set
   * (zero elsewhere). Cell data: block id (= deal.II material_id) and
   * material class. One dataset for all blocks.
   *
   * The nodal fields live on a scalar quadratic element with the same nodes.
   * A node's pressure in a direction is the sum of its constraints' forces
   * in that direction divided by its weight on its contact faces in that
   * direction (int phi_node over them), which is exact for a uniform
   * pressure. A block corner can carry constraints in several directions:
   * there the output shows the larger pressure, the smaller gap, and
   * "active" if any constraint is.
   */
  template <int dim>
  void
  MasonryScene<dim>::output_results(const RunContext &context) const
  {
    context.stage(registered_name, "writing VTU/PVD");
    const Discretisation<dim> &discretisation = state->discretisation;
    const ContactSet<dim>     &contacts       = state->contacts;
    const std::size_t          n_nodes        = contacts.node_dofs.size();

    DirectionClasses<dim> classes;
    Loads                 at;
    for (std::size_t k = 0; k < constraints.size(); ++k)
      {
        const auto        &c     = contacts.constraints[k];
        const unsigned int klass = classes.classify(c.normal).first;
        for (unsigned int end = 0;
             end < (c.kind == ConstraintKind::joint ? 2u : 1u);
             ++end)
          {
            Load &load = at[{end == 0 ? c.lower : c.upper, klass}];
            // An open contact carries no force: its multiplier is the
            // round-off of A u - b, which showed as pressures of -1e-11
            // on the arch's open joints (a review).
            if (constraints[k].active)
              load.force += constraints[k].contact_force;
            load.weight = contacts.weight[k][end];
            load.gap    = std::min(load.gap, constraints[k].normal_gap);
            load.active = load.active || constraints[k].active;
          }
      }
    // A roller's reaction is the pressure of the support (the base of a
    // wall where it is held, not settled; negative where it pulls), its gap
    // zero: without it the field showed 0 under a bearing half-wall, or
    // the pressure of a joint ending at the node (a review). The active
    // set stays the LCP's: a roller is not one of its constraints.
    for (std::size_t r = 0; r < contacts.rollers.size(); ++r)
      {
        const auto &roller = contacts.rollers[r];
        Load &load = at[{roller.node, classes.classify(roller.normal).first}];
        load.force -= balance.roller_force[r]; // along the outward normal
        load.weight = contacts.roller_weight[r];
        load.gap    = std::min(load.gap, 0.0);
      }
    const auto borrowed =
      pressures_without_weight<dim>(at, contacts, discretisation);
    std::vector<double> pressure(n_nodes, 0.0), gap(n_nodes, 0.0),
      active(n_nodes, 0.0);
    std::vector<char> any(n_nodes, 0);
    for (const auto &[key, load] : at)
      {
        const unsigned int node   = key.first;
        const auto         borrow = borrowed.find(key);
        const double       p      = borrow != borrowed.end() ? borrow->second :
                                    std::abs(load.weight) > 0 ? load.force / load.weight :
                                                                0.0;
        pressure[node]            = any[node] ? std::max(pressure[node], p) : p;
        gap[node]    = any[node] ? std::min(gap[node], load.gap) : load.gap;
        active[node] = active[node] > 0 || load.active ? 1.0 : 0.0;
        any[node]    = 1;
      }

    dealii::DoFHandler<dim> node_handler(discretisation.triangulation);
    node_handler.distribute_dofs(*discretisation.scalar_fe);
    dealii::Vector<double> contact_pressure(node_handler.n_dofs());
    dealii::Vector<double> normal_gap(node_handler.n_dofs());
    dealii::Vector<double> active_set(node_handler.n_dofs());
    {
      const dealii::FiniteElement<dim> &fe = *discretisation.fe;
      const unsigned int                n_nodes_per_cell =
        discretisation.scalar_fe->n_dofs_per_cell();
      std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::vector<dealii::types::global_dof_index> nodes(n_nodes_per_cell);
      auto node_cell = node_handler.begin_active();
      for (const auto &cell :
           discretisation.dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          node_cell->get_dof_indices(nodes);
          ++node_cell;
          for (unsigned int k = 0; k < n_nodes_per_cell; ++k)
            {
              const unsigned int node =
                contacts.node_of_dof[dofs[fe.component_to_system_index(0, k)]];
              contact_pressure[nodes[k]] = pressure[node];
              normal_gap[nodes[k]]       = gap[node];
              active_set[nodes[k]]       = active[node];
            }
        }
    }

    dealii::Vector<double> displacement(state->displacement.begin(),
                                        state->displacement.end());

    StressPostprocessor<dim> stress(parameters.materials.classes,
                                    state->class_of_block);
    dealii::DataOut<dim>     data_out;
    data_out.attach_triangulation(discretisation.triangulation);
    data_out.add_data_vector(
      discretisation.dof_handler,
      displacement,
      std::vector<std::string>(dim, "displacement"),
      std::vector<
        dealii::DataComponentInterpretation::DataComponentInterpretation>(
        dim, dealii::DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(discretisation.dof_handler, displacement, stress);
    data_out.add_data_vector(node_handler,
                             contact_pressure,
                             "contact_pressure");
    data_out.add_data_vector(node_handler, normal_gap, "normal_gap");
    data_out.add_data_vector(node_handler, active_set, "active_set");
    // On several ranks each writes the blocks of its own contiguous run of
    // block ids (its piece of the output), rank 0 the record that joins them.
    const unsigned int rank        = ranks::this_rank();
    const unsigned int n_ranks     = ranks::n_ranks();
    const std::size_t  n_blocks    = state->class_of_block.size();
    const std::size_t  first_block = n_blocks * rank / n_ranks;
    const std::size_t  end_block   = n_blocks * (rank + 1) / n_ranks;
    using CellIterator = typename dealii::Triangulation<dim>::cell_iterator;
    using ActiveIterator =
      typename dealii::Triangulation<dim>::active_cell_iterator;
    const auto in_piece = [first_block, end_block](const CellIterator &cell) {
      return cell->material_id() >= first_block &&
             cell->material_id() < end_block;
    };
    // The first selected active cell from @p cell on.
    const auto from = [in_piece](ActiveIterator                    cell,
                                 const dealii::Triangulation<dim> &mesh) {
      while (cell != mesh.end() && !in_piece(cell))
        ++cell;
      return CellIterator(cell);
    };
    if (n_ranks > 1)
      data_out.set_cell_selection(
        [from](const dealii::Triangulation<dim> &mesh) {
          return from(mesh.begin_active(), mesh);
        },
        [from](const dealii::Triangulation<dim> &mesh,
               const CellIterator               &cell) {
          return from(std::next(ActiveIterator(cell)), mesh);
        });
    // Two subdivisions per cell: the patch points are the quadratic nodes,
    // so ParaView shows the nodal values exactly.
    data_out.build_patches(*discretisation.mapping, 2);

    dealii::DataOutBase::VtkFlags flags;
    flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);

    // deal.II 9.4 writes cell data as (piecewise constant) point data; the
    // block and material ids go in as true VTK cell data instead, one value
    // per VTK cell (a deal.II cell is written as 2^dim linear cells, or one
    // quadratic simplex).
    std::ostringstream vtu_text;
    data_out.write_vtu(vtu_text);
    const unsigned int vtk_cells_per_cell =
      discretisation.element == ElementType::q2 ? (1u << dim) : 1;
    std::ostringstream cell_data;
    cell_data << "    <CellData Scalars=\"block_id\">\n";
    for (const std::string name : {"block_id", "material"})
      {
        cell_data << "    <DataArray type=\"Int32\" Name=\"" << name
                  << "\" format=\"ascii\">\n";
        for (const auto &cell :
             discretisation.triangulation.active_cell_iterators())
          if (in_piece(cell))
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

    const auto directory = context.output_directory;
    const auto write     = [&directory](const std::string &name,
                                    const std::string &content) {
      std::ofstream file(directory / name);
      file << content;
      close_written_file(file, (directory / name).string());
    };
    // The file the PVD record names: the VTU, or the PVTU joining the pieces.
    const std::string record_name =
      n_ranks == 1 ? "solution_000.vtu" : "solution_000.pvtu";
    const auto piece = [](const unsigned int r) {
      return "solution_000." + std::to_string(r) + ".vtu";
    };
    // A rank without blocks (more ranks than blocks) writes no piece: an
    // empty one has no points, which VTK reports as an error.
    const auto has_blocks = [n_blocks, n_ranks](const unsigned int r) {
      return n_blocks * (r + 1) / n_ranks > n_blocks * r / n_ranks;
    };
    ranks::collectively([&]() {
      if (n_ranks == 1)
        write(record_name, text);
      else if (has_blocks(rank))
        write(piece(rank), text);
    });
    if (rank != 0)
      return;
    if (n_ranks > 1)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          if (has_blocks(r))
            pieces.push_back(piece(r));
        std::ostringstream record;
        data_out.write_pvtu_record(record, pieces);
        // The record declares the point data only; the cell data above too.
        std::string       pvtu      = record.str();
        const std::size_t points_at = pvtu.find("<PPoints>");
        AssertThrow(points_at != std::string::npos,
                    dealii::ExcMessage("unexpected PVTU layout from DataOut"));
        pvtu.insert(points_at,
                    "<PCellData Scalars=\"block_id\">\n"
                    "      <PDataArray type=\"Int32\" Name=\"block_id\"/>\n"
                    "      <PDataArray type=\"Int32\" Name=\"material\"/>\n"
                    "    </PCellData>\n    ");
        write(record_name, pvtu);
      }
    std::ofstream pvd(directory / "solution.pvd");
    if (!pvd)
      throw InputError("cannot write '" +
                       (directory / "solution.pvd").string() + "'");
    dealii::DataOutBase::write_pvd_record(pvd, {{0.0, record_name}});
    close_written_file(pvd, (directory / "solution.pvd").string());
  }

  template void
  MasonryScene<2>::output_results(const RunContext &) const;
  template void
  MasonryScene<3>::output_results(const RunContext &) const;
} // namespace unilateral::masonry
