#include <tissue_contact/materials/neo_hookean.h>

#include <cmath>

namespace TissueContact
{
  namespace Materials
  {
    NeoHookean::NeoHookean(const double mu, const double lambda)
      : mu(mu)
      , lambda(lambda)
    {
      check_stable_lame_parameters(name(), mu, lambda);
    }


    // Psi = mu/2 (I1 - 3) - mu/2 ln I3 + lambda/8 (ln I3)^2
    double
    NeoHookean::psi(const Invariants &I) const
    {
      const double ln_I3 = std::log(I.I3);
      return 0.5 * mu * (I.I1 - 3.) - 0.5 * mu * ln_I3 +
             0.125 * lambda * ln_I3 * ln_I3;
    }


    InvariantDerivatives
    NeoHookean::psi_derivatives(const Invariants &I) const
    {
      const double         ln_I3 = std::log(I.I3);
      InvariantDerivatives D;
      D.d[0]     = 0.5 * mu;
      D.d[2]     = (-0.5 * mu + 0.25 * lambda * ln_I3) / I.I3;
      D.dd[2][2] = (0.5 * mu + 0.25 * lambda * (1. - ln_I3)) / (I.I3 * I.I3);
      return D;
    }
  } // namespace Materials
} // namespace TissueContact
