#include <tissue_contact/materials/uncoupled_material.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <string>

namespace TissueContact
{
  namespace Materials
  {
    double
    VolumetricEnergy::U(const double J) const
    {
      // J^2 - 1 - 2 ln J = e^2 + 2 (e - ln(1 + e)) with e = J - 1, without
      // the cancellation of the first form, whose terms are each about 2e:
      // near J = 1 it loses all digits of U below 1e-16 kappa, which at
      // kappa = 5e6 drowned the energy changes of the last Newton steps
      // (doc/theory/08-nodal-pressure.md sec. 8.4)
      const double e = J - 1.;
      double       d; // e - ln(1 + e)
      if (std::abs(e) < 0.1)
        {
          // sum_{k >= 2} (-1)^k e^k / k, to e^21 (relative 1e-21)
          double term = e * e, sum = 0.;
          for (unsigned int k = 2; k <= 21; ++k, term *= -e)
            sum += term / k;
          d = sum;
        }
      else
        d = e - std::log1p(e);
      return 0.25 * kappa * (e * e + 2. * d);
    }


    double
    VolumetricEnergy::dU(const double J) const
    {
      return 0.5 * kappa * (J - 1. / J);
    }


    double
    VolumetricEnergy::ddU(const double J) const
    {
      return 0.5 * kappa * (1. + 1. / (J * J));
    }


    UncoupledMaterial::UncoupledMaterial(const double kappa,
                                         const bool   pointwise_volume)
      : kappa(kappa)
      , pointwise_volume(pointwise_volume)
    {}


    void
    UncoupledMaterial::check_parameters() const
    {
      AssertThrow(std::isfinite(kappa) && kappa > 0.,
                  ExcMessage("material '" + name() +
                             "': the Bulk modulus must be positive (" +
                             std::to_string(kappa) + ")"));
      const auto lame = lame_equivalents();
      check_stable_lame_parameters(name(), lame.first, lame.second);
    }


    double
    UncoupledMaterial::psi(const Invariants &I) const
    {
      const double p = 1. / std::cbrt(I.I3);
      return psi_isochoric(p * I.I1, p * p * I.I2) +
             (pointwise_volume ? VolumetricEnergy{kappa}.U(std::sqrt(I.I3)) :
                                 0.);
    }


    InvariantDerivatives
    UncoupledMaterial::psi_derivatives(const Invariants &I) const
    {
      // (M9)-(M10) of doc/theory/03-materials.md, sec. 3.7
      const double p = 1. / std::cbrt(I.I3), q = p * p, J = std::sqrt(I.I3);
      const double I1_bar = p * I.I1, I2_bar = q * I.I2;
      const IsochoricDerivatives B = psi_isochoric_derivatives(I1_bar, I2_bar);

      // derivatives with respect to I3
      const double           d3_I1_bar  = -I.I1 * p / (3. * I.I3);
      const double           d3_I2_bar  = -2. * I.I2 * q / (3. * I.I3);
      const double           d33_I1_bar = 4. * I.I1 * p / (9. * I.I3 * I.I3);
      const double           d33_I2_bar = 10. * I.I2 * q / (9. * I.I3 * I.I3);
      const double           d3_p       = -p / (3. * I.I3);
      const double           d3_q       = -2. * q / (3. * I.I3);
      const double           d3_J       = 0.5 / J;
      const double           d33_J      = -0.25 / (J * I.I3);
      const VolumetricEnergy volume{pointwise_volume ? kappa : 0.};
      const double           dU        = volume.dU(J);
      const double           ddU       = volume.ddU(J);
      const double           d3_bar[2] = {d3_I1_bar, d3_I2_bar};

      InvariantDerivatives D;
      D.d[0] = p * B.d[0];
      D.d[1] = q * B.d[1];
      D.d[2] = B.d[0] * d3_I1_bar + B.d[1] * d3_I2_bar + dU * d3_J;

      D.dd[0][0] = p * p * B.dd[0][0];
      D.dd[0][1] = D.dd[1][0] = p * q * B.dd[0][1];
      D.dd[1][1]              = q * q * B.dd[1][1];
      D.dd[0][2]              = D.dd[2][0] =
        p * (B.dd[0][0] * d3_I1_bar + B.dd[0][1] * d3_I2_bar) + B.d[0] * d3_p;
      D.dd[1][2] = D.dd[2][1] =
        q * (B.dd[1][0] * d3_I1_bar + B.dd[1][1] * d3_I2_bar) + B.d[1] * d3_q;
      double s = 0.;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          s += B.dd[i][j] * d3_bar[i] * d3_bar[j];
      D.dd[2][2] = s + B.d[0] * d33_I1_bar + B.d[1] * d33_I2_bar +
                   ddU * d3_J * d3_J + dU * d33_J;
      return D;
    }


    UncoupledNeoHookean::UncoupledNeoHookean(const double mu,
                                             const double kappa,
                                             const bool   pointwise_volume)
      : UncoupledMaterial(kappa, pointwise_volume)
      , mu(mu)
    {
      check_parameters();
    }


    double
    UncoupledNeoHookean::psi_isochoric(const double I1_bar, const double) const
    {
      return 0.5 * mu * (I1_bar - 3.);
    }


    IsochoricDerivatives
    UncoupledNeoHookean::psi_isochoric_derivatives(const double,
                                                   const double) const
    {
      IsochoricDerivatives B;
      B.d[0] = 0.5 * mu;
      return B;
    }


    UncoupledMooneyRivlin::UncoupledMooneyRivlin(const double C1,
                                                 const double C2,
                                                 const double kappa,
                                                 const bool   pointwise_volume)
      : UncoupledMaterial(kappa, pointwise_volume)
      , C1(C1)
      , C2(C2)
    {
      check_parameters();
    }


    double
    UncoupledMooneyRivlin::psi_isochoric(const double I1_bar,
                                         const double I2_bar) const
    {
      return C1 * (I1_bar - 3.) + C2 * (I2_bar - 3.);
    }


    IsochoricDerivatives
    UncoupledMooneyRivlin::psi_isochoric_derivatives(const double,
                                                     const double) const
    {
      IsochoricDerivatives B;
      B.d[0] = C1;
      B.d[1] = C2;
      return B;
    }


    UncoupledVeronda::UncoupledVeronda(const double alpha,
                                       const double beta,
                                       const double kappa,
                                       const bool   pointwise_volume)
      : UncoupledMaterial(kappa, pointwise_volume)
      , alpha(alpha)
      , beta(beta)
    {
      AssertThrow(alpha > 0. && beta > 0.,
                  ExcMessage("material 'uncoupled Veronda': alpha and beta "
                             "must be positive (alpha = " +
                             std::to_string(alpha) +
                             ", beta = " + std::to_string(beta) + ")"));
      check_parameters();
    }


    double
    UncoupledVeronda::psi_isochoric(const double I1_bar,
                                    const double I2_bar) const
    {
      return alpha * (std::exp(beta * (I1_bar - 3.)) - 1.) -
             0.5 * alpha * beta * (I2_bar - 3.);
    }


    IsochoricDerivatives
    UncoupledVeronda::psi_isochoric_derivatives(const double I1_bar,
                                                const double) const
    {
      const double         e = std::exp(beta * (I1_bar - 3.));
      IsochoricDerivatives B;
      B.d[0]     = alpha * beta * e;
      B.d[1]     = -0.5 * alpha * beta;
      B.dd[0][0] = alpha * beta * beta * e;
      return B;
    }
  } // namespace Materials
} // namespace TissueContact
