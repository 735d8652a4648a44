#include <unilateral/base/disjoint_sets.h>

#include <numeric>
#include <utility>

namespace unilateral
{
  DisjointSets::DisjointSets(const std::size_t n)
    : parent(n)
    , size(n, 1)
  {
    std::iota(parent.begin(), parent.end(), std::size_t(0));
  }

  std::size_t
  DisjointSets::find(std::size_t v)
  {
    while (parent[v] != v)
      {
        parent[v] = parent[parent[v]];
        v         = parent[v];
      }
    return v;
  }

  bool
  DisjointSets::unite(std::size_t a, std::size_t b)
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
} // namespace unilateral
