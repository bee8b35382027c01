#pragma once

// Small helpers shared by the TissueContact test programs (deal.II style:
// every test writes to deallog, which initlog() sends to the file "output"
// that numdiff compares against <name>.output).

#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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

  /** A random rotation (Rodrigues' formula) about a random axis. */
  Tensor<2, 3>
  random_rotation()
  {
    Tensor<1, 3> axis;
    for (unsigned d = 0; d < 3; ++d)
      axis[d] = random_value(-1., 1.);
    axis /= axis.norm();
    const double angle = random_value(0., 2. * M_PI);
    Tensor<2, 3> W;
    W[0][1] = -axis[2];
    W[0][2] = axis[1];
    W[1][0] = axis[2];
    W[1][2] = -axis[0];
    W[2][0] = -axis[1];
    W[2][1] = axis[0];
    return unit_symmetric_tensor<3>() + std::sin(angle) * W +
           (1. - std::cos(angle)) * W * W;
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
   * prints "< 10^k" with the smallest k >= @p smallest_exponent such that
   * the bound holds. The exponent is an integer of its own (numdiff splits
   * at '^'), so the comparison with the expected log fails as soon as the
   * error grows by a power of ten: a bound written as "1e-12" would pass
   * numdiff's absolute tolerance of 1e-6 at any error below 1e-6. */
  inline std::string
  error_bound(const double e, const int smallest_exponent = -12)
  {
    for (int k = smallest_exponent; k <= 0; ++k)
      if (e < std::pow(10., k))
        return "< 10^" + std::to_string(k);
    return "= " + std::to_string(e) + " (large)";
  }

  /** @p x as "m.m 10^e" with @p digits decimals of the mantissa: small
   * numbers (residual histories) keep their magnitude in the comparison,
   * which numdiff's absolute tolerance of 1e-6 would otherwise hide. */
  inline std::string
  scientific(const double x, const unsigned int digits = 1)
  {
    if (x == 0.)
      return "0";
    if (!std::isfinite(x))
      return std::isnan(x) ? "nan" : "inf";
    int    e = static_cast<int>(std::floor(std::log10(std::abs(x))));
    double m = x / std::pow(10., e);
    // rounding the mantissa may carry it to 10
    std::ostringstream probe;
    probe << std::fixed << std::setprecision(digits) << m;
    if (std::abs(std::stod(probe.str())) >= 10.)
      {
        ++e;
        m /= 10.;
      }
    std::ostringstream out;
    out << std::fixed << std::setprecision(digits) << m << " 10^" << e;
    return out.str();
  }

  /**
   * Finite-difference checks of an assembler at the displacement @p u and
   * load factor @p lambda (central differences of step @p h): the relative
   * l2 error of the residual @p R against the gradient of
   * assembler.energy(), of the tangent @p K against the derivative of
   * assembler.assemble()'s residual (column by column, entries outside
   * @p K's pattern counted as 0), and max |K - K^T| / max |K|. The
   * assembler needs energy(u, lambda) and assemble(u, lambda, R, K*).
   */
  struct FiniteDifferenceErrors
  {
    double residual = 0., tangent = 0., asymmetry = 0.;
  };

  template <typename Assembler, typename Vector, typename Matrix>
  FiniteDifferenceErrors
  finite_difference_errors(const Assembler &assembler,
                           const Vector    &u,
                           const double     lambda,
                           const Vector    &R,
                           const Matrix    &K,
                           const double     h = 1e-6)
  {
    FiniteDifferenceErrors e;
    const auto             n = u.size();
    Vector                 up(u), um(u), Rp(n), Rm(n), diff(R);
    for (std::size_t i = 0; i < n; ++i)
      {
        up[i] += h;
        um[i] -= h;
        diff[i] -=
          (assembler.energy(up, lambda) - assembler.energy(um, lambda)) /
          (2 * h);
        up[i] = um[i] = u[i];
      }
    e.residual = diff.l2_norm() / R.l2_norm();

    const auto &pattern = K.get_sparsity_pattern();
    double      err2 = 0., norm2 = 0.;
    for (std::size_t j = 0; j < n; ++j)
      {
        up[j] += h;
        um[j] -= h;
        assembler.assemble(up, lambda, Rp, nullptr);
        assembler.assemble(um, lambda, Rm, nullptr);
        up[j] = um[j] = u[j];
        for (std::size_t i = 0; i < n; ++i)
          {
            const double fd = (Rp[i] - Rm[i]) / (2 * h);
            const double k  = pattern.exists(i, j) ? K(i, j) : 0.;
            err2 += (k - fd) * (k - fd);
            norm2 += k * k;
          }
      }
    e.tangent = std::sqrt(err2 / norm2);

    double asym = 0.;
    for (std::size_t i = 0; i < n; ++i)
      for (auto entry = K.begin(i); entry != K.end(i); ++entry)
        asym = std::max(asym, std::abs(entry->value() - K(entry->column(), i)));
    e.asymmetry = asym / K.linfty_norm();
    return e;
  }

#ifdef SOURCE_DIR
  /** The text of the project's prm/<name> for a test run in the build
   * tree: its meshes read from the source tree, every @p replacements
   * (from, to) applied to each occurrence of from (which must occur), and
   * the output quiet: no VTU, no timing, files in the current folder. */
  inline std::string
  project_prm(
    const std::string                                      &name,
    const std::vector<std::pair<std::string, std::string>> &replacements = {})
  {
    const std::string root = std::string(SOURCE_DIR) + "/../../";
    std::ifstream     in(root + "prm/" + name);
    if (!in)
      throw std::runtime_error("cannot read prm/" + name);
    std::ostringstream text;
    text << in.rdbuf();
    std::string s           = text.str();
    const auto  replace_all = [&](const std::string &from,
                                 const std::string &to) {
      std::size_t pos = s.find(from);
      if (pos == std::string::npos)
        throw std::runtime_error("prm/" + name + " has no '" + from + "'");
      for (; pos != std::string::npos; pos = s.find(from, pos + to.size()))
        s.replace(pos, from.size(), to);
    };
    for (const auto &r : replacements)
      replace_all(r.first, r.second);
    replace_all("../meshes/", root + "meshes/");
    return s + "\nsubsection Output\n  set Write VTU = false\n"
               "  set Print timing = false\n  set Directory = .\nend\n";
  }
#endif
} // namespace TissueContactTests
