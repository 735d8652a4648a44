#include <unilateral/base/disjoint_sets.h>
#include <unilateral/base/text.h>
#include <unilateral/scenes/masonry/free_motions.h>
#include <unilateral/scenes/masonry/mechanism.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    using Sparse = Eigen::SparseMatrix<double>;

    /// The blocks' centres and sizes (largest distance of a node from the
    /// centre), in which their rigid motions are written: u(x) = t + w x
    /// (x - centre) / size, every column of one scale.
    template <int dim>
    struct BlockFrames
    {
      explicit BlockFrames(const ContactSet<dim> &contacts)
      {
        n_blocks = n_blocks_of(contacts);
        centre.assign(n_blocks, {});
        size.assign(n_blocks, 0);
        std::vector<unsigned int> n_nodes(n_blocks, 0);
        for (std::size_t i = 0; i < contacts.node_position.size(); ++i)
          {
            const unsigned int b = contacts.node_block[i];
            for (unsigned int d = 0; d < dim; ++d)
              centre[b][d] += contacts.node_position[i][d];
            ++n_nodes[b];
          }
        for (unsigned int b = 0; b < n_blocks; ++b)
          for (unsigned int d = 0; d < dim; ++d)
            centre[b][d] /= std::max(n_nodes[b], 1u);
        for (std::size_t i = 0; i < contacts.node_position.size(); ++i)
          {
            const unsigned int b = contacts.node_block[i];
            double             r = 0;
            for (unsigned int d = 0; d < dim; ++d)
              r += std::pow(contacts.node_position[i][d] - centre[b][d], 2);
            size[b] = std::max(size[b], std::sqrt(r));
          }
      }

      unsigned int                         n_blocks = 0;
      std::vector<std::array<double, dim>> centre;
      std::vector<double>                  size;
    };

    /// One condition a mechanism keeps, on the rigid motions of one block
    /// (a support) or two (a joint): sum over its parts of coefficients .
    /// (t, w) of the part's block = 0.
    template <int dim>
    struct Condition
    {
      unsigned int                                            n_parts = 0;
      std::array<unsigned int, 2>                             block{};
      std::array<std::array<double, n_rigid_motions(dim)>, 2> coefficients{};
      /// Where it acts (a joint's two nodes coincide).
      std::array<double, dim> position{};
    };

    /// The conditions: n . (u_lower - u_upper) for a closed joint, n . u for
    /// a closed Signorini contact and a roller, every component of u for a
    /// held node.
    template <int dim>
    std::vector<Condition<dim>>
    kept_conditions(const ContactSet<dim>   &contacts,
                    const std::vector<char> &closed,
                    const BlockFrames<dim>  &frames)
    {
      std::vector<Condition<dim>> result;
      const auto                  add = [&](Condition<dim>                &c,
                           const unsigned int             node,
                           const std::array<double, dim> &n,
                           const double                   sign) {
        const unsigned int b = contacts.node_block[node];
        auto              &a = c.coefficients[c.n_parts];
        a                    = rigid_row<dim>(n,
                           contacts.node_position[node],
                           frames.centre[b],
                           frames.size[b]);
        for (double &entry : a)
          entry *= sign;
        c.block[c.n_parts++] = b;
      };
      for (const HeldNode<dim> &h : contacts.held)
        for (unsigned int d = 0; d < dim; ++d)
          {
            std::array<double, dim> e{};
            e[d] = 1;
            add(result.emplace_back(), h.node, e, 1);
          }
      for (const Roller<dim> &r : contacts.rollers)
        add(result.emplace_back(), r.node, r.normal, 1);
      for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
        if (closed[k])
          {
            const UnilateralConstraint<dim> &c   = contacts.constraints[k];
            Condition<dim>                  &row = result.emplace_back();
            add(row, c.lower, c.normal, 1);
            row.position = contacts.node_position[c.lower];
            if (c.kind == ConstraintKind::joint)
              add(row, c.upper, c.normal, -1);
          }
      return result;
    }

    /**
     * The conditions' Gram matrix is scaled block by block (one scale for a
     * block's rigid motions, so that turning the structure changes
     * nothing: a scale per motion made a slide along an axis, held only
     * by a support tilted by 2e-5, free at 0 degrees and held at 30, a
     * review); a motion whose scaled curvature is below mechanism_threshold
     * is a mechanism: one that changes the closed gaps by less than 1e-7 of
     * its size, where the rows themselves are rounded to about 1e-16 (a
     * structure 1e5 from the origin: 1e-10). A block is held from the
     * supports up (held_blocks) only beyond held_threshold: a block held
     * more weakly is left to the whole computation.
     */
    constexpr double mechanism_threshold = 1e-14, held_threshold = 1e-9;

    /// 1 / sqrt(mean diagonal) of @p gram, or 1 for a zero one.
    template <typename Matrix>
    double
    block_scale(const Matrix &gram)
    {
      const double mean = gram.trace() / gram.rows();
      return mean > 0 ? 1 / std::sqrt(mean) : 1;
    }

    /**
     * The blocks that no mechanism moves, found from the supports up: a
     * block whose conditions with the ground and with blocks found already
     * hold each of its rigid motions (their scaled Gram matrix has no
     * eigenvalue below held_threshold) is held. On most walls this finds
     * every block, and the null space is then not computed at all (on the
     * stack bond m = 225 that took 1.6 s).
     */
    template <int dim>
    std::vector<char>
    held_blocks(const std::vector<Condition<dim>> &conditions,
                const unsigned int                 n_blocks)
    {
      constexpr unsigned int                 nr = n_rigid_motions(dim);
      std::vector<std::vector<unsigned int>> of_block(n_blocks);
      for (unsigned int i = 0; i < conditions.size(); ++i)
        for (unsigned int p = 0; p < conditions[i].n_parts; ++p)
          of_block[conditions[i].block[p]].push_back(i);
      std::vector<char>         held(n_blocks, 0), queued(n_blocks, 0);
      std::vector<unsigned int> queue;
      // Each block once in the queue (a slab on 10,000 support nodes was
      // queued and checked once per node, a review).
      const auto enqueue = [&](const unsigned int b) {
        if (!held[b] && !queued[b])
          {
            queued[b] = 1;
            queue.push_back(b);
          }
      };
      for (const Condition<dim> &c : conditions)
        if (c.n_parts == 1)
          enqueue(c.block[0]);
      while (!queue.empty())
        {
          const unsigned int b = queue.back();
          queue.pop_back();
          queued[b] = 0;
          Eigen::Matrix<double, nr, nr> gram =
            Eigen::Matrix<double, nr, nr>::Zero();
          for (const unsigned int i : of_block[b])
            {
              const Condition<dim> &c = conditions[i];
              const unsigned int    p = c.block[0] == b ? 0 : 1;
              if (c.n_parts == 1 || held[c.block[1 - p]])
                {
                  const Eigen::Map<const Eigen::Matrix<double, nr, 1>> a(
                    c.coefficients[p].data());
                  gram += a * a.transpose();
                }
            }
          const double s = block_scale(gram);
          if (Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, nr, nr>>(
                s * s * gram, Eigen::EigenvaluesOnly)
                .eigenvalues()
                .minCoeff() <= held_threshold)
            continue;
          held[b] = 1;
          for (const unsigned int i : of_block[b])
            for (unsigned int p = 0; p < conditions[i].n_parts; ++p)
              enqueue(conditions[i].block[p]);
        }
      return held;
    }

    /**
     * Whether @p motion moves the blocks of every closed joint as one body
     * (the same displacement of both nodes, not only along the normal): a
     * rigid motion of groups of blocks, which free_rigid_motions() noted
     * before solving where it is free.
     */
    template <int dim>
    bool
    moves_joined_blocks_as_one(const std::vector<Condition<dim>> &conditions,
                               const std::vector<char>           &held,
                               const std::vector<unsigned int>   &column_of,
                               const BlockFrames<dim>            &frames,
                               const Eigen::VectorXd             &motion)
    {
      const double scale = motion.template lpNorm<Eigen::Infinity>();
      for (const Condition<dim> &c : conditions)
        if (c.n_parts == 2)
          {
            std::array<std::array<double, dim>, 2> u{};
            for (unsigned int p = 0; p < 2; ++p)
              if (!held[c.block[p]])
                u[p] =
                  rigid_displacement<dim>(motion.data() + column_of[c.block[p]],
                                          c.position,
                                          frames.centre[c.block[p]],
                                          frames.size[c.block[p]]);
            for (unsigned int d = 0; d < dim; ++d)
              if (std::abs(u[0][d] - u[1][d]) > 1e-6 * scale)
                return false;
          }
      return true;
    }

    /// "blocks 15 and 17", "blocks 3, 4, 5, 6 and 12 more".
    std::string
    block_list(const std::vector<unsigned int> &blocks)
    {
      constexpr std::size_t named = 4;
      std::string           text  = blocks.size() == 1 ? "block " : "blocks ";
      for (std::size_t i = 0; i < std::min(blocks.size(), named); ++i)
        text += (i == 0                                           ? "" :
                 i + 1 == blocks.size() && blocks.size() <= named ? " and " :
                                                                    ", ") +
                std::to_string(blocks[i]);
      if (blocks.size() > named)
        text += " and " + std::to_string(blocks.size() - named) + " more";
      return text;
    }
  } // namespace

  template <int dim>
  std::string
  answer_mechanism(const ContactSet<dim>   &contacts,
                   const std::vector<char> &closed,
                   const bool               floating_noted)
  {
    const BlockFrames<dim> frames(contacts);
    if (frames.n_blocks == 0)
      return "";
    const std::vector<Condition<dim>> conditions =
      kept_conditions(contacts, closed, frames);
    std::vector<char> held = held_blocks(conditions, frames.n_blocks);
    if (floating_noted)
      {
        // Sets of blocks joined by closed contacts that no closed contact
        // or support joins to anything held: their rigid motion is the
        // free one noted before solving; set aside, so that a mechanism
        // elsewhere is still found (a loose block beside an arch hid the
        // arch's, a review).
        DisjointSets sets(frames.n_blocks);
        for (const Condition<dim> &c : conditions)
          if (c.n_parts == 2 && !held[c.block[0]] && !held[c.block[1]])
            sets.unite(c.block[0], c.block[1]);
        std::vector<char> anchored(frames.n_blocks, 0);
        for (const Condition<dim> &c : conditions)
          for (unsigned int p = 0; p < c.n_parts; ++p)
            if (!held[c.block[p]] && (c.n_parts == 1 || held[c.block[1 - p]]))
              anchored[sets.find(c.block[p])] = 1;
        for (unsigned int b = 0; b < frames.n_blocks; ++b)
          held[b] = held[b] || !anchored[sets.find(b)];
      }
    // The others, column by column; a held block's motion is 0.
    constexpr unsigned int    nr = n_rigid_motions(dim);
    std::vector<unsigned int> column_of(frames.n_blocks, 0), free_blocks;
    for (unsigned int b = 0; b < frames.n_blocks; ++b)
      if (!held[b])
        {
          column_of[b] = nr * free_blocks.size();
          free_blocks.push_back(b);
        }
    if (free_blocks.empty())
      return "";
    std::vector<Eigen::Triplet<double>> entries;
    int                                 row = 0;
    for (const Condition<dim> &c : conditions)
      {
        bool touches = false;
        for (unsigned int p = 0; p < c.n_parts; ++p)
          if (!held[c.block[p]])
            {
              touches = true;
              for (unsigned int j = 0; j < nr; ++j)
                entries.emplace_back(row,
                                     column_of[c.block[p]] + j,
                                     c.coefficients[p][j]);
            }
        row += touches;
      }
    Sparse M(row, nr * free_blocks.size());
    M.setFromTriplets(entries.begin(), entries.end());
    Sparse gram = Sparse(M.transpose()) * M;
    // Scaled block by block; a block no condition touches (nothing holds
    // it) is a mechanism by itself.
    Eigen::VectorXd scale(gram.cols());
    for (const unsigned int b : free_blocks)
      scale.segment(column_of[b], nr)
        .setConstant(block_scale(
          Eigen::MatrixXd(gram.block(column_of[b], column_of[b], nr, nr))));
    gram = scale.asDiagonal() * gram * scale.asDiagonal();

    // Inverse iteration: the Rayleigh quotient of any vector bounds the
    // smallest eigenvalue from above, so a quotient below the threshold
    // proves a mechanism; two steps leave of every other direction (shift /
    // its eigenvalue)^2. The shift keeps the factorisation of an exactly
    // singular matrix from meeting a pivot of rounding.
    constexpr double shift   = 1e-12;
    Sparse           shifted = gram;
    for (Eigen::Index j = 0; j < shifted.cols(); ++j)
      shifted.coeffRef(j, j) += shift;
    Eigen::SimplicialLDLT<Sparse> factor(shifted);
    if (factor.info() != Eigen::Success)
      return "";
    Eigen::VectorXd x(gram.cols());
    for (Eigen::Index j = 0; j < x.size(); ++j)
      x[j] = 1 + 0.5 * std::sin(12.9898 *
                                static_cast<double>(j)); // no mode is missed
    for (int step = 0; step < 2; ++step)
      {
        x = factor.solve(x);
        x /= x.norm();
      }
    if (!x.allFinite() || x.dot(gram * x) > mechanism_threshold)
      return "";

    const Eigen::VectorXd motion = scale.cwiseProduct(x);
    if (floating_noted &&
        moves_joined_blocks_as_one(conditions, held, column_of, frames, motion))
      return ""; // the free rigid motion of a group, noted already

    // The blocks it moves, by their share of the largest motion.
    std::vector<double> amount(frames.n_blocks, 0);
    for (const unsigned int b : free_blocks)
      amount[b] = motion.segment(column_of[b], nr).norm();
    const double largest = *std::max_element(amount.begin(), amount.end());
    std::vector<unsigned int> moving;
    for (unsigned int b = 0; b < frames.n_blocks; ++b)
      if (amount[b] > 1e-3 * largest)
        moving.push_back(b);
    std::ostringstream where;
    where.precision(8);
    for (unsigned int d = 0; d < dim; ++d)
      where << (d == 0 ? "(" : ", ") << frames.centre[moving.front()][d];
    return block_list(moving) + " (the first centred at " + where.str() +
           ")) can move as rigid bodies without opening a closed contact or "
           "moving a support";
  }

  template std::string
  answer_mechanism(const ContactSet<2> &, const std::vector<char> &, bool);
  template std::string
  answer_mechanism(const ContactSet<3> &, const std::vector<char> &, bool);
} // namespace unilateral::masonry
