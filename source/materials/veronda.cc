#include <tissue_contact/materials/veronda.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace TissueContact
{
  namespace Materials
  {
    Veronda::Veronda(const double alpha, const double beta, const double a)
      : alpha(alpha)
      , beta(beta)
      , a(a)
    {
      AssertThrow(alpha > 0. && beta > 0.,
                  ExcMessage("material 'Veronda': alpha and beta must be "
                             "positive (alpha = " +
                             std::to_string(alpha) +
                             ", beta = " + std::to_string(beta) + ")"));
      AssertThrow(a > 0.,
                  ExcMessage("material 'Veronda': the compressibility a must "
                             "be positive (a = " +
                             std::to_string(a) + ")"));
      const auto lame = lame_equivalents();
      check_stable_lame_parameters(name(), lame.first, lame.second);
    }


    double
    Veronda::psi(const Invariants &I) const
    {
      return alpha * (std::exp(beta * (I.I1 - 3.)) - 1.) -
             0.5 * alpha * beta * (I.I2 - 3.) + a * (I.I3 - 1.) -
             a * std::log(I.I3);
    }


    InvariantDerivatives
    Veronda::psi_derivatives(const Invariants &I) const
    {
      const double         e = std::exp(beta * (I.I1 - 3.));
      InvariantDerivatives D;
      D.d[0]     = alpha * beta * e;
      D.d[1]     = -0.5 * alpha * beta;
      D.d[2]     = a - a / I.I3;
      D.dd[0][0] = alpha * beta * beta * e;
      D.dd[2][2] = a / (I.I3 * I.I3);
      return D;
    }
  } // namespace Materials
} // namespace TissueContact
