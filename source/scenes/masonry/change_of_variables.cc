#include <unilateral/base/input_error.h>
#include <unilateral/scenes/masonry/change_of_variables.h>

#include <algorithm>
#include <numeric>

namespace unilateral::masonry
{
  std::string
  to_string(const ConstraintKind kind)
  {
    switch (kind)
      {
        case ConstraintKind::signorini:
          return "Signorini";
        case ConstraintKind::horizontal_joint:
          return "horizontal joint";
        case ConstraintKind::vertical_joint:
          return "vertical joint";
      }
    return "";
  }

  namespace
  {
    // Union-find with path halving and union by size.
    class DisjointSets
    {
    public:
      explicit DisjointSets(const std::size_t n)
        : parent(n)
        , size(n, 1)
      {
        std::iota(parent.begin(), parent.end(), std::size_t(0));
      }

      std::size_t
      find(std::size_t v)
      {
        while (parent[v] != v)
          {
            parent[v] = parent[parent[v]];
            v         = parent[v];
          }
        return v;
      }

      /// False if @p a and @p b were already connected.
      bool
      unite(std::size_t a, std::size_t b)
      {
        a = find(a);
        b = find(b);
        if (a == b)
          return false;
        if (size[a] < size[b])
          std::swap(a, b);
        parent[b] = a;
        size[a] += size[b];
        return true;
      }

    private:
      std::vector<std::size_t> parent;
      std::vector<std::size_t> size;
    };

    enum class EdgeKind : unsigned char
    {
      dirichlet,
      signorini,
      joint
    };

    struct Edge
    {
      std::size_t a, b; ///< joints: a = lower, b = upper; else b = ground
      EdgeKind    kind;
    };
  } // namespace

