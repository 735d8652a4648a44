#include <unilateral/base/disjoint_sets.h>
#include <unilateral/base/input_error.h>
#include <unilateral/scenes/masonry/change_of_variables.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace unilateral::masonry
{
  std::string
  to_string(const ConstraintKind kind)
  {
    return kind == ConstraintKind::signorini ? "Signorini" : "joint";
  }

  namespace
  {
    constexpr std::size_t none = static_cast<std::size_t>(-1);

    /// One edge of a class graph: a constraint (joint or Signorini), a
    /// roller or a held node; b is the ground vertex for all but joints.
    struct Edge
    {
      std::size_t a, b;
      /// The constraint it is, or none (a roller, a held node).
      std::size_t constraint;
      /// A joint's a is its lower node; the constraint's sign s.
      double sign;
      bool   roller;
    };

    /**
     * The forest of one direction class: union-find checks it is one, a
     * breadth-first search from ground (then from the smallest node of
     * each other tree) orients it; parent_edge[v] is the edge that owns
     * vertex v, and order lists parents before children.
     */
    struct ClassForest
    {
      std::vector<Edge>        edges;
      std::vector<std::size_t> parent_edge;
      std::vector<std::size_t> order;

      void
      orient(const std::size_t                               n_nodes,
             const std::function<std::string(unsigned int)> &describe)
      {
        const std::size_t ground = n_nodes;
        DisjointSets      sets(n_nodes + 1);
        for (const Edge &edge : edges)
          if (!sets.unite(edge.a, edge.b))
            {
              const auto node = static_cast<unsigned int>(edge.a);
              if (sets.find(edge.a) == sets.find(ground))
                throw InputError(
                  "the unilateral constraints give " + describe(node) +
                  " a second support (a held node, a roller or Signorini, "
                  "directly or through joints, in the same direction): the "
                  "constraint rows are dependent and the change of "
                  "variables C~ would be singular; each chain of coincident "
                  "nodes may rest on at most one support in a direction");
              throw InputError(
                "the joint constraints between coincident nodes at " +
                describe(node) +
                " form a cycle: the constraint rows are dependent and the "
                "change of variables C~ would be singular");
            }

        // Adjacency lists (CSR), then the search.
        std::vector<std::size_t> offset(n_nodes + 2, 0);
        for (const Edge &edge : edges)
          {
            ++offset[edge.a + 1];
            ++offset[edge.b + 1];
          }
        std::partial_sum(offset.begin(), offset.end(), offset.begin());
        std::vector<std::size_t> incident(offset.back());
        {
          std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
          for (std::size_t e = 0; e < edges.size(); ++e)
            {
              incident[fill[edges[e].a]++] = e;
              incident[fill[edges[e].b]++] = e;
            }
        }
        parent_edge.assign(n_nodes + 1, none);
        std::vector<char> visited(n_nodes + 1, 0);
        auto              search_from = [&](const std::size_t root) {
          std::size_t head = order.size();
          visited[root]    = 1;
          order.push_back(root);
          while (head < order.size())
            {
              const std::size_t v = order[head++];
              for (std::size_t k = offset[v]; k < offset[v + 1]; ++k)
                {
                  const std::size_t e = incident[k];
                  const std::size_t w =
                    edges[e].a == v ? edges[e].b : edges[e].a;
                  if (!visited[w])
                    {
                      visited[w]     = 1;
                      parent_edge[w] = e;
                      order.push_back(w);
                    }
                }
            }
        };
        search_from(ground);
        for (std::size_t v = 0; v < n_nodes; ++v)
          if (!visited[v] && offset[v + 1] > offset[v])
            search_from(v);
      }
    };

    /**
     * The frame of a node: its class rows (the classes of the constraints
     * and rollers at it), then an orthonormal completion; row r is assigned
     * to component component_of_row[r] (the largest entry among the free
     * ones), which carries its variable.
     */
    template <int dim>
    struct Frame
    {
      std::vector<unsigned int>                classes;
      std::array<Direction<dim>, dim>          rows;
      std::array<unsigned int, dim>            component_of_row;
      std::array<std::array<double, dim>, dim> inverse; // [component][row]
    };

    template <int dim>
    Frame<dim>
    make_frame(const std::vector<unsigned int>                &classes,
               const std::vector<Direction<dim>>              &directions,
               const unsigned int                              node,
               const std::function<std::string(unsigned int)> &describe)
    {
      Frame<dim> frame;
      frame.classes = classes;
      if (classes.size() > dim)
        throw InputError(describe(node) + " has contacts or supports in " +
                         std::to_string(classes.size()) +
                         " directions, more than " + std::to_string(dim) +
                         ": node-to-node contact allows at most one "
                         "direction per dimension at a node (refine the mesh "
                         "or merge the faces that meet there)");
      // Gram-Schmidt: the class rows must be independent (an angle of more
      // than about 0.06 degrees between each and the span of the others).
      std::vector<dealii::Tensor<1, dim>> orthonormal;
      auto residual = [&](const Direction<dim> &row) {
        dealii::Tensor<1, dim> r;
        for (unsigned int c = 0; c < dim; ++c)
          r[c] = row[c];
        for (const auto &q : orthonormal)
          r -= (r * q) * q;
        return r;
      };
      unsigned int n_rows = 0;
      for (const unsigned int k : classes)
        {
          const dealii::Tensor<1, dim> r = residual(directions[k]);
          if (r.norm() < 1e-3)
            {
              std::ostringstream message;
              message << describe(node)
                      << " has contacts or supports in directions that are "
                         "(nearly) linearly dependent (one "
                      << std::asin(std::min(1.0, r.norm()))
                      << " rad from the others' span): node-to-node contact "
                         "needs independent directions at a node (merge the "
                         "faces or refine the mesh)";
              // Directions this close are meant to be one: faces that
              // should be parallel, from coordinates rounded in the file.
              if (r.norm() < 1e-4)
                message << "; faces meant to be parallel whose coordinates "
                           "were rounded (a mesh written with few "
                           "significant digits: write more) differ so "
                           "little, and their joints are one direction if "
                           "'Masonry/Coincidence tolerance' is at least "
                        << 1.5 * r.norm() / 4;
              throw InputError(message.str());
            }
          orthonormal.push_back(r / r.norm());
          frame.rows[n_rows++] = directions[k];
        }
      while (n_rows < dim)
        {
          // The axis with the largest part outside the span so far.
          dealii::Tensor<1, dim> best;
          for (unsigned int c = 0; c < dim; ++c)
            {
              Direction<dim> axis{};
              axis[c]                        = 1;
              const dealii::Tensor<1, dim> r = residual(axis);
              if (r.norm() > best.norm() + 1e-12)
                best = r;
            }
          best /= best.norm();
          orthonormal.push_back(best);
          for (unsigned int c = 0; c < dim; ++c)
            frame.rows[n_rows][c] = best[c];
          ++n_rows;
        }
      std::array<bool, dim> taken{};
      for (unsigned int r = 0; r < dim; ++r)
        {
          unsigned int best = dim;
          for (unsigned int c = 0; c < dim; ++c)
            if (!taken[c] && (best == dim || std::abs(frame.rows[r][c]) >
                                               std::abs(frame.rows[r][best])))
              best = c;
          taken[best]               = true;
          frame.component_of_row[r] = best;
        }
      dealii::Tensor<2, dim> T;
      for (unsigned int r = 0; r < dim; ++r)
        for (unsigned int c = 0; c < dim; ++c)
          T[r][c] = frame.rows[r][c];
      const dealii::Tensor<2, dim> T_inverse = dealii::invert(T);
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int r = 0; r < dim; ++r)
          frame.inverse[c][r] = T_inverse[c][r];
      return frame;
    }
  } // namespace

  template <int dim>
  DirectionClasses<dim>::DirectionClasses(const double tolerance)
    : tolerance(tolerance)
  {}

  template <int dim>
  template <typename Action>
  void
  DirectionClasses<dim>::for_each_near(const Direction<dim> &d,
                                       const double          radius,
                                       const Action         &action) const
  {
    // Probe the neighbouring cells of the grid, so that directions within
    // the radius (at most the cells' 10 tolerances) meet whichever side of
    // a cell edge they fall on.
    std::array<long, dim> key;
    for (unsigned int c = 0; c < dim; ++c)
      key[c] = std::lround(d[c] / (10 * tolerance));
    for (unsigned int probe = 0; probe < (dim == 2 ? 9u : 27u); ++probe)
      {
        std::array<long, dim> neighbour = key;
        for (unsigned int c = 0, p = probe; c < dim; ++c, p /= 3)
          neighbour[c] += static_cast<long>(p % 3) - 1;
        const auto found = index.find(neighbour);
        if (found == index.end())
          continue;
        for (const unsigned int k : found->second)
          {
            double difference = 0;
            for (unsigned int c = 0; c < dim; ++c)
              difference =
                std::max(difference, std::abs(directions[k][c] - d[c]));
            if (difference <= radius)
              action(k, difference);
          }
      }
  }

  template <int dim>
  std::pair<int, double>
  DirectionClasses<dim>::find(const Direction<dim> &d) const
  {
    // The nearest, then the oldest: a pure function of d and the classes,
    // not of the order of the probes.
    int    nearest  = -1;
    double smallest = 0;
    for_each_near(
      d, tolerance, [&](const unsigned int k, const double difference) {
        if (nearest < 0 || difference < smallest ||
            (difference == smallest && static_cast<int>(k) < nearest))
          {
            nearest  = static_cast<int>(k);
            smallest = difference;
          }
      });
    return {nearest, smallest};
  }

  template <int dim>
  std::vector<std::pair<unsigned int, double>>
  DirectionClasses<dim>::within(const Direction<dim> &d,
                                const double          radius) const
  {
    std::vector<std::pair<unsigned int, double>> result;
    for (const double orientation : {1.0, -1.0})
      {
        Direction<dim> oriented;
        for (unsigned int c = 0; c < dim; ++c)
          oriented[c] = orientation * d[c];
        for_each_near(oriented, radius, [&](const unsigned int k, double) {
          result.emplace_back(k, orientation);
        });
      }
    return result;
  }

  template <int dim>
  std::pair<unsigned int, double>
  DirectionClasses<dim>::classify(const Direction<dim> &normal)
  {
    for (const auto &[seen, answer] : recent)
      if (seen == normal)
        return answer;
    const std::size_t n_classes = directions.size();
    const auto        answer    = classify_anew(normal);
    if (directions.size() != n_classes) // a class made: forget the others
      recent.clear();
    if (recent.size() == max_recent)
      recent.erase(recent.begin());
    recent.emplace_back(normal, answer);
    return answer;
  }

  template <int dim>
  std::pair<unsigned int, double>
  DirectionClasses<dim>::classify_anew(const Direction<dim> &normal)
  {
    double sign = 1;
    for (unsigned int c = 0; c < dim; ++c)
      if (std::abs(normal[c]) > 1e-8)
        {
          sign = normal[c] > 0 ? 1.0 : -1.0;
          break;
        }
    Direction<dim> d, opposite;
    for (unsigned int c = 0; c < dim; ++c)
      {
        d[c]        = sign * normal[c];
        opposite[c] = -d[c];
      }
    // Both orientations: a normal whose first components are about as
    // small as 1e-8 may have got the other sign than its class's d.
    const auto [k, difference]                   = find(d);
    const auto [k_opposite, difference_opposite] = find(opposite);
    if (k_opposite >= 0 && (k < 0 || difference_opposite < difference))
      return {static_cast<unsigned int>(k_opposite), -sign};
    if (k >= 0)
      return {static_cast<unsigned int>(k), sign};
    std::array<long, dim> key;
    for (unsigned int c = 0; c < dim; ++c)
      key[c] = std::lround(d[c] / (10 * tolerance));
    index[key].push_back(static_cast<unsigned int>(directions.size()));
    directions.push_back(d);
    return {static_cast<unsigned int>(directions.size() - 1), sign};
  }

  template <int dim>
  ChangeOfVariables<dim>::ChangeOfVariables(
    const DofIndex                                  n_dofs,
    const std::vector<std::array<DofIndex, dim>>   &nodes,
    const std::vector<HeldNode<dim>>               &held,
    const std::vector<Roller<dim>>                 &rollers,
    const std::vector<UnilateralConstraint<dim>>   &constraints,
    const std::function<std::string(unsigned int)> &describe)
  {
    const std::size_t n_nodes = nodes.size();
    const std::size_t ground  = n_nodes;

    std::vector<int> held_index(n_nodes, -1);
    for (std::size_t h = 0; h < held.size(); ++h)
      held_index[held[h].node] = static_cast<int>(h);

    // The classes, and per class the graph: held nodes first (only where
    // the class reaches them), then rollers, then the constraints, so that
    // the search visits supports before what hangs from them.
    DirectionClasses<dim>    classes;
    std::vector<ClassForest> forest;
    auto                     class_of = [&](const Direction<dim> &normal) {
      const auto result = classes.classify(normal);
      if (result.first >= forest.size())
        forest.resize(result.first + 1);
      return result;
    };
    std::vector<std::vector<unsigned int>> classes_at(n_nodes);
    auto touch = [&](const std::size_t node, const unsigned int k) {
      auto &list = classes_at[node];
      if (std::find(list.begin(), list.end(), k) == list.end())
        list.push_back(k);
    };
    std::vector<std::pair<unsigned int, double>> constraint_class;
    for (const UnilateralConstraint<dim> &c : constraints)
      {
        if (c.kind == ConstraintKind::joint && c.lower == c.upper)
          throw InputError("a joint constraint at " + describe(c.lower) +
                           " couples a node with itself");
        constraint_class.push_back(class_of(c.normal));
      }
    std::vector<std::pair<unsigned int, double>> roller_class;
    for (const Roller<dim> &roller : rollers)
      roller_class.push_back(class_of(roller.normal));
    for (std::size_t k = 0; k < constraints.size(); ++k)
      {
        const auto &c     = constraints[k];
        auto       &edges = forest[constraint_class[k].first].edges;
        const bool  joint = c.kind == ConstraintKind::joint;
        for (const unsigned int node :
             joint ? std::vector<unsigned int>{c.lower, c.upper} :
                     std::vector<unsigned int>{c.lower})
          if (held_index[node] >= 0)
            edges.push_back({node, ground, none, 1.0, false});
      }
    // The held edges above are in constraint order; put them in node order
    // and first, then the rollers (node order), then the constraints.
    for (unsigned int k = 0; k < forest.size(); ++k)
      {
        auto &edges = forest[k].edges;
        std::sort(edges.begin(), edges.end(), [](const Edge &x, const Edge &y) {
          return x.a < y.a;
        });
        edges.erase(std::unique(edges.begin(),
                                edges.end(),
                                [](const Edge &x, const Edge &y) {
                                  return x.a == y.a;
                                }),
                    edges.end());
      }
    {
      std::vector<std::size_t> order(rollers.size());
      std::iota(order.begin(), order.end(), std::size_t(0));
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const std::size_t x, const std::size_t y) {
                         return rollers[x].node < rollers[y].node;
                       });
      for (const std::size_t r : order)
        {
          const auto [k, sign] = roller_class[r];
          forest[k].edges.push_back(
            {rollers[r].node, ground, none, sign, true});
          touch(rollers[r].node, k);
        }
    }
    for (std::size_t i = 0; i < constraints.size(); ++i)
      {
        const auto &c        = constraints[i];
        const auto [k, sign] = constraint_class[i];
        if (c.kind == ConstraintKind::joint)
          {
            forest[k].edges.push_back({c.lower, c.upper, i, sign, false});
            touch(c.upper, k);
          }
        else
          forest[k].edges.push_back({c.lower, ground, i, sign, false});
        touch(c.lower, k);
      }
    for (ClassForest &f : forest)
      f.orient(n_nodes, describe);

    // Frames, and one variable per DOF that is neither held nor a roller's
    // frame row, in DOF order.
    std::vector<Frame<dim>> frames(n_nodes);
    // row_of_class[node][k]: the frame row of class k at node.
    for (std::size_t a = 0; a < n_nodes; ++a)
      if (held_index[a] < 0)
        {
          std::sort(classes_at[a].begin(), classes_at[a].end());
          frames[a] = make_frame<dim>(classes_at[a],
                                      classes.directions,
                                      static_cast<unsigned int>(a),
                                      describe);
        }
    auto row_of_class = [&](const std::size_t a, const unsigned int k) {
      const auto &list = frames[a].classes;
      return static_cast<unsigned int>(std::find(list.begin(), list.end(), k) -
                                       list.begin());
    };
    std::vector<char> roller_row(n_nodes * dim, 0);
    for (std::size_t k = 0; k < forest.size(); ++k)
      for (const Edge &edge : forest[k].edges)
        if (edge.roller)
          roller_row[edge.a * dim + row_of_class(edge.a, k)] = 1;
    variable.assign(n_dofs, -1);
    std::vector<int> row_variable(n_nodes * dim, -1);
    // The frame row (a dim + r) of each variable.
    std::vector<std::size_t> slot_of_variable;
    {
      std::vector<std::pair<std::size_t, unsigned int>> row_of_dof(n_dofs,
                                                                   {none, 0});
      for (std::size_t a = 0; a < n_nodes; ++a)
        if (held_index[a] < 0)
          for (unsigned int r = 0; r < dim; ++r)
            row_of_dof[nodes[a][frames[a].component_of_row[r]]] = {a, r};
      n_variables = 0;
      for (DofIndex i = 0; i < n_dofs; ++i)
        {
          const auto [a, r] = row_of_dof[i];
          if (a == none || roller_row[a * dim + r])
            continue;
          variable[i]               = static_cast<int>(n_variables++);
          row_variable[a * dim + r] = variable[i];
          slot_of_variable.push_back(a * dim + r);
        }
    }

    // The expansions of the frame variables v_{a,r}: terms and a constant,
    // class by class in the search order (parents first).
    std::vector<std::vector<Term>> row_terms(n_nodes * dim);
    std::vector<double>            row_constant(n_nodes * dim, 0.0);
    for (std::size_t a = 0; a < n_nodes; ++a)
      if (held_index[a] < 0)
        for (unsigned int r = frames[a].classes.size(); r < dim; ++r)
          row_terms[a * dim + r] = {{row_variable[a * dim + r], 1.0}};
    for (std::size_t k = 0; k < forest.size(); ++k)
      {
        const ClassForest    &f = forest[k];
        const Direction<dim> &d = classes.directions[k];
        for (const std::size_t v : f.order)
          {
            if (v == ground || held_index[v] >= 0)
              continue;
            const std::size_t slot = v * dim + row_of_class(v, k);
            const std::size_t e    = f.parent_edge[v];
            const int         own  = row_variable[slot];
            if (e == none)
              row_terms[slot] = {{own, 1.0}}; // the root of a free tree
            else if (f.edges[e].roller)
              row_terms[slot].clear();
            else if (f.edges[e].b == ground)
              row_terms[slot] = {{own, f.edges[e].sign}}; // Signorini
            else
              {
                // A joint: w = s (v_upper - v_lower); v is lower or upper.
                const Edge       &edge     = f.edges[e];
                const bool        is_upper = edge.b == v;
                const std::size_t p        = is_upper ? edge.a : edge.b;
                std::vector<Term> expansion{
                  {own, is_upper ? edge.sign : -edge.sign}};
                double constant = 0;
                if (held_index[p] >= 0)
                  for (unsigned int c = 0; c < dim; ++c)
                    constant += d[c] * held[held_index[p]].value[c];
                else
                  {
                    const std::size_t parent_slot =
                      p * dim + row_of_class(p, k);
                    expansion.insert(expansion.end(),
                                     row_terms[parent_slot].begin(),
                                     row_terms[parent_slot].end());
                    constant = row_constant[parent_slot];
                  }
                row_terms[slot]    = std::move(expansion);
                row_constant[slot] = constant;
              }
          }
      }

    // u_{a,c} = sum_r T_a^-1[c][r] v_{a,r}; held nodes are constants.
    // Stored flat (term_start, terms), counted first and then written: a
    // vector per DOF would be a million small allocations.
    offsets.assign(n_dofs, 0.0);
    term_start.assign(n_dofs + 1, 0);
    // The frame rows r of u_{a,c}'s expansion (slot a dim + r) and their
    // factors T_a^-1[c][r]: none for a held node.
    const auto for_each_row =
      [&](const std::size_t a, const unsigned int c, const auto &action) {
        if (held_index[a] < 0)
          for (unsigned int r = 0; r < dim; ++r)
            if (const double factor = frames[a].inverse[c][r]; factor != 0)
              action(a * dim + r, factor);
      };
    for (std::size_t a = 0; a < n_nodes; ++a)
      for (unsigned int c = 0; c < dim; ++c)
        for_each_row(a, c, [&](const std::size_t slot, double) {
          term_start[nodes[a][c] + 1] += row_terms[slot].size();
        });
    for (DofIndex i = 0; i < n_dofs; ++i)
      term_start[i + 1] += term_start[i];
    terms.resize(term_start.back());
    for (std::size_t a = 0; a < n_nodes; ++a)
      for (unsigned int c = 0; c < dim; ++c)
        {
          const DofIndex dof  = nodes[a][c];
          std::size_t    next = term_start[dof];
          if (held_index[a] >= 0)
            offsets[dof] = held[held_index[a]].value[c];
          for_each_row(a, c, [&](const std::size_t slot, const double factor) {
            for (const Term &t : row_terms[slot])
              terms[next++] = {t.variable, factor * t.coefficient};
            offsets[dof] += factor * row_constant[slot];
          });
        }
    any_offset = std::any_of(offsets.begin(), offsets.end(), [](double x) {
      return x != 0;
    });

    // Each constraint lives in the variable of its owner (the child).
    constraint_variable.resize(constraints.size());
    for (std::size_t k = 0; k < forest.size(); ++k)
      for (const std::size_t v : forest[k].order)
        if (v != ground && forest[k].parent_edge[v] != none)
          {
            const Edge &edge = forest[k].edges[forest[k].parent_edge[v]];
            if (edge.constraint != none)
              constraint_variable[edge.constraint] =
                row_variable[v * dim + row_of_class(v, k)];
          }

    // The rows of C~: a frame row times u, or for the owner of a
    // constraint its gap. Flat as the terms above.
    std::vector<int> gap_of(n_variables, -1);
    for (std::size_t k = 0; k < constraints.size(); ++k)
      gap_of[constraint_variable[k]] = static_cast<int>(k);
    const auto for_each_entry = [&](const unsigned int t, const auto &action) {
      if (gap_of[t] >= 0)
        {
          const UnilateralConstraint<dim> &constraint = constraints[gap_of[t]];
          const bool joint = constraint.kind == ConstraintKind::joint;
          for (unsigned int c = 0; c < dim; ++c)
            if (const double n = constraint.normal[c]; n != 0)
              {
                if (joint)
                  action(nodes[constraint.upper][c], n);
                action(nodes[constraint.lower][c], joint ? -n : n);
              }
          return;
        }
      const std::size_t a = slot_of_variable[t] / dim;
      const std::size_t r = slot_of_variable[t] % dim;
      for (unsigned int c = 0; c < dim; ++c)
        if (frames[a].rows[r][c] != 0)
          action(nodes[a][c], frames[a].rows[r][c]);
    };
    row_start.assign(n_variables + 1, 0);
    for (unsigned int t = 0; t < n_variables; ++t)
      for_each_entry(t, [&](DofIndex, double) { ++row_start[t + 1]; });
    for (unsigned int t = 0; t < n_variables; ++t)
      row_start[t + 1] += row_start[t];
    row_entries.resize(row_start.back());
    for (unsigned int t = 0; t < n_variables; ++t)
      {
        std::size_t next = row_start[t];
        for_each_entry(t, [&](const DofIndex dof, const double coefficient) {
          row_entries[next++] = {dof, coefficient};
        });
      }
  }

  template <int dim>
  unsigned int
  ChangeOfVariables<dim>::max_expansion_length() const
  {
    std::size_t longest = 0;
    for (std::size_t i = 0; i + 1 < term_start.size(); ++i)
      longest = std::max(longest, term_start[i + 1] - term_start[i]);
    return static_cast<unsigned int>(longest);
  }

  template <int dim>
  std::vector<double>
  ChangeOfVariables<dim>::to_physical(const double *new_variables) const
  {
    std::vector<double> u(offsets);
    for (std::size_t i = 0; i < u.size(); ++i)
      for (std::size_t t = term_start[i]; t < term_start[i + 1]; ++t)
        u[i] += terms[t].coefficient * new_variables[terms[t].variable];
    return u;
  }

  template class DirectionClasses<2>;
  template class DirectionClasses<3>;
  template class ChangeOfVariables<2>;
  template class ChangeOfVariables<3>;
} // namespace unilateral::masonry
