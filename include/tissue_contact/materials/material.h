#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <string>

namespace TissueContact
{
  namespace Materials
  {
    using namespace dealii;

    /**
     * The constitutive response at one material point: the strain energy
     * density @f$\Psi@f$ per unit reference volume, the first Piola-Kirchhoff
     * stress @f$P = \partial\Psi/\partial F@f$ and the tangent
     * @f$\mathcal{A} = \partial P/\partial F@f$ (components
     * @f$\mathcal{A}_{iJkL} = \partial P_{iJ}/\partial F_{kL}@f$).
     *
     * See doc/theory/02-weak-form-and-linearization.md.
     */
    struct MaterialResponse
    {
      double       psi = 0.;
      Tensor<2, 3> P;
      Tensor<4, 3> A;
    };

    /**
     * Interface of every elastic material: energy, stress and exact tangent
     * as functions of the deformation gradient @p F at the reference point
     * @p X (needed by position-dependent data such as fiber directions).
     *
     * Implementations assume @f$J = \det F > 0@f$; the assembler checks this
     * before it calls a material.
     */
    class Material
    {
    public:
      virtual ~Material() = default;

      /** Name of the model as written in parameter files. */
      virtual std::string
      name() const = 0;

      /** Strain energy density @f$\Psi(F)@f$ per unit reference volume. */
      virtual double
      energy(const Tensor<2, 3> &F, const Point<3> &X) const = 0;

      /** First Piola-Kirchhoff stress @f$P(F)@f$. */
      virtual Tensor<2, 3>
      first_piola_kirchhoff(const Tensor<2, 3> &F, const Point<3> &X) const = 0;

      /** Energy, stress and tangent together (the cheapest way to get all). */
      virtual void
      evaluate(const Tensor<2, 3> &F,
               const Point<3>     &X,
               MaterialResponse   &response) const = 0;

      /**
       * Small-strain Lame parameters @f$(\mu,\lambda)@f$ of the model at
       * @f$F = I@f$ (the table of doc/theory/03-materials.md), used for
       * stable time steps and for viscosity scaling.
       */
      virtual std::pair<double, double>
      lame_equivalents() const = 0;
    };


    /**
     * Push the material (second Piola-Kirchhoff) stress @p S and elasticity
     * tensor @p CC (@f$\mathbb{C}_{IJKL} = \partial S_{IJ}/\partial E_{KL}@f$,
     * with minor symmetries) forward to the two-point quantities
     * @f$P = F S@f$ and
     * @f$\mathcal{A}_{iJkL} = \delta_{ik} S_{JL}
     *      + F_{iI}\,\mathbb{C}_{IJLN}\,F_{kN}@f$,
     * i.e. the initial-stress and the constitutive part of the tangent
     * (doc/theory/02-weak-form-and-linearization.md, eq. (L3)).
     */
    void
    push_forward_tangent(const Tensor<2, 3> &F,
                         const Tensor<2, 3> &S,
                         const Tensor<4, 3> &CC,
                         Tensor<2, 3>       &P,
                         Tensor<4, 3>       &A);


    /**
     * Throw a user-facing error unless the small-strain Lame parameters of a
     * model describe a stable solid: shear modulus @f$\mu > 0@f$ and bulk
     * modulus @f$\kappa = \lambda + \frac23\mu > 0@f$.
     */
    void
    check_stable_lame_parameters(const std::string &model,
                                 const double       mu,
                                 const double       lambda);

  } // namespace Materials
} // namespace TissueContact
