#pragma once

#include <tissue_contact/materials/isotropic_material.h>

namespace TissueContact
{
  namespace Materials
  {
    /**
     * Derivatives of an isochoric energy @f$\bar\Psi(\bar I_1, \bar I_2)@f$:
     * @p d[i] @f$=\bar\Psi_{i+1}@f$, @p dd[i][j] @f$=\bar\Psi_{i+1,j+1}@f$.
     */
    struct IsochoricDerivatives
    {
      double d[2]     = {0., 0.};
      double dd[2][2] = {{0., 0.}, {0., 0.}};
    };

    /**
     * The volumetric energy of the uncoupled forms,
     * @f$U(J) = \frac\kappa4(J^2 - 1 - 2\ln J)@f$, and its derivatives
     * (doc/theory/03-materials.md, (M8)).
     */
    struct VolumetricEnergy
    {
      double kappa = 0.;

      double
      U(const double J) const;
      /** @f$U'(J) = \frac\kappa2(J - J^{-1})@f$, the hydrostatic Cauchy
       * stress. */
      double
      dU(const double J) const;
      /** @f$U''(J) = \frac\kappa2(1 + J^{-2})@f$. */
      double
      ddU(const double J) const;
    };


    /**
     * An isotropic material in uncoupled form (doc/theory/03-materials.md,
     * sec. 3.7, (M8)): @f$\Psi = \bar\Psi(\bar I_1, \bar I_2) + U(J)@f$
     * with @f$\bar I_1 = I_3^{-1/3}I_1@f$, @f$\bar I_2 = I_3^{-2/3}I_2@f$
     * and @f$U(J) = \frac\kappa4(J^2 - 1 - 2\ln J)@f$. A model supplies
     * @f$\bar\Psi@f$, its derivatives and its shear modulus at rest; this
     * class maps them to @f$\Psi_i@f$, @f$\Psi_{ij}@f$ by (M9)-(M10), and
     * IsotropicMaterial computes the stress and the tangent. Small-strain
     * equivalents: the model's @f$\mu@f$ and @f$\lambda = \kappa -
     * \frac23\mu@f$.
     *
     * With @p pointwise_volume false the material evaluates
     * @f$\bar\Psi@f$ alone: its volumetric term is integrated at the
     * vertices by Elasticity::NodalPressure (doc/theory/08-nodal-pressure.md).
     * Its small-strain equivalents still include @f$\kappa@f$, the body's.
     */
    class UncoupledMaterial : public IsotropicMaterial
    {
    public:
      /** Throws unless the bulk modulus @p kappa is positive. */
      UncoupledMaterial(const double kappa, const bool pointwise_volume);

      /** @f$\bar\Psi@f$. */
      virtual double
      psi_isochoric(const double I1_bar, const double I2_bar) const = 0;
      /** @f$\bar\Psi_i@f$ and @f$\bar\Psi_{ij}@f$. */
      virtual IsochoricDerivatives
      psi_isochoric_derivatives(const double I1_bar,
                                const double I2_bar) const = 0;
      /** The small-strain shear modulus @f$2(\bar\Psi_1 + \bar\Psi_2)@f$
       * at rest. */
      virtual double
      shear_modulus() const = 0;

      double
      psi(const Invariants &I) const override;
      InvariantDerivatives
      psi_derivatives(const Invariants &I) const override;
      std::pair<double, double>
      lame_equivalents() const override
      {
        return {shear_modulus(), kappa - 2. * shear_modulus() / 3.};
      }

    protected:
      /** The checks every model's constructor ends with: a positive shear
       * modulus (check_stable_lame_parameters). */
      void
      check_parameters() const;

      const double kappa;
      /** Whether @f$U(J)@f$ is part of the energy evaluated here. */
      const bool pointwise_volume;
    };


    /** Uncoupled neo-Hookean: @f$\bar\Psi = \frac\mu2(\bar I_1 - 3)@f$. */
    class UncoupledNeoHookean : public UncoupledMaterial
    {
    public:
      UncoupledNeoHookean(const double mu,
                          const double kappa,
                          const bool   pointwise_volume = true);
      std::string
      name() const override
      {
        return "uncoupled neo-Hookean";
      }
      double
      psi_isochoric(const double I1_bar, const double I2_bar) const override;
      IsochoricDerivatives
      psi_isochoric_derivatives(const double I1_bar,
                                const double I2_bar) const override;
      double
      shear_modulus() const override
      {
        return mu;
      }

    private:
      const double mu;
    };


    /** Uncoupled Mooney-Rivlin: @f$\bar\Psi = C_1(\bar I_1 - 3) +
     * C_2(\bar I_2 - 3)@f$. */
    class UncoupledMooneyRivlin : public UncoupledMaterial
    {
    public:
      UncoupledMooneyRivlin(const double C1,
                            const double C2,
                            const double kappa,
                            const bool   pointwise_volume = true);
      std::string
      name() const override
      {
        return "uncoupled Mooney-Rivlin";
      }
      double
      psi_isochoric(const double I1_bar, const double I2_bar) const override;
      IsochoricDerivatives
      psi_isochoric_derivatives(const double I1_bar,
                                const double I2_bar) const override;
      double
      shear_modulus() const override
      {
        return 2. * (C1 + C2);
      }

    private:
      const double C1, C2;
    };


    /** Uncoupled Veronda-Westmann: @f$\bar\Psi = \alpha(e^{\beta(\bar I_1 -
     * 3)} - 1) - \frac{\alpha\beta}2(\bar I_2 - 3)@f$. */
    class UncoupledVeronda : public UncoupledMaterial
    {
    public:
      /** Throws unless @f$\alpha > 0@f$ and @f$\beta > 0@f$. */
      UncoupledVeronda(const double alpha,
                       const double beta,
                       const double kappa,
                       const bool   pointwise_volume = true);
      std::string
      name() const override
      {
        return "uncoupled Veronda";
      }
      double
      psi_isochoric(const double I1_bar, const double I2_bar) const override;
      IsochoricDerivatives
      psi_isochoric_derivatives(const double I1_bar,
                                const double I2_bar) const override;
      double
      shear_modulus() const override
      {
        return alpha * beta;
      }

    private:
      const double alpha, beta;
    };
  } // namespace Materials
} // namespace TissueContact
