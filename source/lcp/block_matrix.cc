#include <unilateral/lcp/block_matrix.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cstring>
#include <numeric>

namespace unilateral::lcp
{
  namespace
  {
    using Block      = BlockMatrix::Block;
    using NodeVector = BlockMatrix::NodeVector;

    /**
     * The blocks of one row gathered before they are stored: a column's
     * block is found through a marker per column (-1: not in the row yet).
     */
    class RowAccumulator
    {
    public:
      explicit RowAccumulator(const Index n_columns)
        : position(n_columns, -1)
      {}

      Block &
      operator[](const Index column)
      {
        Index &p = position[column];
        if (p < 0)
          {
            p = static_cast<Index>(columns.size());
            columns.push_back(column);
            blocks.push_back(Block::Zero());
          }
        return blocks[p];
      }

      // Append the row, columns sorted, to @p matrix and start a new one.
      void
      flush(BlockMatrix &matrix)
      {
        order.resize(columns.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(),
                  order.end(),
                  [&](const Index a, const Index b) {
                    return columns[a] < columns[b];
                  });
        for (const Index k : order)
          {
            matrix.append(columns[k], blocks[k]);
            position[columns[k]] = -1;
          }
        matrix.end_row();
        columns.clear();
        blocks.clear();
      }

    private:
      std::vector<Index> position;
      std::vector<Index> columns;
      std::vector<Block> blocks;
      std::vector<Index> order;
    };
  } // namespace

  std::size_t
  BlockTable::Hash::operator()(const Key &key) const
  {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (const std::uint64_t word : key)
      h = (h ^ word) * 0x100000001b3ULL + (h >> 29);
    return static_cast<std::size_t>(h);
  }

  BlockTable::Id
  BlockTable::intern(const Block &block)
  {
    Key key;
    std::memcpy(key.data(), block.data(), sizeof(Key));
    const auto [entry, added] =
      index.try_emplace(key, static_cast<Id>(blocks.size()));
    if (added)
      blocks.push_back(block);
    return entry->second;
  }

  BlockMatrix::NodeMap
  BlockMatrix::node_map(const std::vector<Index> &nodes,
                        const unsigned int        block_size,
                        const Index               n_unknowns)
  {
    NodeMap map;
    map.n_nodes = static_cast<Index>(nodes.size() / block_size);
    map.node.assign(n_unknowns, -1);
    map.component.assign(n_unknowns, 0);
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (nodes[k] >= 0)
        {
          map.node[nodes[k]]      = static_cast<Index>(k / block_size);
          map.component[nodes[k]] = static_cast<int>(k % block_size);
        }
    return map;
  }

