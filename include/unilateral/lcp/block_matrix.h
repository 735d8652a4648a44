#pragma once

#include <unilateral/lcp/problem.h>

#include <Eigen/Core>

#include <vector>

namespace unilateral::lcp
{
  /**
   * A sparse matrix of 4 x 4 blocks in block compressed rows: one block row
   * and column per node of a mesh, for the multigrid methods
   * (truncated_multigrid.h), whose smoothers solve a node's block at once.
   * Vectors are in node layout: entries 4k..4k+3 are node k's unknowns,
   * padded with zeros where a node has fewer (a clamped DOF, or a block
   * size below 4). In a square matrix such a padding entry has a zero row
   * and column; the smoothers and the coarse solve read a zero diagonal
   * entry as "no unknown".
   *
   * Eigen's sparse matrices hold scalars: a node's 16 couplings cost 16
   * index lookups there and one here, and a block Gauss-Seidel step needs
   * the block anyway.
   */
  class BlockMatrix
  {
  public:
    static constexpr int size = 4;
    using Block             = Eigen::Matrix4d;
    using NodeVector        = Eigen::Vector4d;

    /// Per unknown of one side: its node and its place in the node.
    struct NodeMap
    {
      std::vector<Index> node;
      std::vector<int>   component;
      Index              n_nodes = 0;
    };

    /**
     * The map of @p nodes (block_size entries per node, -1 for none) over
     * @p n_unknowns unknowns.
     */
    static NodeMap
    node_map(const std::vector<Index> &nodes,
             unsigned int              block_size,
             Index                     n_unknowns);

    /**
     * The blocks of M^T for M with rows in @p rows and columns in
     * @p columns: row J of the result holds the couplings of M's column
     * node J (for a symmetric M, M itself). With @p diagonal every row
     * gets its diagonal block, even if M has no entry there.
     */
    static BlockMatrix
    transpose_of(const SparseMatrix &M,
                 const NodeMap      &rows,
                 const NodeMap      &columns,
                 bool                diagonal);

    Index
    n_rows() const
    {
      return static_cast<Index>(row_start.size()) - 1;
    }

    Index
    n_columns() const
    {
      return columns;
    }

    std::size_t
    n_blocks() const
    {
      return blocks.size();
    }

    /// y = this x (node layout).
    void
    vmult(double *y, const double *x) const;

    /// y += this x.
    void
    vmult_add(double *y, const double *x) const;

    /// The transpose.
    BlockMatrix
    transpose() const;

    /**
     * P^T this P, with @p P_transpose = P^T (its block rows are P's
     * columns): the Galerkin product, row by row of the result
     * (Gustavson's algorithm on blocks).
     */
    BlockMatrix
    galerkin(const BlockMatrix &P, const BlockMatrix &P_transpose) const;

    /**
     * Recompute the rows @p rows of this matrix, P^T A P (made by
     * galerkin() from the same P's pattern), after A or P changed there;
     * the pattern stays (the changes only zero contributions).
     */
    void
    galerkin_rows(const BlockMatrix        &A,
                  const BlockMatrix        &P,
                  const BlockMatrix        &P_transpose,
                  const std::vector<Index> &rows);

    /// The position of block (i, j), which must be in the pattern.
    Index
    position(Index i, Index j) const;

    /// The same matrix with the rows of the entries where @p mask is 0
    /// zeroed (M P for a diagonal 0/1 mask M, node layout).
    BlockMatrix
    rows_masked(const double *mask) const;

    /// The diagonal block of row i.
    const Block &
    diagonal_block(const Index i) const
    {
      return blocks[diagonal[i]];
    }

    /// Block compressed rows: row i's blocks are row_start[i] ...
    /// row_start[i + 1] - 1, columns increasing.
    std::vector<Index> row_start;
    std::vector<Index> column;
    std::vector<Block> blocks;
    /// The position of each row's diagonal block (square matrices).
    std::vector<Index> diagonal;

  private:
    Index columns = 0;

    void
    find_diagonal();
  };

  /**
   * The inverse of a diagonal block on the entries where @p mask is 1 and
   * the diagonal is positive, zero elsewhere (a masked or missing unknown
   * stays where it is).
   */
  BlockMatrix::Block
  masked_inverse(const BlockMatrix::Block &block, const double *mask);
} // namespace unilateral::lcp
