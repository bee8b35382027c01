// Every material model: stress = finite-difference derivative of the energy,
// tangent = finite-difference derivative of the stress, zero stress at F = I,
// objectivity, positive-definite tangent at rest and the small-strain Lame
// equivalents of doc/theory/03-materials.md. Also evaluates the Veronda forms
// printed in the paper and in the dissertation and shows what is wrong with
// them (nonzero stress at rest; negative shear modulus).

#include "../tests.h"

#include <tissue_contact/materials/fiber_reinforcement.h>
#include <tissue_contact/materials/linear_elastic.h>
#include <tissue_contact/materials/mooney_rivlin.h>
#include <tissue_contact/materials/neo_hookean.h>
#include <tissue_contact/materials/saint_venant_kirchhoff.h>
#include <tissue_contact/materials/veronda.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

using namespace dealii;
using namespace TissueContact::Materials;
using namespace TissueContactTests;

namespace
{
  const Point<3> X0(0.1, 0.2, 0.3);

  // Central difference of a scalar function of F in direction (k,L).
  template <typename Fn>
  double
  fd(const Fn &f, const Tensor<2, 3> &F, unsigned k, unsigned L, double h)
  {
    Tensor<2, 3> Fp = F, Fm = F;
    Fp[k][L] += h;
    Fm[k][L] -= h;
    return (f(Fp) - f(Fm)) / (2. * h);
  }

  Tensor<2, 3>
  random_rotation()
  {
    Tensor<1, 3> axis;
    for (unsigned d = 0; d < 3; ++d)
      axis[d] = random_value(-1., 1.);
    axis /= axis.norm();
    const double angle = random_value(0., 2. * M_PI);
    Tensor<2, 3> W;
    W[0][1] = -axis[2];
    W[0][2] = axis[1];
    W[1][0] = axis[2];
    W[1][2] = -axis[0];
    W[2][0] = -axis[1];
    W[2][1] = axis[0];
    return unit_symmetric_tensor<3>() + std::sin(angle) * W +
           (1. - std::cos(angle)) * W * W;
  }

