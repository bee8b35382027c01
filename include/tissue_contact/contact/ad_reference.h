#pragma once

#include <deal.II/base/point.h>
#include <deal.II/differentiation/ad/ad_number_traits.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    using namespace dealii;

    /**
     * Value, gradient and Hessian of a contact energy with respect to the
     * coordinates of its points (x y z each), by automatic differentiation:
     * the reference the hand-derived kernels are tested against, and the
     * kernel of the rigid obstacles.
     */
    struct PairDerivatives
    {
      double             energy = 0.;
      Vector<double>     gradient;
      FullMatrix<double> hessian;
    };

    /** The number type of the reference derivatives: Sacado forward mode
     * over forward mode, exact first and second derivatives. */
    using ADNumber = Differentiation::AD::NumberTraits<
      double,
      Differentiation::AD::NumberTypes::sacado_dfad_dfad>::ad_type;

    /** First-order AD number: gradients only (the residual). */
    using ADNumber1 = Differentiation::AD::NumberTraits<
      double,
      Differentiation::AD::NumberTypes::sacado_dfad>::ad_type;

    /** Value, gradient and Hessian of @p energy at @p coordinates
     * (deal.II's Differentiation::AD::ScalarFunction). */
    PairDerivatives
    differentiate(
      const std::vector<double>                                    &coordinates,
      const std::function<ADNumber(const std::vector<ADNumber> &)> &energy);

    /** Value and gradient only (hessian left empty), by first-order AD:
     * about n times cheaper than differentiate() for n coordinates. */
    PairDerivatives
    differentiate_once(
      const std::vector<double> &coordinates,
      const std::function<ADNumber1(const std::vector<ADNumber1> &)> &energy);

    namespace internal
    {
      template <std::size_t... N>
      constexpr std::array<std::size_t, sizeof...(N)>
      offsets()
      {
        std::array<std::size_t, sizeof...(N)> o{};
        const std::size_t                     sizes[] = {N...};
        std::size_t                           sum     = 0;
        for (std::size_t i = 0; i < sizeof...(N); ++i)
          {
            o[i] = sum;
            sum += 3 * sizes[i];
          }
        return o;
      }

      template <typename Number, std::size_t N>
      std::array<Point<3, Number>, N>
      points_from(const std::vector<Number> &x, const std::size_t offset)
      {
        std::array<Point<3, Number>, N> p;
        for (std::size_t v = 0; v < N; ++v)
          for (unsigned int d = 0; d < 3; ++d)
            p[v][d] = x[offset + 3 * v + d];
        return p;
      }

      template <typename Number,
                std::size_t... N,
                typename Energy,
                std::size_t... I>
      Number
      call_with_points(const Energy              &energy,
                       const std::vector<Number> &x,
                       std::index_sequence<I...>)
      {
        constexpr auto o = offsets<N...>();
        return energy(points_from<Number, N>(x, o[I])...);
      }
    } // namespace internal

    /**
     * Value, gradient and (if @p with_hessian) Hessian of
     * @p energy(groups...) with respect to the coordinates of every point of
     * every group, in order: e.g. the 21 coordinates of a (tetrahedron,
     * triangle) pair,
     * @code
     * ad_derivatives([&](const auto &tet, const auto &tri) {
     *                  return penalty_energy(tet, tri, g, eps_p);
     *                },
     *                true, tet, tri);
     * @endcode
     * @p energy is a generic callable templated on the number type (it is
     * called with arrays of Point<3, ADNumber>).
     */
    template <typename Energy, std::size_t... N>
    PairDerivatives
    ad_derivatives(const Energy &energy,
                   const bool    with_hessian,
                   const std::array<Point<3>, N> &...groups)
    {
      std::vector<double> coordinates;
      const auto          append = [&](const auto &group) {
        for (const auto &p : group)
          for (unsigned int d = 0; d < 3; ++d)
            coordinates.push_back(p[d]);
      };
      (append(groups), ...);
      const auto unpack = [&](const auto &x) {
        using Number = typename std::decay_t<decltype(x)>::value_type;
        return internal::call_with_points<Number, N...>(
          energy, x, std::make_index_sequence<sizeof...(N)>());
      };
      if (with_hessian)
        return differentiate(coordinates, unpack);
      return differentiate_once(coordinates, unpack);
    }
  } // namespace Contact
} // namespace TissueContact
