#include <unilateral/lcp/hierarchy.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace unilateral::lcp
{
  namespace
  {
    void
    require(const bool condition, const unsigned int level, const char *what)
    {
      if (!condition)
        throw std::logic_error("inconsistent multigrid hierarchy, level " +
                               std::to_string(level) + ": " + what);
    }

    // Each unknown in one node; at most one constrained unknown per node.
    void
    check_nodes(const Hierarchy          &hierarchy,
                const unsigned int        level,
                const std::vector<Index> &constrained)
    {
      const Hierarchy::Level &data = hierarchy.levels[level];
      const unsigned int      size = hierarchy.block_size;
      require(data.nodes.size() % size == 0,
              level,
              "the node list is not a whole number of blocks");
      std::vector<char> seen(data.n_unknowns, 0);
      std::vector<char> bounded(data.n_unknowns, 0);
      for (const Index i : constrained)
        {
          require(i >= 0 && i < data.n_unknowns,
                  level,
                  "a constrained index out of range");
          bounded[i] = 1;
        }
      for (std::size_t node = 0; node < data.nodes.size() / size; ++node)
        {
          unsigned int n_bounded = 0;
          for (unsigned int c = 0; c < size; ++c)
            {
              const Index i = data.nodes[size * node + c];
              if (i < 0)
                continue;
              require(i < data.n_unknowns && !seen[i],
                      level,
                      "an unknown out of range or in two nodes");
              seen[i] = 1;
              n_bounded += bounded[i];
            }
          require(n_bounded <= 1,
                  level,
                  "a node with more than one constrained unknown");
        }
      for (const char s : seen)
        require(s, level, "an unknown in no node");
    }
  } // namespace

  void
  check_hierarchy(const Hierarchy &hierarchy, const Problem &problem)
  {
    const auto n_levels = static_cast<unsigned int>(hierarchy.levels.size());
    require(n_levels > 0, 0, "no levels");
    require(hierarchy.block_size >= 1 &&
              hierarchy.block_size <= Hierarchy::max_block_size,
            0,
            "block size not in 1..4");
    const Hierarchy::Level &finest = hierarchy.levels.back();
    require(finest.n_unknowns == problem.size() && finest.constrained.empty() &&
              finest.prolongation.size() == 0,
            n_levels - 1,
            "the finest level is not the problem");
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        const Hierarchy::Level &data = hierarchy.levels[level];
        if (level + 1 == n_levels)
          {
            check_nodes(hierarchy, level, problem.constrained);
            continue;
          }
        require(data.prolongation.rows() ==
                    hierarchy.levels[level + 1].n_unknowns &&
                  data.prolongation.cols() == data.n_unknowns,
                level,
                "the prolongation's shape");
        require(static_cast<Index>(data.constrained.size()) ==
                  data.lower_bound.size(),
                level,
                "one bound per constrained unknown");
        for (std::size_t k = 0; k < data.constrained.size(); ++k)
          require(std::isfinite(data.lower_bound[k]) &&
                    (k == 0 || data.constrained[k - 1] < data.constrained[k]),
                  level,
                  "bounds not finite or indices not increasing");
        check_nodes(hierarchy, level, data.constrained);
      }
  }
} // namespace unilateral::lcp
