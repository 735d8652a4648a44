#pragma once

#include <cstddef>
#include <vector>

namespace unilateral
{
  /**
   * Disjoint sets of the indices 0 ... n-1 (union-find with path halving
   * and union by size): the groups of blocks linked by joints, the trees
   * of the change of variables, the cells of one block in a mesh file.
   */
  class DisjointSets
  {
  public:
    explicit DisjointSets(std::size_t n);

    /// The representative of the set holding @p v.
    std::size_t
    find(std::size_t v);

    /// Joins the sets of @p a and @p b; false if they were one already.
    bool
    unite(std::size_t a, std::size_t b);

  private:
    std::vector<std::size_t> parent;
    std::vector<std::size_t> size;
  };
} // namespace unilateral
