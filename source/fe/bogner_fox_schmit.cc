#include <unilateral/fe/bogner_fox_schmit.h>

#include <deal.II/base/function.h>
#include <deal.II/fe/fe.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace unilateral::fe
{
  namespace
  {
    /**
     * The cubic Hermite basis on [x0, x0 + h] in the variable s = (x - x0)/h,
     * with its first and second x-derivatives. side 0/1 is the end the
     * function belongs to, kind 0 interpolates the value there, kind 1 the
     * derivative (hence the factor h: d/dx = (1/h) d/ds). These are the
     * paper's psi^0_1, psi^0_2, (h/2) psi^1_1, (h/2) psi^1_2 (eq. 20) after
     * the change of variable xi = 2 s - 1.
     */
    struct Hermite1d
    {
      double value[2][2];
      double first[2][2];
      double second[2][2];

      Hermite1d(const double x, const double x0, const double h)
      {
        const double s  = (x - x0) / h;
        const double s2 = s * s, s3 = s2 * s;

        value[0][0]  = 1 - 3 * s2 + 2 * s3;
        first[0][0]  = (-6 * s + 6 * s2) / h;
        second[0][0] = (-6 + 12 * s) / (h * h);

        value[0][1]  = h * (s - 2 * s2 + s3);
        first[0][1]  = 1 - 4 * s + 3 * s2;
        second[0][1] = (-4 + 6 * s) / h;

        value[1][0]  = 3 * s2 - 2 * s3;
        first[1][0]  = (6 * s - 6 * s2) / h;
        second[1][0] = (6 - 12 * s) / (h * h);

        value[1][1]  = h * (-s2 + s3);
        first[1][1]  = -2 * s + 3 * s2;
        second[1][1] = (-2 + 6 * s) / h;
      }
    };

    // Shape function i = 4 v + c is X(side_x, kind_x) * Y(side_y, kind_y).
    struct ShapeIndex
    {
      unsigned int side_x, side_y, kind_x, kind_y;

      explicit ShapeIndex(const unsigned int i)
      {
        const unsigned int v = i / BognerFoxSchmit::dofs_per_vertex;
        const unsigned int c = i % BognerFoxSchmit::dofs_per_vertex;
        side_x               = v % 2;
        side_y               = v / 2;
        kind_x = (c == BognerFoxSchmit::slope_x || c == BognerFoxSchmit::twist);
        kind_y = (c == BognerFoxSchmit::slope_y || c == BognerFoxSchmit::twist);
      }
    };
  } // namespace

  BognerFoxSchmit::BognerFoxSchmit(const dealii::Point<2> &lower_left,
                                   const double            h1,
                                   const double            h2)
    : lower_left(lower_left)
    , h{{h1, h2}}
  {
    if (!(h1 > 0 && h2 > 0))
      throw std::invalid_argument(
        "Bogner-Fox-Schmit rectangle with nonpositive size");
  }

  BognerFoxSchmit
  BognerFoxSchmit::from_vertices(
    const std::array<dealii::Point<2>, 4> &vertices)
  {
    const double h1        = vertices[1][0] - vertices[0][0];
    const double h2        = vertices[2][1] - vertices[0][1];
    const double tolerance = 1e-10 * std::max(std::abs(h1), std::abs(h2));
    const bool   rectangle =
      h1 > 0 && h2 > 0 &&
      std::abs(vertices[1][1] - vertices[0][1]) <= tolerance &&
      std::abs(vertices[2][0] - vertices[0][0]) <= tolerance &&
      std::abs(vertices[3][0] - vertices[1][0]) <= tolerance &&
      std::abs(vertices[3][1] - vertices[2][1]) <= tolerance;
    if (!rectangle)
      {
        std::ostringstream message;
        message << "the Bogner-Fox-Schmit element needs an axis-aligned "
                   "rectangle in deal.II vertex order; got vertices ("
                << vertices[0] << "), (" << vertices[1] << "), (" << vertices[2]
                << "), (" << vertices[3] << ")";
        throw std::invalid_argument(message.str());
      }
    return BognerFoxSchmit(vertices[0], h1, h2);
  }

  dealii::Point<2>
  BognerFoxSchmit::vertex(const unsigned int v) const
  {
    return dealii::Point<2>(lower_left[0] + (v % 2) * h[0],
                            lower_left[1] + (v / 2) * h[1]);
  }

  void
  BognerFoxSchmit::evaluate(
    const dealii::Point<2>                          &p,
    std::array<double, dofs_per_cell>               *values,
    std::array<dealii::Tensor<1, 2>, dofs_per_cell> *gradients,
    std::array<dealii::Tensor<2, 2>, dofs_per_cell> *hessians) const
  {
    const Hermite1d X(p[0], lower_left[0], h[0]);
    const Hermite1d Y(p[1], lower_left[1], h[1]);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      {
        const ShapeIndex s(i);
        const double     x0 = X.value[s.side_x][s.kind_x];
        const double     x1 = X.first[s.side_x][s.kind_x];
        const double     x2 = X.second[s.side_x][s.kind_x];
        const double     y0 = Y.value[s.side_y][s.kind_y];
        const double     y1 = Y.first[s.side_y][s.kind_y];
        const double     y2 = Y.second[s.side_y][s.kind_y];
        if (values != nullptr)
          (*values)[i] = x0 * y0;
        if (gradients != nullptr)
          {
            (*gradients)[i][0] = x1 * y0;
            (*gradients)[i][1] = x0 * y1;
          }
        if (hessians != nullptr)
          {
            (*hessians)[i][0][0] = x2 * y0;
            (*hessians)[i][0][1] = x1 * y1;
            (*hessians)[i][1][0] = x1 * y1;
            (*hessians)[i][1][1] = x0 * y2;
          }
      }
  }

  double
  BognerFoxSchmit::shape_value(const unsigned int      i,
                               const dealii::Point<2> &p) const
  {
    std::array<double, dofs_per_cell> values;
    evaluate(p, &values, nullptr, nullptr);
    return values[i];
  }

  dealii::Tensor<1, 2>
  BognerFoxSchmit::shape_gradient(const unsigned int      i,
                                  const dealii::Point<2> &p) const
  {
    std::array<dealii::Tensor<1, 2>, dofs_per_cell> gradients;
    evaluate(p, nullptr, &gradients, nullptr);
    return gradients[i];
  }

  dealii::Tensor<2, 2>
  BognerFoxSchmit::shape_hessian(const unsigned int      i,
                                 const dealii::Point<2> &p) const
  {
    std::array<dealii::Tensor<2, 2>, dofs_per_cell> hessians;
    evaluate(p, nullptr, nullptr, &hessians);
    return hessians[i];
  }

  double
  BognerFoxSchmit::value(const Coefficients     &coefficients,
                         const dealii::Point<2> &p) const
  {
    std::array<double, dofs_per_cell> values;
    evaluate(p, &values, nullptr, nullptr);
    double result = 0;
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      result += coefficients[i] * values[i];
    return result;
  }

  dealii::Tensor<1, 2>
  BognerFoxSchmit::gradient(const Coefficients     &coefficients,
                            const dealii::Point<2> &p) const
  {
    std::array<dealii::Tensor<1, 2>, dofs_per_cell> gradients;
    evaluate(p, nullptr, &gradients, nullptr);
    dealii::Tensor<1, 2> result;
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      result += coefficients[i] * gradients[i];
    return result;
  }

  dealii::Tensor<2, 2>
  BognerFoxSchmit::hessian(const Coefficients     &coefficients,
                           const dealii::Point<2> &p) const
  {
    std::array<dealii::Tensor<2, 2>, dofs_per_cell> hessians;
    evaluate(p, nullptr, nullptr, &hessians);
    dealii::Tensor<2, 2> result;
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      result += coefficients[i] * hessians[i];
    return result;
  }

  BognerFoxSchmit::Coefficients
  BognerFoxSchmit::interpolate(const dealii::Function<2, double> &f) const
  {
    Coefficients coefficients;
    for (unsigned int v = 0; v < 4; ++v)
      {
        const dealii::Point<2>     p             = vertex(v);
        const dealii::Tensor<1, 2> gradient      = f.gradient(p);
        coefficients[local_index(v, deflection)] = f.value(p);
        coefficients[local_index(v, slope_x)]    = gradient[0];
        coefficients[local_index(v, slope_y)]    = gradient[1];
        coefficients[local_index(v, twist)]      = f.hessian(p)[0][1];
      }
    return coefficients;
  }

  std::vector<unsigned int>
  bfs_local_indices(const dealii::FiniteElement<2, 2> &fe)
  {
    // FE_Q(1)^4: each base element's DOFs are its vertex DOFs, in vertex
    // order, so the index within the base element is the vertex.
    const bool right_element =
      fe.n_components() == BognerFoxSchmit::dofs_per_vertex &&
      fe.n_dofs_per_cell() == BognerFoxSchmit::dofs_per_cell &&
      fe.n_dofs_per_vertex() == BognerFoxSchmit::dofs_per_vertex &&
      fe.n_base_elements() == 1 && fe.base_element(0).n_dofs_per_cell() == 4 &&
      fe.base_element(0).n_dofs_per_vertex() == 1 &&
      fe.base_element(0).degree == 1;
    if (!right_element)
      throw std::invalid_argument(
        "the Bogner-Fox-Schmit DOF map needs FESystem<2>(FE_Q<2>(1), 4), got " +
        fe.get_name());
    std::vector<unsigned int> indices(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto [component, vertex] = fe.system_to_component_index(i);
        indices[i] = BognerFoxSchmit::local_index(vertex, component);
      }
    return indices;
  }
} // namespace unilateral::fe
