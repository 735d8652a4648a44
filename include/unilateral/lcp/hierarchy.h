#pragma once

#include <unilateral/lcp/problem.h>

#include <vector>

namespace unilateral::lcp
{
  /**
   * A problem discretised on a sequence of meshes, coarsest first, for the
   * multigrid methods: the last level is the Problem itself, and each level
   * carries its unknowns to the next finer one. Built by a scene that has
   * such meshes (the plate's uniformly refined Bogner-Fox-Schmit meshes);
   * the solver layer knows nothing else of them.
   *
   * A level's unknowns are grouped by node, block_size entries per node (a
   * plate node: w, w_x, w_y, w_xy), the blocks a block smoother solves at
   * once. A node may lack some of them (a clamped DOF): -1 there. At most
   * one unknown of a node is constrained (the plate's w), so that a node's
   * block with its bound is solved exactly by one projection.
   *
   * The coarse levels' problems are derived, not given: A_l = P_l^T A_{l+1}
   * P_l (Galerkin) and b_l = P_l^T b_{l+1}, with the bounds the scene gives
   * for the coarse nodes (the obstacle there). Where the meshes are nested
   * and the prolongation is the exact interpolation, A_l and b_l are the
   * coarse mesh's own stiffness and load.
   */
  struct Hierarchy
  {
    /// The largest block size the multigrid methods take.
    static constexpr unsigned int max_block_size = 4;

    struct Level
    {
      /// The number of this level's unknowns (the finest: the problem's).
      Index n_unknowns = 0;
      /// Node k's unknowns are nodes[block_size k + c], c < block_size, or
      /// -1 where it has none; every unknown belongs to exactly one node.
      std::vector<Index> nodes;
      /// The constrained unknowns of a coarse level, strictly increasing,
      /// and their lower bounds (on the finest level both stay empty: the
      /// problem's S and l_S are used).
      std::vector<Index> constrained;
      Vector             lower_bound;
      /// P_l: u_{l+1} = P_l u_l carries this level's unknowns to the next
      /// finer level's (n_{l+1} x n_l); empty on the finest level.
      SparseMatrix prolongation;
    };

    unsigned int       block_size = 1;
    std::vector<Level> levels;

    Index
    n_nodes(const unsigned int level) const
    {
      return static_cast<Index>(levels[level].nodes.size() / block_size);
    }
  };

  /**
   * Check that @p hierarchy fits @p problem and itself: block size, the
   * finest level's unknowns are the problem's, each level's nodes cover its
   * unknowns once, the prolongations' shapes, the coarse bounds (finite,
   * sorted, in range) and at most one constrained unknown per node (the
   * finest level's from the problem's S). Throws std::logic_error naming
   * what is wrong: a hierarchy is built by a scene, not given by a user.
   */
  void
  check_hierarchy(const Hierarchy &hierarchy, const Problem &problem);
} // namespace unilateral::lcp
