#include <tissue_contact/materials/fiber_reinforcement.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace TissueContact
{
  namespace Materials
  {
    FiberReinforcement::FiberReinforcement(
      std::unique_ptr<HyperelasticMaterial> ground,
      const double                          alpha_f,
      const double                          beta_f,
      std::shared_ptr<const Function<3>>    direction)
      : ground(std::move(ground))
      , alpha_f(alpha_f)
      , beta_f(beta_f)
      , direction(std::move(direction))
    {
      Assert(this->ground != nullptr, ExcInternalError());
      AssertThrow(alpha_f >= 0. && beta_f > 0.,
                  ExcMessage("fiber reinforcement: alpha must be >= 0 and "
                             "beta > 0 (alpha = " +
                             std::to_string(alpha_f) +
                             ", beta = " + std::to_string(beta_f) + ")"));
      AssertThrow(this->direction->n_components == 3,
                  ExcMessage("fiber reinforcement: the fiber direction "
                             "function must have 3 components"));
    }


    std::string
    FiberReinforcement::name() const
    {
      return ground->name() + " + fibers";
    }


    Tensor<1, 3>
    FiberReinforcement::fiber_direction(const Point<3> &X) const
    {
      Tensor<1, 3> f;
      for (unsigned int d = 0; d < 3; ++d)
        f[d] = direction->value(X, d);
      const double norm = f.norm();
      AssertThrow(norm > 1e-12,
                  ExcMessage("fiber reinforcement: the fiber direction "
                             "vanishes at a point of the body; give a nonzero "
                             "direction everywhere"));
      return f / norm;
    }


    double
    FiberReinforcement::energy_C(const SymmetricTensor<2, 3> &C,
                                 const Point<3>              &X) const
    {
      const Tensor<1, 3> f   = fiber_direction(X);
      const double       lf2 = f * (C * f);
      return ground->energy_C(C, X) +
             alpha_f * (std::exp(beta_f * (lf2 - 1.)) - 1.) -
             alpha_f * beta_f * (lf2 - 1.);
    }


    void
    FiberReinforcement::stress_C(const SymmetricTensor<2, 3> &C,
                                 const Point<3>              &X,
                                 SymmetricTensor<2, 3>       &S,
                                 VoigtTangent                *CC) const
    {
      ground->stress_C(C, X, S, CC);
      const Tensor<1, 3> f = fiber_direction(X);
      add_fiber(f, f * (C * f), S, CC);
    }


    void
    FiberReinforcement::stress_b(const Tensor<2, 3>    &F,
                                 const Point<3>        &X,
                                 SymmetricTensor<2, 3> &tau,
                                 VoigtTangent          *c) const
    {
      // stress_C() pushed forward: f (x) f becomes a (x) a with the
      // stretched fiber a = F f, whose length squared is f . C f
      ground->stress_b(F, X, tau, c);
      const Tensor<1, 3> a = F * fiber_direction(X);
      add_fiber(a, a * a, tau, c);
    }


    void
    FiberReinforcement::add_fiber(const Tensor<1, 3>    &v,
                                  const double           lf2,
                                  SymmetricTensor<2, 3> &stress,
                                  VoigtTangent          *tangent) const
    {
      const double                e  = std::exp(beta_f * (lf2 - 1.));
      const SymmetricTensor<2, 3> vv = symmetrize(outer_product(v, v));
      stress += 2. * alpha_f * beta_f * (e - 1.) * vv;
      if (tangent != nullptr)
        tangent->add_outer(4. * alpha_f * beta_f * beta_f * e, vv, vv);
    }
  } // namespace Materials
} // namespace TissueContact
