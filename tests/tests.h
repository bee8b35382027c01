#pragma once

// Small helpers shared by the TissueContact test programs (deal.II style:
// every test writes to deallog, which initlog() sends to the file "output"
// that numdiff compares against <name>.output).

#include <cmath>
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <fstream>
#include <iomanip>
#include <random>

namespace TissueContactTests
{
  using namespace dealii;

  inline std::ofstream &
  log_file()
  {
    static std::ofstream file("output");
    return file;
  }

  /** Send deallog to "output" with a fixed precision and no timestamps. */
  inline void
  initlog(const unsigned int precision = 6)
  {
    deallog.attach(log_file(), /*print_job_id=*/false);
    deallog.depth_console(0);
    deallog << std::setprecision(precision);
    log_file() << std::setprecision(precision);
  }

  /** A reproducible random number generator for all tests. */
  inline std::mt19937 &
  rng()
  {
    static std::mt19937 generator(20261122);
    return generator;
  }

  inline double
  random_value(const double a, const double b)
  {
    return std::uniform_real_distribution<double>(a, b)(rng());
  }

  /** A random deformation gradient near the identity with det F > 0:
   * F = I + amplitude * (random matrix), redrawn until det F > 0.2. */
  inline Tensor<2, 3>
  random_deformation_gradient(const double amplitude)
  {
    while (true)
      {
        Tensor<2, 3> F;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            F[i][j] = (i == j ? 1. : 0.) + amplitude * random_value(-1., 1.);
        if (determinant(F) > 0.2)
          return F;
      }
  }

  /** Relative error |a-b|/max(|b|, floor), the measure printed by tests. */
  inline double
  relative_error(const double a_minus_b_norm,
                 const double b_norm,
                 const double floor = 1e-12)
  {
    return a_minus_b_norm / std::max(b_norm, floor);
  }

  /** Round a small error to a power of ten for a machine-independent log:
   * prints "< 1e-k" with the smallest k such that the bound holds, capped. */
  inline std::string
  error_bound(const double e, const int smallest_exponent = -12)
  {
    for (int k = smallest_exponent; k <= 0; ++k)
      if (e < std::pow(10., k))
        return "< 1e" + std::to_string(k);
    return "= " + std::to_string(e) + " (large)";
  }
} // namespace TissueContactTests
