#include <unilateral/lcp/tearing.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace unilateral::lcp
{
  Index
  Tearing::n_subdomains() const
  {
    Index n = 0;
    for (const Group &group : groups)
      n += group.n_subdomains;
    return n;
  }

  std::string
  Tearing::describe(const Index subdomain) const
  {
    return describe_subdomain ? describe_subdomain(subdomain) :
                                "subdomain " + std::to_string(subdomain);
  }

  void
  check_tearing(const Tearing &tearing, const Problem &problem)
  {
    const auto fail = [](const std::string &what) {
      throw std::logic_error("inconsistent tearing: " + what);
    };
    Index next_dof = 0;
    for (const Tearing::Group &group : tearing.groups)
      {
        if (group.shape >= tearing.shapes.size())
          fail("a group names shape " + std::to_string(group.shape));
        if (group.first_dof != next_dof)
          fail("the groups do not cover the DOFs in order");
        next_dof +=
          group.n_subdomains *
          static_cast<Index>(tearing.shapes[group.shape].stiffness.rows());
      }
    if (next_dof != tearing.n_dofs())
      fail("the groups cover " + std::to_string(next_dof) + " of " +
           std::to_string(tearing.n_dofs()) + " DOFs");
    for (const Tearing::Shape &shape : tearing.shapes)
      {
        if (shape.stiffness.rows() != shape.stiffness.cols() ||
            shape.rigid_motions.rows() != shape.stiffness.rows())
          fail("a shape's K and R do not match");
        const double size = shape.stiffness.cwiseAbs().maxCoeff() *
                            shape.rigid_motions.cwiseAbs().maxCoeff();
        if ((shape.stiffness * shape.rigid_motions).cwiseAbs().maxCoeff() >
            1e-8 * size)
          fail("K R != 0: the rigid motions are not in the null space");
      }
    if (tearing.B.cols() != tearing.n_dofs() ||
        tearing.c.size() != tearing.B.rows() ||
        tearing.n_inequalities > tearing.B.rows())
      fail("B and c do not match the DOFs");
    if (tearing.inequality_unknown.size() !=
        static_cast<std::size_t>(tearing.n_inequalities))
      fail("not every inequality names its unknown");
    for (const Index i : tearing.inequality_unknown)
      if (!std::binary_search(problem.constrained.begin(),
                              problem.constrained.end(),
                              i))
        fail("an inequality names an unconstrained unknown");
    if (tearing.to_problem.rows() != problem.size() ||
        tearing.to_problem.cols() != tearing.n_dofs())
      fail("the map to the problem's unknowns has the wrong shape");
  }
} // namespace unilateral::lcp