  ChangeOfVariables::ChangeOfVariables(
    const DofIndex                              n_dofs,
    const std::vector<char>                    &dirichlet,
    const std::vector<UnilateralConstraint>    &constraints,
    const std::function<std::string(DofIndex)> &describe)
  {
    const std::size_t ground = n_dofs;

    // The graph: one edge per Dirichlet DOF, then one per constraint, so
    // that constraint k is edge n_dirichlet + k.
    std::vector<Edge> edges;
    for (DofIndex i = 0; i < n_dofs; ++i)
      if (dirichlet[i])
        edges.push_back({i, ground, EdgeKind::dirichlet});
    const std::size_t first_constraint_edge = edges.size();
    for (const UnilateralConstraint &c : constraints)
      {
        if (c.kind == ConstraintKind::signorini)
          edges.push_back({c.lower, ground, EdgeKind::signorini});
        else
          {
            if (c.lower == c.upper)
              throw InputError("a " + to_string(c.kind) + " constraint at " +
                               describe(c.lower) +
                               " couples a DOF with itself");
            edges.push_back({c.lower, c.upper, EdgeKind::joint});
          }
      }

    // C~ is invertible iff the graph is a forest in which ground is one
    // vertex: a cycle, or a second support of a chain, is a dependent row.
    {
      DisjointSets sets(n_dofs + 1);
      for (const Edge &edge : edges)
        if (!sets.unite(edge.a, edge.b))
          {
            if (sets.find(edge.a) == sets.find(ground))
              throw InputError(
                "the unilateral constraints give " + describe(edge.a) +
                " a second support (Dirichlet or Signorini, directly or "
                "through joints): the constraint rows are dependent and the "
                "change of variables C~ would be singular; each chain of "
                "coincident nodes may rest on at most one support");
            throw InputError(
              "the joint constraints between coincident nodes at " +
              describe(edge.a) +
              " form a cycle: the constraint rows are dependent and the "
              "change of variables C~ would be singular");
          }
    }

    // Adjacency lists (CSR) of the vertices that have edges.
    std::vector<std::size_t> offset(n_dofs + 2, 0);
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

    // Orient every tree from its root by breadth-first search; the child of
    // each edge owns it. Ground first, so Dirichlet and Signorini DOFs are
    // owned by their own support edge.
    constexpr std::size_t    none = static_cast<std::size_t>(-1);
    std::vector<std::size_t> parent_edge(n_dofs + 1, none);
    std::vector<char>        visited(n_dofs + 1, 0);
    std::vector<std::size_t> order; // visiting order: parents before children
    order.reserve(n_dofs + 1);
    auto search_from = [&](const std::size_t root) {
      std::size_t head = order.size();
      visited[root]    = 1;
      order.push_back(root);
      while (head < order.size())
        {
          const std::size_t v = order[head++];
          for (std::size_t k = offset[v]; k < offset[v + 1]; ++k)
            {
              const std::size_t e = incident[k];
              const std::size_t w = edges[e].a == v ? edges[e].b : edges[e].a;
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
    for (std::size_t v = 0; v < n_dofs; ++v)
      if (!visited[v])
        search_from(v);

    // One new variable per non-Dirichlet DOF, numbered in DOF order.
    variable.assign(n_dofs, -1);
    n_variables = 0;
    for (DofIndex i = 0; i < n_dofs; ++i)
      if (!dirichlet[i])
        variable[i] = static_cast<int>(n_variables++);

    // Expansions in visiting order, so a parent's terms exist before its
    // children copy them. A joint child c with parent p: the gap is
    // s_c u_c + s_p u_p with s_c = -s_p = +-1, hence u_c = s_c gap + u_p.
    std::vector<std::size_t> length(n_dofs, 0);
    for (const std::size_t v : order)
      {
        if (v == ground)
          continue;
        const std::size_t e = parent_edge[v];
        if (e == none)
          length[v] = 1; // a root
        else if (edges[e].kind == EdgeKind::dirichlet)
          length[v] = 0;
        else if (edges[e].kind == EdgeKind::signorini)
          length[v] = 1;
        else
          {
            const std::size_t p = edges[e].a == v ? edges[e].b : edges[e].a;
            length[v]           = 1 + length[p];
          }
      }
    term_start.assign(n_dofs + 1, 0);
    for (DofIndex i = 0; i < n_dofs; ++i)
      term_start[i + 1] = term_start[i] + length[i];
    terms.resize(term_start.back());
    for (const std::size_t v : order)
      {
        if (v == ground || length[v] == 0)
          continue;
        Term             *out = terms.data() + term_start[v];
        const std::size_t e   = parent_edge[v];
        if (e == none || edges[e].kind == EdgeKind::signorini)
          out[0] = {variable[v], 1.0};
        else
          {
            const bool        child_is_upper = edges[e].b == v;
            const std::size_t p = child_is_upper ? edges[e].a : edges[e].b;
            out[0]              = {variable[v], child_is_upper ? 1.0 : -1.0};
            std::copy(terms.begin() + term_start[p],
                      terms.begin() + term_start[p + 1],
                      out + 1);
          }
      }

    // Each constraint lives in the variable of its owner (the child).
    constraint_variable.resize(constraints.size());
    for (std::size_t k = 0; k < constraints.size(); ++k)
      {
        const Edge       &edge = edges[first_constraint_edge + k];
        const std::size_t owner =
          parent_edge[edge.a] == first_constraint_edge + k ? edge.a : edge.b;
        constraint_variable[k] = variable[owner];
      }
  }

  unsigned int
  ChangeOfVariables::max_expansion_length() const
  {
    std::size_t longest = 0;
    for (std::size_t i = 0; i + 1 < term_start.size(); ++i)
      longest = std::max(longest, term_start[i + 1] - term_start[i]);
    return static_cast<unsigned int>(longest);
  }

  std::vector<double>
  ChangeOfVariables::to_physical(const double *new_variables) const
  {
    std::vector<double> u(variable.size(), 0.0);
    for (std::size_t i = 0; i < u.size(); ++i)
      for (std::size_t t = term_start[i]; t < term_start[i + 1]; ++t)
        u[i] += terms[t].coefficient * new_variables[terms[t].variable];
    return u;
  }
} // namespace unilateral::masonry
