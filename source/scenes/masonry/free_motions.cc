#include <unilateral/base/disjoint_sets.h>
#include <unilateral/base/text.h>
#include <unilateral/scenes/masonry/free_motions.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    /// The rounding of a unit quantity.
    constexpr double epsilon = std::numeric_limits<double>::epsilon();

    template <int dim>
    using RigidVector = Eigen::Matrix<double, n_rigid_motions(dim), 1>;

    template <int dim>
    std::string
    point_text(const std::array<double, dim> &p)
    {
      std::ostringstream text;
      // Enough digits for a point of a structure far from the origin.
      text.precision(8);
      text << "(";
      for (unsigned int c = 0; c < dim; ++c)
        text << (c > 0 ? ", " : "") << (std::abs(p[c]) < 1e-12 ? 0.0 : p[c]);
      text << ")";
      return text.str();
    }

    /**
     * One free motion in words: u(x) = t + (w / size) x (x - centre) for
     * the basis vector (t, w). A translation if w vanishes; in 2D else a
     * rotation about the point where u = 0; in 3D a rotation about the
     * axis through the point nearest to the centre where u is along w.
     */
    template <int dim>
    std::string
    describe_motion(const RigidVector<dim>        &v,
                    const std::array<double, dim> &centre,
                    const double                   size)
    {
      constexpr unsigned int  n_rotations = n_rigid_motions(dim) - dim;
      std::array<double, dim> t{};
      for (unsigned int c = 0; c < dim; ++c)
        t[c] = v[c];
      Eigen::Matrix<double, n_rotations, 1> w =
        v.template tail<n_rotations>() / size;
      if (w.norm() * size <= 1e-8)
        {
          const double length = v.template head<dim>().norm();
          for (double &x : t)
            x /= length;
          return "translation along " + point_text<dim>(t);
        }
      std::array<double, dim> point = centre;
      if constexpr (dim == 2)
        {
          point[0] -= t[1] / w[0];
          point[1] += t[0] / w[0];
          return "rotation about " + point_text<dim>(point);
        }
      else
        {
          const Eigen::Vector3d   tt(t[0], t[1], t[2]);
          const Eigen::Vector3d   ww(w[0], w[1], w[2]);
          const Eigen::Vector3d   shift = ww.cross(tt) / ww.squaredNorm();
          std::array<double, dim> axis{};
          for (unsigned int c = 0; c < dim; ++c)
            {
              point[c] += shift[c];
              axis[c] = ww[c] / ww.norm();
            }
          return "rotation about the axis through " + point_text<dim>(point) +
                 " along " + point_text<dim>(axis);
        }
    }

    /// The row of a support acting along @p normal at @p p (rigid_row).
    template <int dim>
    RigidVector<dim>
    support_row(const std::array<double, dim> &normal,
                const std::array<double, dim> &p,
                const std::array<double, dim> &centre,
                const double                   size)
    {
      const auto row = rigid_row<dim>(normal, p, centre, size);
      return Eigen::Map<const RigidVector<dim>>(row.data());
    }

    /**
     * A basis of the null space of the support rows @p rows: the right
     * singular vectors whose singular value is below @p rounding (that of
     * the rows' entries, which are of size 1) times a hundred times the
     * root of their number. The singular values of the rows, not the
     * eigenvalues of their Gram matrix, whose rounding (epsilon of the
     * largest) is that of a singular value of 1e-8: a block in a V-groove
     * of 5e-6 turns about a far point by a motion that the groove resists,
     * whose Gram eigenvalue 2.5e-11 of the largest was once taken as zero
     * (a review). Translations first: the vectors of a null space of more
     * than one dimension mix translations and rotations at random, so the
     * pure translations in it are found first (where the rotation parts
     * vanish) and the rest is made orthogonal to them.
     */
    template <int dim>
    std::vector<RigidVector<dim>>
    free_basis(const std::vector<RigidVector<dim>> &rows, const double rounding)
    {
      constexpr int   n_rotations = n_rigid_motions(dim) - dim;
      constexpr int   n           = n_rigid_motions(dim);
      Eigen::MatrixXd R(std::max<std::size_t>(rows.size(), n), n);
      R.setZero();
      for (std::size_t r = 0; r < rows.size(); ++r)
        R.row(r) = rows[r].transpose();
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(R, Eigen::ComputeFullV);
      const double     zero = 1e2 * rounding * std::sqrt(double(rows.size()));
      std::vector<int> null;
      for (int i = 0; i < n; ++i)
        if (!(svd.singularValues()[i] > zero))
          null.push_back(i);
      if (null.empty())
        return {};
      Eigen::MatrixXd N(n, null.size());
      for (std::size_t j = 0; j < null.size(); ++j)
        N.col(j) = svd.matrixV().col(null[j]);
      // In the coordinates a of v = N a: the rotation parts' Gram matrix,
      // zero along the translations.
      const Eigen::MatrixXd rotations = N.bottomRows(n_rotations);
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> split(
        rotations.transpose() * rotations);
      std::vector<RigidVector<dim>> basis;
      for (int pass = 0; pass < 2; ++pass)
        for (int j = 0; j < int(null.size()); ++j)
          if ((split.eigenvalues()[j] <= 1e-12) == (pass == 0))
            basis.push_back(N * split.eigenvectors().col(j));
      return basis;
    }

    /// What one group's nodes and supports add up to.
    template <int dim>
    struct Group
    {
      std::vector<unsigned int> blocks;
      std::array<double, dim>   centre{};
      double                    size       = 0;
      unsigned int              n_nodes    = 0;
      unsigned int              first_node = 0;
      /// The largest coordinate of its nodes.
      double farthest = 0;
      /**
       * The rounding of its support rows (of size 1): epsilon times the
       * largest coordinate over the shortest support face, estimated as
       * the group's size over the number of rows (2D) or its root (3D).
       * Joints' normals are snapped to their direction classes, supports'
       * are not: on a long support of many short faces far from the
       * origin they carry epsilon times that distance over the face's
       * length (a review: 16,000 faces of 0.1 at 1e5).
       */
      double rounding = 0;
      /// Its supports' rows in the basis of rigid motions (support_row):
      /// the first n_bilateral of held nodes and rollers, then the
      /// Signorini supports'. Kept only where held_by_signorini.
      std::vector<RigidVector<dim>> rows;
      std::size_t                   n_bilateral = 0;
      /// A basis of its free motions (empty if the supports hold it).
      std::vector<RigidVector<dim>> motions;
      /// A basis of the motions its other supports than the Signorini ones
      /// leave free, where these are more than its free motions: then its
      /// Signorini supports, which only push, hold it in some motion.
      std::vector<RigidVector<dim>> bilateral_motions;
      bool                          held_by_signorini = false;
      /// "block 3 (a node at (1, 0)) and the 2 blocks joined to it".
      std::string who;
    };

    template <int dim>
    double
    dot(const std::array<double, dim> &a, const std::array<double, dim> &b)
    {
      double sum = 0;
      for (unsigned int c = 0; c < dim; ++c)
        sum += a[c] * b[c];
      return sum;
    }

    template <std::size_t n>
    double
    norm(const std::array<double, n> &u)
    {
      double sum = 0;
      for (const double x : u)
        sum += x * x;
      return std::sqrt(sum);
    }

    /// The displacement at @p p of the rigid motion (t, w) of a group
    /// (rigid_displacement), the motion support_row() measures.
    template <int dim>
    std::array<double, dim>
    motion_at(const RigidVector<dim>        &v,
              const std::array<double, dim> &p,
              const Group<dim>              &g)
    {
      return rigid_displacement<dim>(v.data(), p, g.centre, g.size);
    }

    /**
     * The groups of blocks linked by joints that their supports leave free
     * to move, each with those free motions, and those that their
     * Signorini supports hold in some motion (Group::held_by_signorini);
     * for every node its group's index (none for a node of a group that
     * its other supports hold).
     */
    template <int dim>
    std::vector<Group<dim>>
    groups_and_free_motions(const ContactSet<dim>     &contacts,
                            std::vector<unsigned int> &group_of_node)
    {
      const std::size_t n_nodes = contacts.node_position.size();
      if (n_nodes == 0)
        return {};
      const unsigned int n_blocks = n_blocks_of(contacts);
      DisjointSets       groups(n_blocks);
      for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
        if (contacts.constraints[k].kind == ConstraintKind::joint)
          groups.unite(contacts.blocks[k][0], contacts.blocks[k][1]);

      // Each group's centre and size (the largest distance of a node from
      // it), so that rotations and translations are rows of one scale.
      std::vector<Group<dim>> group(n_blocks);
      for (unsigned int b = 0; b < n_blocks; ++b)
        group[groups.find(b)].blocks.push_back(b);
      for (std::size_t a = 0; a < n_nodes; ++a)
        {
          Group<dim> &g = group[groups.find(contacts.node_block[a])];
          if (g.n_nodes++ == 0)
            g.first_node = static_cast<unsigned int>(a);
          for (unsigned int c = 0; c < dim; ++c)
            g.centre[c] += contacts.node_position[a][c];
        }
      for (Group<dim> &g : group)
        for (unsigned int c = 0; c < dim && g.n_nodes > 0; ++c)
          g.centre[c] /= g.n_nodes;
      for (std::size_t a = 0; a < n_nodes; ++a)
        {
          Group<dim> &g        = group[groups.find(contacts.node_block[a])];
          double      distance = 0;
          for (unsigned int c = 0; c < dim; ++c)
            {
              distance +=
                std::pow(contacts.node_position[a][c] - g.centre[c], 2);
              g.farthest =
                std::max(g.farthest, std::abs(contacts.node_position[a][c]));
            }
          g.size = std::max(g.size, std::sqrt(distance));
        }

      const auto add_support = [&](const unsigned int             node,
                                   const std::array<double, dim> &normal) {
        Group<dim> &g = group[groups.find(contacts.node_block[node])];
        const RigidVector<dim> row =
          support_row<dim>(normal,
                           contacts.node_position[node],
                           g.centre,
                           std::max(g.size, 1e-300));
        g.rows.push_back(row);
      };
      for (const HeldNode<dim> &h : contacts.held)
        for (unsigned int c = 0; c < dim; ++c)
          {
            std::array<double, dim> axis{};
            axis[c] = 1;
            add_support(h.node, axis);
          }
      for (const Roller<dim> &r : contacts.rollers)
        add_support(r.node, r.normal);
      for (Group<dim> &g : group)
        g.n_bilateral = g.rows.size();
      for (const UnilateralConstraint<dim> &s : contacts.constraints)
        if (s.kind == ConstraintKind::signorini)
          add_support(s.lower, s.normal);

      std::vector<unsigned int> index_of_root(
        n_blocks, std::numeric_limits<unsigned int>::max());
      std::vector<Group<dim>> with_motions;
      for (Group<dim> &g : group)
        {
          if (g.blocks.empty())
            continue;
          const double faces_along =
            std::max(1.0,
                     dim == 2 ? double(g.rows.size()) :
                                std::sqrt(double(g.rows.size())));
          g.rounding = epsilon *
                       std::max(1.0, g.farthest / std::max(g.size, 1e-300)) *
                       faces_along;
          g.motions = free_basis<dim>(g.rows, g.rounding);
          if (g.rows.size() > g.n_bilateral &&
              g.motions.size() < n_rigid_motions(dim))
            {
              const std::vector<RigidVector<dim>> bilateral(g.rows.begin(),
                                                            g.rows.begin() +
                                                              g.n_bilateral);
              g.bilateral_motions = free_basis<dim>(bilateral, g.rounding);
              g.held_by_signorini =
                g.bilateral_motions.size() > g.motions.size();
            }
          if (!g.held_by_signorini)
            {
              g.rows              = {};
              g.bilateral_motions = {};
            }
          if (g.motions.empty() && !g.held_by_signorini)
            continue;
          const unsigned int first_block = contacts.node_block[g.first_node];
          const std::string  where =
            " (a node at " +
            point_text<dim>(contacts.node_position[g.first_node]) + ")";
          g.who =
            g.blocks.size() == n_blocks ?
              "the whole structure (" + quantity(n_blocks, "block") + ")" :
            g.blocks.size() == 1 ?
              "block " + std::to_string(first_block) + where :
              "block " + std::to_string(first_block) + where + " and the " +
                quantity(g.blocks.size() - 1, "block") + " joined to it";
          index_of_root[groups.find(first_block)] = with_motions.size();
          with_motions.push_back(std::move(g));
        }
      group_of_node.resize(n_nodes);
      for (std::size_t a = 0; a < n_nodes; ++a)
        group_of_node[a] = index_of_root[groups.find(contacts.node_block[a])];
      return with_motions;
    }

    /// What the loads and the gaps do along one motion of a group.
    struct AlongMotion
    {
      double work    = 0; ///< the loads' work W = f . u
      double scale   = 0; ///< sum over the nodes of |f| |u|
      double largest = 0; ///< the largest |u| at a node
      double changed = 0; ///< the largest change of a gap
    };

    /**
     * Lawson & Hanson's non-negative least squares (Solving Least Squares
     * Problems, 1974, ch. 23): mu >= 0 minimising |C mu - t|, for C of a
     * few rows (a group's rigid motions) and a column per Signorini
     * support. At its end the residual r = t - C mu has C^T r <= 0 (to the
     * rounding of C^T t) and r^T C mu = 0. Stops after a bounded number of
     * steps where rounding keeps it from ending (its residual is then
     * what the caller's proof test judges).
     */
    Eigen::VectorXd
    non_negative_least_squares(const Eigen::MatrixXd &C,
                               const Eigen::VectorXd &t)
    {
      const Eigen::Index m  = C.cols();
      Eigen::VectorXd    mu = Eigen::VectorXd::Zero(m);
      std::vector<char>  passive(m, 0);
      const double       zero_gradient =
        1e2 * epsilon * (C.cwiseAbs().transpose() * t.cwiseAbs()).maxCoeff();
      for (Eigen::Index step = 0; step < 4 * C.rows() + 20; ++step)
        {
          // The support whose force would lower the residual most enters.
          const Eigen::VectorXd gradient = C.transpose() * (t - C * mu);
          Eigen::Index          entering = -1;
          double                largest  = zero_gradient;
          for (Eigen::Index j = 0; j < m; ++j)
            if (!passive[j] && gradient[j] > largest)
              largest = gradient[entering = j];
          if (entering < 0)
            break;
          passive[entering] = 1;
          // Least squares on the passive columns; where that makes a force
          // negative, go only as far as the first reaches zero and drop it.
          for (Eigen::Index inner = 0; inner <= m; ++inner)
            {
              std::vector<Eigen::Index> P;
              for (Eigen::Index j = 0; j < m; ++j)
                if (passive[j])
                  P.push_back(j);
              Eigen::MatrixXd CP(C.rows(), P.size());
              for (std::size_t k = 0; k < P.size(); ++k)
                CP.col(k) = C.col(P[k]);
              const Eigen::VectorXd z =
                CP.completeOrthogonalDecomposition().solve(t);
              double       alpha   = 1;
              Eigen::Index blocked = -1;
              for (std::size_t k = 0; k < P.size(); ++k)
                if (z[k] <= 0 && mu[P[k]] / (mu[P[k]] - z[k]) < alpha)
                  {
                    alpha   = mu[P[k]] / (mu[P[k]] - z[k]);
                    blocked = P[k];
                  }
              for (std::size_t k = 0; k < P.size(); ++k)
                mu[P[k]] += alpha * (z[k] - mu[P[k]]);
              if (blocked < 0)
                break;
              mu[blocked] = 0;
              for (const Eigen::Index j : P)
                if (!(mu[j] > 0))
                  {
                    mu[j]      = 0;
                    passive[j] = 0;
                  }
            }
        }
      return mu;
    }

    /**
     * For a group that its Signorini supports hold in some motion
     * (Group::held_by_signorini): a rigid motion that keeps its other
     * supports, closes none of its Signorini supports (to rounding), and
     * along which the loads do work; zero where its supports balance its
     * loads by pushing. Such a motion exists exactly where no forces mu >=
     * 0 of the Signorini supports (and any of the others) balance the
     * group's loads @p loads as a rigid body (Farkas; the forces of the
     * joints within the group cancel): the statics N^T (F + R^T mu) = 0, in
     * the basis N of the motions its other supports leave free (F: the
     * loads, R: the Signorini rows), solved by non-negative least squares.
     * Their residual r, where not zero, gives the motion -N r: R (-N r) >=
     * 0 and F . (-N r) = |r|^2 > 0. That is the loads' direction among the
     * motions that keep the supports which push (mu > 0) and the other
     * supports, and is computed so, from those rows: r itself is the
     * difference of forces far larger than it where the loads nearly
     * balance, and as -N r the motion closed the pushing supports by far
     * more than their rounding (a block on a slope of 1e-3 degrees).
     */
    template <int dim>
    RigidVector<dim>
    escape_motion(const Group<dim> &g, const RigidVector<dim> &loads)
    {
      const Eigen::Index k = g.bilateral_motions.size();
      const Eigen::Index m = g.rows.size() - g.n_bilateral;
      Eigen::MatrixXd    C(k, m);
      Eigen::VectorXd    work(k);
      for (Eigen::Index j = 0; j < k; ++j)
        {
          work[j] = g.bilateral_motions[j].dot(loads);
          for (Eigen::Index s = 0; s < m; ++s)
            C(j, s) = g.bilateral_motions[j].dot(g.rows[g.n_bilateral + s]);
        }
      const Eigen::VectorXd mu = non_negative_least_squares(C, -work);
      // The loads' direction among the motions that keep the other
      // supports and the Signorini ones for which @p keep holds.
      const auto direction = [&](const auto &keep) {
        std::vector<RigidVector<dim>> kept(g.rows.begin(),
                                           g.rows.begin() + g.n_bilateral);
        for (Eigen::Index s = 0; s < m; ++s)
          if (keep(s))
            kept.push_back(g.rows[g.n_bilateral + s]);
        RigidVector<dim> v = RigidVector<dim>::Zero();
        for (const RigidVector<dim> &z : free_basis<dim>(kept, g.rounding))
          v += z.dot(loads) * z;
        return v.norm() > 0 ? RigidVector<dim>(v / v.norm()) : v;
      };
      const RigidVector<dim> pushing =
        direction([&](const Eigen::Index s) { return mu[s] > 0; });
      // Then every support that motion does not open (to 1e-8), not only
      // those that push: the least squares push with as few as balance the
      // loads (a block's base at two nodes), and the loads' rounding turned
      // the motion about the line those leave free, closing the rest of
      // the base by 1e-12 of it (a 3D block on a slope of 1e-3 degrees).
      return direction([&](const Eigen::Index s) {
        return g.rows[g.n_bilateral + s].dot(pushing) <= 1e-8;
      });
    }

    /**
     * The loads on each group as a row over its rigid motions: their work
     * along the motion v is F . v (the sum of f . u over its nodes, by
     * rigid_row() with f for the normal).
     */
    template <int dim>
    std::vector<RigidVector<dim>>
    group_loads(const ContactSet<dim>           &contacts,
                const std::vector<Group<dim>>   &groups,
                const std::vector<unsigned int> &group_of_node,
                const std::vector<double>       &load)
    {
      std::vector<RigidVector<dim>> F(groups.size(), RigidVector<dim>::Zero());
      for (std::size_t a = 0; a < contacts.node_position.size(); ++a)
        if (const unsigned int i = group_of_node[a]; i < groups.size())
          {
            std::array<double, dim> f;
            for (unsigned int c = 0; c < dim; ++c)
              f[c] = load[contacts.node_dofs[a][c]];
            F[i] += support_row<dim>(f,
                                     contacts.node_position[a],
                                     groups[i].centre,
                                     std::max(groups[i].size, 1e-300));
          }
      return F;
    }

    /**
     * For each group, the combination of its free motions along which the
     * loads do the most work: with the loads' work w_j along each motion of
     * its (orthonormal) basis, v = sum_j w_j v_j / |w| (zero if they do no
     * work along any).
     */
    template <int dim>
    std::vector<RigidVector<dim>>
    most_driven_motions(const std::vector<Group<dim>>       &groups,
                        const std::vector<RigidVector<dim>> &loads)
    {
      std::vector<RigidVector<dim>> v(groups.size(), RigidVector<dim>::Zero());
      for (std::size_t i = 0; i < groups.size(); ++i)
        {
          Eigen::VectorXd work(groups[i].motions.size());
          for (std::size_t j = 0; j < groups[i].motions.size(); ++j)
            work[j] = groups[i].motions[j].dot(loads[i]);
          if (work.norm() > 0)
            for (std::size_t j = 0; j < groups[i].motions.size(); ++j)
              v[i] += work[j] / work.norm() * groups[i].motions[j];
        }
      return v;
    }

    /// The figures of AlongMotion for each group's motion @p v; with @p
    /// signorini_may_open, Signorini supports count only where v closes
    /// them.
    template <int dim>
    std::vector<AlongMotion>
    along_motions(const ContactSet<dim>               &contacts,
                  const std::vector<Group<dim>>       &groups,
                  const std::vector<unsigned int>     &group_of_node,
                  const std::vector<double>           &load,
                  const std::vector<RigidVector<dim>> &v,
                  const bool                           signorini_may_open)
    {
      std::vector<AlongMotion> along(groups.size());
      const auto               motion = [&](const unsigned int node) {
        const unsigned int i = group_of_node[node];
        return motion_at<dim>(v[i], contacts.node_position[node], groups[i]);
      };
      for (std::size_t a = 0; a < contacts.node_position.size(); ++a)
        if (const unsigned int i = group_of_node[a]; i < groups.size())
          {
            const auto              u = motion(a);
            std::array<double, dim> f;
            for (unsigned int c = 0; c < dim; ++c)
              {
                f[c] = load[contacts.node_dofs[a][c]];
                along[i].work += f[c] * u[c];
              }
            along[i].scale += norm(f) * norm(u);
            along[i].largest = std::max(along[i].largest, norm(u));
          }

      // The gaps: the supports' (whose rows free_basis() took) and
      // the joints' (whose two nodes coincide only to 'Coincidence
      // tolerance', so that a rotation moves them apart a little).
      const auto change = [&](const unsigned int node, const double amount) {
        if (const unsigned int i = group_of_node[node]; i < groups.size())
          along[i].changed = std::max(along[i].changed, std::abs(amount));
      };
      const auto normal_part = [&](const std::array<double, dim> &normal,
                                   const unsigned int             node) {
        return group_of_node[node] < groups.size() ?
                 dot<dim>(normal, motion(node)) :
                 0.0;
      };
      for (const HeldNode<dim> &h : contacts.held)
        if (group_of_node[h.node] < groups.size())
          change(h.node, norm(motion(h.node)));
      for (const Roller<dim> &r : contacts.rollers)
        change(r.node, normal_part(r.normal, r.node));
      for (const UnilateralConstraint<dim> &s : contacts.constraints)
        if (s.kind == ConstraintKind::joint)
          change(s.lower,
                 normal_part(s.normal, s.upper) -
                   normal_part(s.normal, s.lower));
        else
          {
            const double opening = normal_part(s.normal, s.lower);
            change(s.lower,
                   signorini_may_open ? std::min(opening, 0.0) : opening);
          }
      return along;
    }

    /**
     * The largest |n . t| for which a joint or support does not resist
     * (nor link blocks in) a slide along t: a thousand times the rounding
     * of a unit normal. Larger tilts resist: a block pushed into a slot
     * whose walls taper by theta holds a load along the slot with forces
     * of 1 / theta times it.
     */
    constexpr double parallel = 1e3 * epsilon;

    /**
     * The directions to try slides along: perpendicular to the most
     * frequent joint normals (2D: one per normal; 3D: two in the plane of
     * each normal, and the cross product of each pair).
     */
    template <int dim>
    std::vector<std::array<double, dim>>
    slide_directions(const ContactSet<dim> &contacts)
    {
      DirectionClasses<dim>     classes;
      std::vector<unsigned int> count;
      for (const UnilateralConstraint<dim> &s : contacts.constraints)
        if (s.kind == ConstraintKind::joint)
          {
            const unsigned int k = classes.classify(s.normal).first;
            count.resize(std::max<std::size_t>(count.size(), k + 1));
            ++count[k];
          }
      std::vector<unsigned int> order(count.size());
      std::iota(order.begin(), order.end(), 0u);
      std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) {
        return count[a] > count[b];
      });
      constexpr std::size_t most_frequent = 16;
      order.resize(std::min(order.size(), most_frequent));

      std::vector<std::array<double, dim>> directions;
      const auto add = [&](std::array<double, dim> t) {
        const double length = norm(t);
        if (!(length > 1e-6))
          return;
        for (double &x : t)
          x /= length;
        // The same direction (up to sign) from another pair.
        for (const std::array<double, dim> &s : directions)
          if (std::abs(dot<dim>(s, t)) > 1 - parallel)
            return;
        directions.push_back(t);
      };
      for (const unsigned int k : order)
        {
          const std::array<double, dim> &n = classes.directions[k];
          if constexpr (dim == 2)
            add({{-n[1], n[0]}});
          else
            {
              // Two directions in the plane of n: n x e, e the axis least
              // along n, and n x (n x e).
              std::array<double, dim> e{};
              e[std::abs(n[0]) <= std::abs(n[1]) ?
                  (std::abs(n[0]) <= std::abs(n[2]) ? 0 : 2) :
                  (std::abs(n[1]) <= std::abs(n[2]) ? 1 : 2)] = 1;
              const auto cross = [](const std::array<double, dim> &a,
                                    const std::array<double, dim> &b) {
                return std::array<double, dim>{{a[1] * b[2] - a[2] * b[1],
                                                a[2] * b[0] - a[0] * b[2],
                                                a[0] * b[1] - a[1] * b[0]}};
              };
              const auto t = cross(n, e);
              add(t);
              add(cross(n, t));
              for (const unsigned int l : order)
                if (l > k)
                  add(cross(n, classes.directions[l]));
            }
        }
      return directions;
    }

    /**
     * The proof from the slides: the loads' work W = sum f . t over a set's
     * nodes against sum |f|.
     */
    template <int dim>
    std::string
    loads_driving_a_slide(const ContactSet<dim>              &contacts,
                          const std::vector<FreeSlides<dim>> &slides,
                          const std::vector<double>          &load)
    {
      for (const FreeSlides<dim> &slide : slides)
        {
          std::vector<double>       work(slide.n_sets), scale(slide.n_sets);
          std::vector<unsigned int> n_blocks(slide.n_sets),
            first_node(slide.n_sets);
          std::vector<char> seen(slide.set_of_block.size(), 0);
          for (std::size_t a = 0; a < contacts.node_position.size(); ++a)
            {
              const unsigned int b = contacts.node_block[a];
              const unsigned int i = slide.set_of_block[b];
              if (i == FreeSlides<dim>::none)
                continue;
              if (!seen[b]++ && n_blocks[i]++ == 0)
                first_node[i] = a;
              std::array<double, dim> f;
              for (unsigned int c = 0; c < dim; ++c)
                f[c] = load[contacts.node_dofs[a][c]];
              work[i] += dot<dim>(f, slide.direction);
              scale[i] += norm(f);
            }
          // As for the groups: the work a thousand times the tilts that
          // count as parallel.
          for (unsigned int i = 0; i < slide.n_sets; ++i)
            if (std::abs(work[i]) > 1e3 * parallel * scale[i])
              {
                const unsigned int node = first_node[i];
                // Named the way the loads push.
                std::array<double, dim> t = slide.direction;
                for (double &x : t)
                  x = work[i] < 0 ? -x : x;
                std::ostringstream proof;
                proof.precision(2);
                proof << "the loads do work along a motion that no support "
                         "or joint resists, the translation along "
                      << point_text<dim>(t) << " of block "
                      << contacts.node_block[node] << " (a node at "
                      << point_text<dim>(contacts.node_position[node]) << ")"
                      << (n_blocks[i] > 1 ?
                            " and the " + quantity(n_blocks[i] - 1, "block") +
                              (n_blocks[i] == 2 ? " that slides" :
                                                  " that slide") +
                              " with it along their joints" :
                            std::string(" sliding along its joints"))
                      << ": their work along it is "
                      << std::abs(work[i]) / scale[i]
                      << " of sum |f| |u|, and it changes no gap by more "
                         "than "
                      << parallel
                      << " of the displacement (found from the supports and "
                         "the loads before solving)";
                return proof.str();
              }
        }
      return "";
    }
  } // namespace

  template <int dim>
  unsigned int
  n_blocks_of(const ContactSet<dim> &contacts)
  {
    return contacts.node_block.empty() ?
             0 :
             *std::max_element(contacts.node_block.begin(),
                               contacts.node_block.end()) +
               1;
  }

  template <int dim>
  std::vector<std::string>
  free_rigid_motions(const ContactSet<dim> &contacts, bool &held_by_signorini)
  {
    std::vector<unsigned int> group_of_node(contacts.node_position.size());
    std::vector<std::string>  result;
    held_by_signorini = false;
    for (const Group<dim> &g : groups_and_free_motions(contacts, group_of_node))
      {
        held_by_signorini = held_by_signorini || g.held_by_signorini;
        if (g.motions.empty())
          continue;
        std::vector<std::string> motions;
        for (const RigidVector<dim> &v : g.motions)
          motions.push_back(
            describe_motion<dim>(v, g.centre, std::max(g.size, 1e-300)));
        if (motions.size() == n_rigid_motions(dim))
          result.push_back(g.who + " is held by no support");
        else
          {
            std::string line = g.who + " can move freely by ";
            for (std::size_t i = 0; i < motions.size(); ++i)
              line += (i == 0                  ? "" :
                       i + 1 == motions.size() ? " and " :
                                                 ", ") +
                      motions[i];
            result.push_back(line);
          }
      }
    // A mesh of thousands of loose blocks would print thousands of notes.
    constexpr std::size_t listed = 10;
    if (result.size() > listed)
      {
        const std::size_t more = result.size() - listed;
        result.resize(listed);
        result.push_back("and " + std::to_string(more) +
                         " more groups of blocks that the supports do not "
                         "hold in every rigid motion");
      }
    return result;
  }

  template <int dim>
  std::vector<FreeSlides<dim>>
  free_slides(const ContactSet<dim> &contacts)
  {
    const unsigned int n_blocks = n_blocks_of(contacts);
    if (n_blocks == 0)
      return {};
    std::vector<FreeSlides<dim>> result;
    for (const std::array<double, dim> &t : slide_directions(contacts))
      {
        // Blocks whose joint is not parallel to t slide together; a
        // support not parallel to t holds their set.
        DisjointSets sets(n_blocks);
        for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
          if (contacts.constraints[k].kind == ConstraintKind::joint &&
              std::abs(dot<dim>(contacts.constraints[k].normal, t)) > parallel)
            sets.unite(contacts.blocks[k][0], contacts.blocks[k][1]);
        std::vector<char> held(n_blocks, 0);
        const auto        hold = [&](const unsigned int node) {
          held[sets.find(contacts.node_block[node])] = 1;
        };
        for (const HeldNode<dim> &h : contacts.held)
          hold(h.node);
        for (const Roller<dim> &r : contacts.rollers)
          if (std::abs(dot<dim>(r.normal, t)) > parallel)
            hold(r.node);
        for (const UnilateralConstraint<dim> &s : contacts.constraints)
          if (s.kind == ConstraintKind::signorini &&
              std::abs(dot<dim>(s.normal, t)) > parallel)
            hold(s.lower);

        FreeSlides<dim> slides;
        slides.direction = t;
        slides.set_of_block.assign(n_blocks, FreeSlides<dim>::none);
        std::vector<unsigned int> set_of_root(n_blocks, FreeSlides<dim>::none);
        for (unsigned int b = 0; b < n_blocks; ++b)
          if (const std::size_t root = sets.find(b); !held[root])
            {
              if (set_of_root[root] == FreeSlides<dim>::none)
                set_of_root[root] = slides.n_sets++;
              slides.set_of_block[b] = set_of_root[root];
            }
        if (slides.n_sets > 0)
          result.push_back(std::move(slides));
      }
    return result;
  }

  template <int dim>
  std::string
  loads_driving_a_free_motion(const ContactSet<dim>              &contacts,
                              const std::vector<FreeSlides<dim>> &slides,
                              const std::vector<double>          &load)
  {
    std::vector<unsigned int>     group_of_node;
    const std::vector<Group<dim>> groups =
      groups_and_free_motions(contacts, group_of_node);
    const std::vector<RigidVector<dim>> loads =
      group_loads(contacts, groups, group_of_node, load);

    // A proof only where the motion v is free to a hundred times the
    // rounding of the support rows (Group::rounding: larger for a
    // structure far from the origin), and the loads' work is a thousand
    // times the gap change measured or that rounding, and at least 1e-10:
    // a support tilted by theta against v holds loads whose work along v
    // is up to theta of their size (a block in a V-groove). work / scale
    // is the sine of the slope that a block slides down. Along an escape
    // (escape_motion), only the gaps it closes count, and the loads must
    // push along it, not against.
    const auto proof = [&](const std::vector<RigidVector<dim>> &v,
                           const bool                           escape) {
      const std::vector<AlongMotion> along =
        along_motions(contacts, groups, group_of_node, load, v, escape);
      for (std::size_t i = 0; i < groups.size(); ++i)
        {
          const AlongMotion &a        = along[i];
          const double       rounding = groups[i].rounding;
          const double       tilt     = a.changed / a.largest;
          const double       work     = escape ? a.work : std::abs(a.work);
          if (!(tilt <= 1e2 * rounding) ||
              !(work >
                std::max(1e-10, 1e3 * std::max(tilt, rounding)) * a.scale))
            continue;
          std::ostringstream text;
          text.precision(2);
          text << "the loads do work along a motion that "
               << (escape ? "the supports could resist only by pulling (it "
                            "opens Signorini supports and moves no other "
                            "support or joint), the " :
                            "no support or joint resists, the ")
               << describe_motion<dim>(v[i], groups[i].centre, groups[i].size)
               << " of " << groups[i].who << ": their work along it is "
               << work / a.scale << " of sum |f| |u|, and it "
               << (escape ? "closes" : "changes") << " no gap by more than "
               << tilt
               << " of the largest displacement (found from the supports "
                  "and the loads before solving)";
          return text.str();
        }
      return std::string();
    };
    if (const std::string free =
          proof(most_driven_motions(groups, loads), false);
        !free.empty())
      return free;
    if (const std::string slide = loads_driving_a_slide(contacts, slides, load);
        !slide.empty())
      return slide;
    std::vector<RigidVector<dim>> escapes(groups.size(),
                                          RigidVector<dim>::Zero());
    for (std::size_t i = 0; i < groups.size(); ++i)
      if (groups[i].held_by_signorini)
        escapes[i] = escape_motion(groups[i], loads[i]);
    return proof(escapes, true);
  }

  template std::vector<FreeSlides<2>>
  free_slides(const ContactSet<2> &contacts);
  template std::vector<FreeSlides<3>>
  free_slides(const ContactSet<3> &contacts);
  template std::string
  loads_driving_a_free_motion(const ContactSet<2>              &contacts,
                              const std::vector<FreeSlides<2>> &slides,
                              const std::vector<double>        &load);
  template std::string
  loads_driving_a_free_motion(const ContactSet<3>              &contacts,
                              const std::vector<FreeSlides<3>> &slides,
                              const std::vector<double>        &load);
  template unsigned int
  n_blocks_of(const ContactSet<2> &contacts);
  template unsigned int
  n_blocks_of(const ContactSet<3> &contacts);
  template std::vector<std::string>
  free_rigid_motions(const ContactSet<2> &contacts, bool &held_by_signorini);
  template std::vector<std::string>
  free_rigid_motions(const ContactSet<3> &contacts, bool &held_by_signorini);
} // namespace unilateral::masonry
