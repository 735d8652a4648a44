#pragma once

// Small helpers for the unit tests (deal.II's tests.h is not installed).
// Tests print verdicts ("...: yes"), never bare tiny numbers: numdiff's
// tolerances would hide a wrong digit, a wrong "yes" it cannot.

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace test_tools
{
  /// Print "<what>: yes|no" and return the condition.
  inline bool
  verdict(const std::string &what, const bool condition)
  {
    std::cout << what << ": " << (condition ? "yes" : "no") << std::endl;
    return condition;
  }

  /// A deterministic sequence in [-1, 1] for test data (no <random>: its
  /// distributions are not portable across standard libraries).
  class Sequence
  {
  public:
    explicit Sequence(const unsigned int seed = 1)
      : state(seed)
    {}

    double
    next()
    {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return static_cast<double>(state >> 11) * 0x1.0p-53 * 2 - 1;
    }

  private:
    unsigned long long state;
  };

  /**
   * p(x, y) = sum_{i,j} a[i][j] x^i y^j with exact value, gradient and
   * Hessian, for any degrees (a[i] may have any length).
   */
  class Polynomial : public dealii::Function<2>
  {
  public:
    explicit Polynomial(std::vector<std::vector<double>> coefficients)
      : a(std::move(coefficients))
    {}

    /// x^i y^j.
    static Polynomial
    monomial(const unsigned int i, const unsigned int j)
    {
      std::vector<std::vector<double>> a(i + 1, std::vector<double>(j + 1, 0));
      a[i][j] = 1;
      return Polynomial(a);
    }

    /// A bicubic with coefficients from @p sequence.
    static Polynomial
    bicubic(Sequence &sequence)
    {
      std::vector<std::vector<double>> a(4, std::vector<double>(4));
      for (auto &row : a)
        for (double &c : row)
          c = sequence.next();
      return Polynomial(a);
    }

    /// d^(dx+dy) p / dx^dx dy^dy at p.
    double
    derivative(const dealii::Point<2> &p,
               const unsigned int      dx,
               const unsigned int      dy) const
    {
      double result = 0;
      for (unsigned int i = 0; i < a.size(); ++i)
        for (unsigned int j = 0; j < a[i].size(); ++j)
          if (i >= dx && j >= dy && a[i][j] != 0)
            result += a[i][j] * falling(i, dx) * falling(j, dy) *
                      std::pow(p[0], i - dx) * std::pow(p[1], j - dy);
      return result;
    }

    double
    value(const dealii::Point<2> &p, const unsigned int = 0) const override
    {
      return derivative(p, 0, 0);
    }

    dealii::Tensor<1, 2>
    gradient(const dealii::Point<2> &p, const unsigned int = 0) const override
    {
      dealii::Tensor<1, 2> g;
      g[0] = derivative(p, 1, 0);
      g[1] = derivative(p, 0, 1);
      return g;
    }

    dealii::SymmetricTensor<2, 2>
    hessian(const dealii::Point<2> &p, const unsigned int = 0) const override
    {
      dealii::SymmetricTensor<2, 2> h;
      h[0][0] = derivative(p, 2, 0);
      h[0][1] = derivative(p, 1, 1);
      h[1][1] = derivative(p, 0, 2);
      return h;
    }

    dealii::Tensor<2, 2>
    full_hessian(const dealii::Point<2> &p) const
    {
      return dealii::Tensor<2, 2>(hessian(p));
    }

    /// Scale all coefficients.
    Polynomial
    scaled(const double factor) const
    {
      auto b = a;
      for (auto &row : b)
        for (double &c : row)
          c *= factor;
      return Polynomial(b);
    }

  private:
    static double
    falling(const unsigned int n, const unsigned int k)
    {
      double result = 1;
      for (unsigned int m = 0; m < k; ++m)
        result *= n - m;
      return result;
    }

    std::vector<std::vector<double>> a;
  };
} // namespace test_tools
