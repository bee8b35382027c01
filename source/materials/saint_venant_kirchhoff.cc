#include <tissue_contact/materials/saint_venant_kirchhoff.h>

namespace TissueContact
{
  namespace Materials
  {
    SaintVenantKirchhoff::SaintVenantKirchhoff(const double mu,
                                               const double lambda)
      : mu(mu)
      , lambda(lambda)
    {
      check_stable_lame_parameters(name(), mu, lambda);
    }


    double
    SaintVenantKirchhoff::psi(const Invariants &I) const
    {
      const double t = I.I1 - 3.;
      return 0.125 * lambda * t * t +
             0.25 * mu * (I.I1 * I.I1 - 2. * I.I2 - 2. * I.I1 + 3.);
    }


    InvariantDerivatives
    SaintVenantKirchhoff::psi_derivatives(const Invariants &I) const
    {
      InvariantDerivatives D;
      D.d[0]     = 0.25 * lambda * (I.I1 - 3.) + 0.5 * mu * (I.I1 - 1.);
      D.d[1]     = -0.5 * mu;
      D.dd[0][0] = 0.25 * lambda + 0.5 * mu;
      return D;
    }
  } // namespace Materials
} // namespace TissueContact