  void
  check(const Material &m, const double expected_mu, const double expected_l)
  {
    deallog << "--- " << m.name() << std::endl;
    const double h        = 1e-6;
    double       err_P    = 0.;
    double       err_A    = 0.;
    double       err_obj  = 0.;
    double       err_part = 0.;
    for (unsigned int sample = 0; sample < 20; ++sample)
      {
        const Tensor<2, 3> F = random_deformation_gradient(0.3);
        MaterialResponse   r;
        m.evaluate(F, X0, r);
        const double scale_P = std::max(r.P.norm(), 1.);
        const double scale_A = std::max(r.A.norm(), 1.);

        Tensor<2, 3> P_fd;
        Tensor<4, 3> A_fd;
        for (unsigned k = 0; k < 3; ++k)
          for (unsigned L = 0; L < 3; ++L)
            {
              P_fd[k][L] =
                fd([&](const Tensor<2, 3> &G) { return m.energy(G, X0); },
                   F,
                   k,
                   L,
                   h);
              for (unsigned i = 0; i < 3; ++i)
                for (unsigned J = 0; J < 3; ++J)
                  A_fd[i][J][k][L] = fd(
                    [&](const Tensor<2, 3> &G) {
                      return m.first_piola_kirchhoff(G, X0)[i][J];
                    },
                    F,
                    k,
                    L,
                    h);
            }
        err_P = std::max(err_P, (P_fd - r.P).norm() / scale_P);
        err_A = std::max(err_A, (A_fd - r.A).norm() / scale_A);
        err_part =
          std::max(err_part,
                   (m.first_piola_kirchhoff(F, X0) - r.P).norm() / scale_P +
                     std::abs(m.energy(F, X0) - r.psi) /
                       std::max(std::abs(r.psi), 1.));

        // objectivity: P(QF) = Q P(F) and Psi(QF) = Psi(F)
        const Tensor<2, 3> Q  = random_rotation();
        const Tensor<2, 3> QF = Q * F;
        err_obj               = std::max(err_obj,
                           (m.first_piola_kirchhoff(QF, X0) - Q * r.P).norm() /
                             scale_P);
      }
    deallog << "stress vs FD of energy: relative error " << error_bound(err_P)
            << std::endl;
    deallog << "tangent vs FD of stress: relative error " << error_bound(err_A)
            << std::endl;
    deallog << "evaluate() vs energy()/stress(): " << error_bound(err_part)
            << std::endl;
    deallog << "objectivity P(QF) - Q P(F): " << error_bound(err_obj)
            << std::endl;

    // at rest
    MaterialResponse r0;
    m.evaluate(unit_symmetric_tensor<3>(), X0, r0);
    deallog << "|P(I)| " << error_bound(r0.P.norm()) << ", Psi(I) "
            << error_bound(std::abs(r0.psi)) << std::endl;
    // Lame equivalents from the tangent at rest (fiber along x does not
    // touch A_1111, A_1122 and A_1212 = A_0101)
    const double mu     = r0.A[0][1][0][1];
    const double lambda = r0.A[1][1][2][2];
    deallog << "mu = " << mu << " (table " << expected_mu
            << "), lambda = " << lambda << " (table " << expected_l << ")"
            << std::endl;
    deallog << "A_xxxx = " << r0.A[0][0][0][0] << std::endl;
    // positive definiteness of the tangent on symmetric strains at rest
    LAPACKFullMatrix<double> K(6, 6);
    const unsigned int       voigt[6][2] = {
            {0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
    for (unsigned a = 0; a < 6; ++a)
      for (unsigned b = 0; b < 6; ++b)
        K(a, b) = r0.A[voigt[a][0]][voigt[a][1]][voigt[b][0]][voigt[b][1]] *
                  (a < 3 ? 1. : 2.) * (b < 3 ? 1. : 2.);
    K.compute_eigenvalues();
    double min_ev = 1e300;
    for (unsigned a = 0; a < 6; ++a)
      min_ev = std::min(min_ev, K.eigenvalue(a).real());
    deallog << "smallest eigenvalue of the tangent at rest "
            << (min_ev > 0 ? "positive" : "NOT positive") << std::endl;
  }

  // The Veronda forms as printed in the sources, as energies of C.
  double
  invariant_I1(const Tensor<2, 3> &F)
  {
    return trace(transpose(F) * F);
  }
  double
  trace_C2(const Tensor<2, 3> &F)
  {
    const Tensor<2, 3> C = transpose(F) * F;
    return double_contract<0, 0, 1, 1>(C, C);
  }
  double
  invariant_I2(const Tensor<2, 3> &F)
  {
    const double I1 = invariant_I1(F);
    return 0.5 * (I1 * I1 - trace_C2(F));
  }
  double
  invariant_I3(const Tensor<2, 3> &F)
  {
    const double J = determinant(F);
    return J * J;
  }

  void
  printed_veronda_forms(const double alpha, const double beta, const double a)
  {
    deallog << "--- Veronda forms printed in the sources (alpha=" << alpha
            << " beta=" << beta << " a=" << a << ")" << std::endl;
    const auto paper = [&](const Tensor<2, 3> &F) {
      return 2. * alpha * std::exp(invariant_I1(F) - 3.) +
             alpha * beta * (invariant_I2(F) - 3.) + a * invariant_I3(F) -
             a * std::log(invariant_I3(F));
    };
    const auto dissertation = [&](const Tensor<2, 3> &F) {
      return alpha * std::exp(beta * (invariant_I1(F) - 3.)) -
             0.5 * alpha * beta * trace_C2(F) + a * invariant_I3(F) -
             a * std::log(invariant_I3(F));
    };
    const Veronda corrected(alpha, beta, a);
    const auto    ours = [&](const Tensor<2, 3> &F) {
      return corrected.energy(F, X0);
    };
    const auto report = [&](const std::string &name, const auto &psi) {
      const Tensor<2, 3> I = unit_symmetric_tensor<3>();
      Tensor<2, 3>       P;
      for (unsigned k = 0; k < 3; ++k)
        for (unsigned L = 0; L < 3; ++L)
          P[k][L] = fd(psi, I, k, L, 1e-5);
      // shear modulus: Psi(I + g e1 x e2) = mu g^2 / 2 + O(g^3)
      const double g  = 1e-4;
      Tensor<2, 3> Fp = I, Fm = I;
      Fp[0][1]        = g;
      Fm[0][1]        = -g;
      const double mu = (psi(Fp) - 2. * psi(I) + psi(Fm)) / (g * g);
      deallog << name << ": |P(I)| = "
              << (P.norm() < 1e-4 ? std::string("0") : std::to_string(P.norm()))
              << ", shear modulus " << std::setprecision(4) << mu
              << std::setprecision(6) << std::endl;
    };
    report("paper (P 3.3)", paper);
    report("dissertation (D 3.85)", dissertation);
    report("corrected (implemented)", ours);
  }
} // namespace

int
main()
{
  initlog();

  auto fiber_x = std::make_shared<FunctionParser<3>>(3);
  fiber_x->initialize("x,y,z", "1; 0; 0", std::map<std::string, double>());
  auto fiber_field = std::make_shared<FunctionParser<3>>(3);
  fiber_field->initialize("x,y,z",
                          "1; x; 0.5*z+y",
                          std::map<std::string, double>());

  check(NeoHookean(3., 5.), 3., 5.);
  check(MooneyRivlin(5., 1., 50.), 12., 204.);
  check(Veronda(7., 8., 100.), 56., 4. * (7. * 64. - 28. + 100.));
  check(SaintVenantKirchhoff(3., 5.), 3., 5.);
  check(LinearElastic(3., 5.), 3., 5.);
  check(FiberReinforcement(
          std::make_unique<MooneyRivlin>(5., 1., 50.), 2., 3., fiber_x),
        12.,
        204.);
  deallog << "fiber stiffness added to A_xxxx: 4 alpha beta^2 = "
          << 4. * 2. * 9. << std::endl;
  // a position-dependent fiber field: at X0 the fiber is not along x, so the
  // shear entries include fiber stiffness and differ from the ground table
  deallog << "fiber field (1, x, 0.5 z + y) at X0" << std::endl;
  check(FiberReinforcement(
          std::make_unique<Veronda>(7., 8., 100.), 2., 3., fiber_field),
        56.,
        4. * (7. * 64. - 28. + 100.));

  printed_veronda_forms(7., 8., 100.);

  // invalid parameters give one-line user errors
  const auto expect_error = [](const auto &make) {
    try
      {
        make();
        deallog << "no error (wrong)" << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream s;
        e.print_info(s);
        std::string msg = s.str();
        while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' '))
          msg.pop_back();
        deallog << "error:" << msg.substr(msg.find_first_not_of(' '))
                << std::endl;
      }
  };
  expect_error([] { NeoHookean(-1., 1.); });
  expect_error([] { MooneyRivlin(1., 0., -10.); });
  expect_error([] { Veronda(7., -8., 100.); });
  expect_error([] { LinearElastic(1., -5.); });
}
