#include <tissue_contact/contact/ad_reference.h>

#include <deal.II/differentiation/ad.h>

namespace TissueContact
{
  namespace Contact
  {
    namespace
    {
      /** The AD driver of differentiate() and differentiate_once(). */
      template <Differentiation::AD::NumberTypes code, typename Energy>
      PairDerivatives
      run_ad(const std::vector<double> &coordinates,
             const Energy              &energy,
             const bool                 with_hessian)
      {
        using ADHelper = Differentiation::AD::ScalarFunction<3, code, double>;
        const unsigned int n = coordinates.size();
        ADHelper           ad(n);
        ad.register_independent_variables(coordinates);
        ad.register_dependent_variable(energy(ad.get_sensitive_variables()));
        PairDerivatives result;
        result.energy = ad.compute_value();
        result.gradient.reinit(n);
        ad.compute_gradient(result.gradient);
        if (with_hessian)
          {
            result.hessian.reinit(n, n);
            ad.compute_hessian(result.hessian);
          }
        return result;
      }
    } // namespace


    PairDerivatives
    differentiate(
      const std::vector<double>                                    &coordinates,
      const std::function<ADNumber(const std::vector<ADNumber> &)> &energy)
    {
      return run_ad<Differentiation::AD::NumberTypes::sacado_dfad_dfad>(
        coordinates, energy, true);
    }


    PairDerivatives
    differentiate_once(
      const std::vector<double> &coordinates,
      const std::function<ADNumber1(const std::vector<ADNumber1> &)> &energy)
    {
      return run_ad<Differentiation::AD::NumberTypes::sacado_dfad>(coordinates,
                                                                   energy,
                                                                   false);
    }
  } // namespace Contact
} // namespace TissueContact
