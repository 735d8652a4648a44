#include <unilateral/base/text.h>
#include <unilateral/scenes/masonry/free_motions.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    constexpr unsigned int
    n_rigid_motions(const int dim)
    {
      return dim == 2 ? 3 : 6;
    }

    template <int dim>
    using RigidMatrix =
      Eigen::Matrix<double, n_rigid_motions(dim), n_rigid_motions(dim)>;
    template <int dim>
    using RigidVector = Eigen::Matrix<double, n_rigid_motions(dim), 1>;

    /// Groups of blocks linked by joints (union-find on the joints' blocks).
    class BlockGroups
    {
    public:
      explicit BlockGroups(const unsigned int n_blocks)
        : parent(n_blocks)
      {
        std::iota(parent.begin(), parent.end(), 0u);
      }

      unsigned int
      root(unsigned int b)
      {
        while (parent[b] != b)
          b = parent[b] = parent[parent[b]];
        return b;
      }

      void
      join(const unsigned int a, const unsigned int b)
      {
        parent[root(a)] = root(b);
      }

    private:
      std::vector<unsigned int> parent;
    };

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

    /// The row of a support acting along @p normal at @p p: n . u for the
    /// rigid motion (t, w): n . t + w . ((p - centre) x n) / size.
    template <int dim>
    RigidVector<dim>
    support_row(const std::array<double, dim> &normal,
                const std::array<double, dim> &p,
                const std::array<double, dim> &centre,
                const double                   size)
    {
      RigidVector<dim>        row;
      std::array<double, dim> d{};
      for (unsigned int c = 0; c < dim; ++c)
        {
          row[c] = normal[c];
          d[c]   = (p[c] - centre[c]) / size;
        }
      if constexpr (dim == 2)
        row[2] = d[0] * normal[1] - d[1] * normal[0];
      else
        {
          row[3] = d[1] * normal[2] - d[2] * normal[1];
          row[4] = d[2] * normal[0] - d[0] * normal[2];
          row[5] = d[0] * normal[1] - d[1] * normal[0];
        }
      return row;
    }

    /**
     * A basis of the null space of @p gram (eigenvalues below 1e-10 of the
     * largest), translations first: the eigenvectors of a null space of
     * more than one dimension mix translations and rotations at random, so
     * the pure translations in it are found first (where the rotation
     * parts vanish) and the rest is made orthogonal to them.
     */
    template <int dim>
    std::vector<RigidVector<dim>>
    free_basis(const RigidMatrix<dim> &gram)
    {
      constexpr int n_rotations = n_rigid_motions(dim) - dim;
      const Eigen::SelfAdjointEigenSolver<RigidMatrix<dim>> eigen(gram);
      const double     largest = eigen.eigenvalues().maxCoeff();
      std::vector<int> null;
      for (int i = 0; i < int(n_rigid_motions(dim)); ++i)
        if (!(eigen.eigenvalues()[i] > 1e-10 * largest))
          null.push_back(i);
      if (null.empty())
        return {};
      Eigen::MatrixXd N(n_rigid_motions(dim), null.size());
      for (std::size_t j = 0; j < null.size(); ++j)
        N.col(j) = eigen.eigenvectors().col(null[j]);
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
      RigidMatrix<dim>          gram       = RigidMatrix<dim>::Zero();
    };
  } // namespace

  template <int dim>
  std::vector<std::string>
  free_rigid_motions(const ContactSet<dim> &contacts)
  {
    const std::size_t n_nodes = contacts.node_position.size();
    if (n_nodes == 0)
      return {};
    const unsigned int n_blocks = *std::max_element(contacts.node_block.begin(),
                                                    contacts.node_block.end()) +
                                  1;
    BlockGroups groups(n_blocks);
    for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
      if (contacts.constraints[k].kind == ConstraintKind::joint)
        groups.join(contacts.blocks[k][0], contacts.blocks[k][1]);

    // Each group's centre and size (the largest distance of a node from
    // it), so that rotations and translations are rows of one scale.
    std::vector<Group<dim>> group(n_blocks);
    for (unsigned int b = 0; b < n_blocks; ++b)
      group[groups.root(b)].blocks.push_back(b);
    for (std::size_t a = 0; a < n_nodes; ++a)
      {
        Group<dim> &g = group[groups.root(contacts.node_block[a])];
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
        Group<dim> &g        = group[groups.root(contacts.node_block[a])];
        double      distance = 0;
        for (unsigned int c = 0; c < dim; ++c)
          distance += std::pow(contacts.node_position[a][c] - g.centre[c], 2);
        g.size = std::max(g.size, std::sqrt(distance));
      }

    const auto add_support = [&](const unsigned int             node,
                                 const std::array<double, dim> &normal) {
      Group<dim>            &g = group[groups.root(contacts.node_block[node])];
      const RigidVector<dim> row =
        support_row<dim>(normal,
                         contacts.node_position[node],
                         g.centre,
                         std::max(g.size, 1e-300));
      g.gram += row * row.transpose();
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
    for (const UnilateralConstraint<dim> &s : contacts.constraints)
      if (s.kind == ConstraintKind::signorini)
        add_support(s.lower, s.normal);

    std::vector<std::string> result;
    for (const Group<dim> &g : group)
      {
        if (g.blocks.empty())
          continue;
        std::vector<std::string> motions;
        for (const RigidVector<dim> &v : free_basis<dim>(g.gram))
          motions.push_back(
            describe_motion<dim>(v, g.centre, std::max(g.size, 1e-300)));
        if (motions.empty())
          continue;
        const unsigned int first_block = contacts.node_block[g.first_node];
        const std::string  where =
          " (a node at " +
          point_text<dim>(contacts.node_position[g.first_node]) + ")";
        const std::string who =
          g.blocks.size() == n_blocks ?
            "the whole structure (" + quantity(n_blocks, "block") + ")" :
          g.blocks.size() == 1 ?
            "block " + std::to_string(first_block) + where :
            "block " + std::to_string(first_block) + where + " and the " +
              quantity(g.blocks.size() - 1, "block") + " joined to it";
        if (motions.size() == n_rigid_motions(dim))
          result.push_back(who + " is held by no support");
        else
          {
            std::string line = who + " can move freely by ";
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

  template std::vector<std::string>
  free_rigid_motions(const ContactSet<2> &contacts);
  template std::vector<std::string>
  free_rigid_motions(const ContactSet<3> &contacts);
} // namespace unilateral::masonry
