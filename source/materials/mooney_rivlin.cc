#include <tissue_contact/materials/mooney_rivlin.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace TissueContact
{
  namespace Materials
  {
    MooneyRivlin::MooneyRivlin(const double C1, const double C2, const double a)
      : C1(C1)
      , C2(C2)
      , a(a)
    {
      const auto lame = lame_equivalents();
      check_stable_lame_parameters(name(), lame.first, lame.second);
      AssertThrow(C1 + 2. * C2 + a > 0.,
                  ExcMessage("material 'Mooney-Rivlin': C1 + 2 C2 + a must be "
                             "positive so that the energy grows without bound "
                             "as the volume goes to zero"));
    }


    double
    MooneyRivlin::psi(const Invariants &I) const
    {
      return C1 * (I.I1 - 3.) + C2 * (I.I2 - 3.) + a * (I.I3 - 1.) -
             (C1 + 2. * C2 + a) * std::log(I.I3);
    }


    InvariantDerivatives
    MooneyRivlin::psi_derivatives(const Invariants &I) const
    {
      const double         k = C1 + 2. * C2 + a;
      InvariantDerivatives D;
      D.d[0]     = C1;
      D.d[1]     = C2;
      D.d[2]     = a - k / I.I3;
      D.dd[2][2] = k / (I.I3 * I.I3);
      return D;
    }
  } // namespace Materials
} // namespace TissueContact
