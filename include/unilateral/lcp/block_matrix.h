#pragma once

#include <unilateral/lcp/problem.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace unilateral::lcp
{
  /**
   * 4 x 4 blocks, each distinct one stored once: a block is named by its
   * index here. Matrices of a uniform mesh repeat a few dozen blocks
   * millions of times (every interior node of the plate has the same
   * couplings, and so do its Galerkin coarse levels), so a product with
   * one reads an index per block instead of 128 bytes.
   */
  class BlockTable
  {
  public:
    using Block = Eigen::Matrix4d;
    using Id    = std::uint32_t;

    /// The index of @p block, added if it is new (bitwise comparison).
    Id
    intern(const Block &block);

    const Block &
    operator[](const Id id) const
    {
      return blocks[id];
    }

    const Block *
    data() const
    {
      return blocks.data();
    }

    std::size_t
    size() const
    {
      return blocks.size();
    }

  private:
    using Key = std::array<std::uint64_t, 16>;
    struct Hash
    {
      std::size_t
      operator()(const Key &key) const;
    };

    std::vector<Block>                blocks;
    std::unordered_map<Key, Id, Hash> index;
  };

  /**
   * A sparse matrix of 4 x 4 blocks in block compressed rows: one block row
   * and column per node of a mesh, for the multigrid methods
   * (truncated_multigrid.h), whose smoothers solve a node's block at once.
   * Vectors are in node layout: entries 4k..4k+3 are node k's unknowns,
   * padded with zeros where a node has fewer (a clamped DOF, or a block
   * size below 4). In a square matrix such a padding entry has a zero row
   * and column; the smoothers and the coarse solve read a zero diagonal
   * entry as "no unknown". The blocks are kept in a BlockTable.
   */
  class BlockMatrix
  {
  public:
    static constexpr int size = 4;
    using Block               = BlockTable::Block;
    using Id                  = BlockTable::Id;
    using NodeVector          = Eigen::Vector4d;

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
      return column.size();
    }

    /// The block at position @p p.
    const Block &
    block(const Index p) const
    {
      return table[ids[p]];
    }

    /// Its index in the matrix's table (equal blocks, equal indices).
    Id
    block_id(const Index p) const
    {
      return ids[p];
    }

    /// The block at position @p p set to @p value.
    void
    set_block(const Index p, const Block &value)
    {
      ids[p] = table.intern(value);
    }

    /// The diagonal block of row i.
    const Block &
    diagonal_block(const Index i) const
    {
      return block(diagonal[i]);
    }

    /// The position of block (i, j), which must be in the pattern.
    Index
    position(Index i, Index j) const;

    /// y = this x (node layout).
    void
    vmult(double *y, const double *x) const;

    /// y += this x.
    void
    vmult_add(double *y, const double *x) const;

    /// (b - this x) in node @p i's entries.
    NodeVector
    row_residual(Index i, const double *b, const double *x) const
    {
      NodeVector   r      = Eigen::Map<const NodeVector>(b + size * i);
      const Block *blocks = table.data();
      for (Index p = row_start[i]; p < row_start[i + 1]; ++p)
        r.noalias() -=
          blocks[ids[p]] * Eigen::Map<const NodeVector>(x + size * column[p]);
      return r;
    }

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

    /// Building row by row: a block at the end of the current row, and
    /// the end of that row.
    void
    append(const Index j, const Block &value)
    {
      column.push_back(j);
      ids.push_back(table.intern(value));
    }

    void
    end_row()
    {
      row_start.push_back(static_cast<Index>(column.size()));
    }

    /// The same matrix with the rows of the entries where @p mask is 0
    /// zeroed (M P for a diagonal 0/1 mask M, node layout).
    BlockMatrix
    rows_masked(const double *mask) const;

    /// Block compressed rows: row i's blocks are at the positions
    /// row_start[i] ... row_start[i + 1] - 1, columns increasing.
    std::vector<Index> row_start;
    std::vector<Index> column;
    /// The position of each row's diagonal block (square matrices).
    std::vector<Index> diagonal;

  private:
    Index           columns = 0;
    std::vector<Id> ids;
    BlockTable      table;

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

  /**
   * The inverses of a square BlockMatrix's diagonal blocks, masked
   * (masked_inverse), one per row, each distinct one computed and stored
   * once.
   */
  class DiagonalInverses
  {
  public:
    using Block = BlockMatrix::Block;

    /// Row @p i's inverse for the matrix's diagonal block and @p mask
    /// (4 entries; null: all 1). The matrix's table must only grow
    /// between calls (its indices name the blocks here).
    void
    set(const BlockMatrix &A, Index i, const double *mask);

    /// Every row's, with @p mask in node layout (null: all 1).
    void
    set_all(const BlockMatrix &A, const double *mask);

    const Block &
    operator[](const Index i) const
    {
      return table[ids[i]];
    }

  private:
    std::vector<BlockTable::Id> ids;
    BlockTable                  table;
    /// (diagonal block's table entry, mask bits) -> inverse.
    std::unordered_map<std::uint64_t, BlockTable::Id> known;
  };
} // namespace unilateral::lcp