  BlockMatrix
  BlockMatrix::transpose_of(const SparseMatrix &M,
                            const NodeMap      &rows,
                            const NodeMap      &columns,
                            const bool          diagonal)
  {
    // The columns of M node by node.
    std::vector<Index> start(columns.n_nodes + 1, 0);
    for (Index j = 0; j < M.cols(); ++j)
      ++start[columns.node[j] + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<Index> by_node(M.cols());
    {
      std::vector<Index> next(start.begin(), start.end() - 1);
      for (Index j = 0; j < M.cols(); ++j)
        by_node[next[columns.node[j]]++] = j;
    }

    BlockMatrix result;
    result.columns = rows.n_nodes;
    result.row_start.reserve(columns.n_nodes + 1);
    result.row_start.push_back(0);
    RowAccumulator row(rows.n_nodes);
    for (Index J = 0; J < columns.n_nodes; ++J)
      {
        if (diagonal)
          row[J];
        for (Index k = start[J]; k < start[J + 1]; ++k)
          {
            const Index j = by_node[k];
            const int   c = columns.component[j];
            for (SparseMatrix::InnerIterator it(M, j); it; ++it)
              row[rows.node[it.row()]](c, rows.component[it.row()]) =
                it.value();
          }
        row.flush(result);
      }
    if (diagonal)
      result.find_diagonal();
    return result;
  }

  void
  BlockMatrix::find_diagonal()
  {
    diagonal.resize(n_rows());
    for (Index i = 0; i < n_rows(); ++i)
      diagonal[i] = position(i, i);
  }

  Index
  BlockMatrix::position(const Index i, const Index j) const
  {
    return static_cast<Index>(
      std::lower_bound(column.begin() + row_start[i],
                       column.begin() + row_start[i + 1],
                       j) -
      column.begin());
  }

  void
  BlockMatrix::vmult(double *y, const double *x) const
  {
    const Block *blocks = table.data();
    for (Index i = 0; i < n_rows(); ++i)
      {
        NodeVector sum = NodeVector::Zero();
        for (Index p = row_start[i]; p < row_start[i + 1]; ++p)
          sum.noalias() +=
            blocks[ids[p]] * Eigen::Map<const NodeVector>(x + size * column[p]);
        Eigen::Map<NodeVector>(y + size * i) = sum;
      }
  }

  void
  BlockMatrix::vmult_add(double *y, const double *x) const
  {
    const Block *blocks = table.data();
    for (Index i = 0; i < n_rows(); ++i)
      {
        NodeVector sum = NodeVector::Zero();
        for (Index p = row_start[i]; p < row_start[i + 1]; ++p)
          sum.noalias() +=
            blocks[ids[p]] * Eigen::Map<const NodeVector>(x + size * column[p]);
        Eigen::Map<NodeVector>(y + size * i) += sum;
      }
  }

  BlockMatrix
  BlockMatrix::transpose() const
  {
    // The transposed table: entry k is block k transposed, so the ids
    // carry over.
    BlockMatrix result;
    for (std::size_t k = 0; k < table.size(); ++k)
      result.table.intern(table[static_cast<Id>(k)].transpose());
    result.columns = n_rows();
    result.row_start.assign(columns + 1, 0);
    for (const Index j : column)
      ++result.row_start[j + 1];
    std::partial_sum(result.row_start.begin(),
                     result.row_start.end(),
                     result.row_start.begin());
    result.column.resize(column.size());
    result.ids.resize(ids.size());
    std::vector<Index> next(result.row_start.begin(),
                            result.row_start.end() - 1);
    for (Index i = 0; i < n_rows(); ++i)
      for (Index p = row_start[i]; p < row_start[i + 1]; ++p)
        {
          const Index q    = next[column[p]]++;
          result.column[q] = i;
          result.ids[q]    = ids[p];
        }
    if (result.n_rows() == result.columns && columns == n_rows() &&
        !diagonal.empty())
      result.find_diagonal();
    return result;
  }

  BlockMatrix
  BlockMatrix::galerkin(const BlockMatrix &P,
                        const BlockMatrix &P_transpose) const
  {
    BlockMatrix result;
    result.columns = P.n_columns();
    result.row_start.reserve(P.n_columns() + 1);
    result.row_start.push_back(0);
    RowAccumulator row(P.n_columns());
    for (Index I = 0; I < P_transpose.n_rows(); ++I)
      {
        row[I];
        for (Index a = P_transpose.row_start[I];
             a < P_transpose.row_start[I + 1];
             ++a)
          {
            const Index i = P_transpose.column[a];
            for (Index p = row_start[i]; p < row_start[i + 1]; ++p)
              {
                const Block left = P_transpose.block(a) * block(p);
                const Index j    = column[p];
                for (Index b = P.row_start[j]; b < P.row_start[j + 1]; ++b)
                  row[P.column[b]].noalias() += left * P.block(b);
              }
          }
        row.flush(result);
      }
    result.find_diagonal();
    return result;
  }

  void
  BlockMatrix::galerkin_rows(const BlockMatrix        &A,
                             const BlockMatrix        &P,
                             const BlockMatrix        &P_transpose,
                             const std::vector<Index> &rows)
  {
    std::vector<Index> position(n_columns(), -1);
    std::vector<Block> sums;
    for (const Index I : rows)
      {
        sums.assign(row_start[I + 1] - row_start[I], Block::Zero());
        for (Index p = row_start[I]; p < row_start[I + 1]; ++p)
          position[column[p]] = p - row_start[I];
        for (Index a = P_transpose.row_start[I];
             a < P_transpose.row_start[I + 1];
             ++a)
          {
            const Index i = P_transpose.column[a];
            for (Index p = A.row_start[i]; p < A.row_start[i + 1]; ++p)
              {
                const Block left = P_transpose.block(a) * A.block(p);
                const Index j    = A.column[p];
                for (Index b = P.row_start[j]; b < P.row_start[j + 1]; ++b)
                  sums[position[P.column[b]]].noalias() += left * P.block(b);
              }
          }
        for (Index p = row_start[I]; p < row_start[I + 1]; ++p)
          {
            set_block(p, sums[p - row_start[I]]);
            position[column[p]] = -1;
          }
      }
  }

  BlockMatrix
  BlockMatrix::rows_masked(const double *mask) const
  {
    BlockMatrix result = *this;
    for (Index i = 0; i < n_rows(); ++i)
      {
        const Eigen::Map<const NodeVector> m(mask + size * i);
        if (m.minCoeff() == 1)
          continue;
        for (Index p = row_start[i]; p < row_start[i + 1]; ++p)
          result.set_block(p, m.asDiagonal() * block(p));
      }
    return result;
  }

  BlockMatrix::Block
  masked_inverse(const BlockMatrix::Block &block, const double *mask)
  {
    // The kept entries: masked in and with a positive diagonal (relative
    // to the block's largest: a coarse padding entry is zero up to the
    // round-off of the Galerkin product).
    const double largest = block.diagonal().cwiseAbs().maxCoeff();
    NodeVector   kept;
    for (int c = 0; c < BlockMatrix::size; ++c)
      kept[c] = mask[c] != 0 && block(c, c) > 1e-14 * largest ? 1.0 : 0.0;
    // The kept rows and columns, identity elsewhere: invertible where the
    // kept block is.
    Block reduced = kept.asDiagonal() * block * kept.asDiagonal();
    reduced.diagonal() += NodeVector::Ones() - kept;
    const Block inverse = Eigen::LDLT<Block>(reduced).solve(Block::Identity());
    return kept.asDiagonal() * inverse * kept.asDiagonal();
  }

  void
  DiagonalInverses::set(const BlockMatrix &A, const Index i, const double *mask)
  {
    const double  all[BlockMatrix::size] = {1, 1, 1, 1};
    const double *m                      = mask != nullptr ? mask : all;
    // The same block with the same mask has the same inverse.
    std::uint64_t key = A.block_id(A.diagonal[i]);
    for (int c = 0; c < BlockMatrix::size; ++c)
      key = 2 * key + (m[c] != 0 ? 1 : 0);
    const auto [entry, added] = known.try_emplace(key, 0);
    if (added)
      entry->second = table.intern(masked_inverse(A.diagonal_block(i), m));
    ids[i] = entry->second;
  }

  void
  DiagonalInverses::set_all(const BlockMatrix &A, const double *mask)
  {
    // A new matrix: its table's indices mean other blocks now.
    known.clear();
    table = BlockTable();
    ids.resize(A.n_rows());
    for (Index i = 0; i < A.n_rows(); ++i)
      set(A, i, mask != nullptr ? mask + BlockMatrix::size * i : nullptr);
  }
} // namespace unilateral::lcp
