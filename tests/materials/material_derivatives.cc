// Every material model: stress = finite-difference derivative of the energy,
// tangent = finite-difference derivative of the stress, zero stress at F = I,
// objectivity, positive-definite tangent at rest and the small-strain Lame
// equivalents of doc/theory/03-materials.md. Also evaluates the Veronda forms
// printed in the paper and in the dissertation and shows what is wrong with
// them (nonzero stress at rest; negative shear modulus). Finally every model
// against an independent evaluation: Psi, P and the tangent at one F from a
// symbolic derivation of the energies of doc/theory/03-materials.md
// (contrib/material_reference.py, differentiating Psi(F) directly; the
// corotated model's in 60-digit arithmetic). Corotated elasticity against
// linear elasticity at small strain and under a 90 degree rotation. The
// uncoupled forms: a pure dilatation gives the pressure U'(J) whatever the
// shear parameters, an isochoric deformation a traceless Cauchy stress.
// Every hyperelastic model's spatial stress and tangent (stress_b(), the
// closed form (M3S) or the push-forward) against P F^T and A.

#include "../tests.h"

#include <tissue_contact/materials/corotated.h>
#include <tissue_contact/materials/fiber_reinforcement.h>
#include <tissue_contact/materials/linear_elastic.h>
#include <tissue_contact/materials/mooney_rivlin.h>
#include <tissue_contact/materials/neo_hookean.h>
#include <tissue_contact/materials/saint_venant_kirchhoff.h>
#include <tissue_contact/materials/uncoupled_material.h>
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


  void
  check(const Material &m, const double expected_mu, const double expected_l)
  {
    deallog << "--- " << m.name() << std::endl;
    const double h           = 1e-6;
    double       err_P       = 0.;
    double       err_A       = 0.;
    double       err_obj     = 0.;
    double       err_part    = 0.;
    double       err_spatial = 0.;
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

        // the spatial form (doc/theory/02, (L5)): tau = P F^T and
        // c_ijkl = A_iJkL F_jJ F_lL - delta_ik tau_jl, in Voigt form
        if (const auto *hyper = dynamic_cast<const HyperelasticMaterial *>(&m))
          {
            SymmetricTensor<2, 3> tau;
            VoigtTangent          c;
            hyper->stress_b(F, X0, tau, &c);
            const Tensor<2, 3> tau_P = r.P * transpose(F);
            double             e_tau = 0., e_c = 0.;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                e_tau = std::max(e_tau, std::abs(tau[i][j] - tau_P[i][j]));
            const auto &index = VoigtTangent::index;
            for (unsigned int p = 0; p < 6; ++p)
              for (unsigned int q = 0; q < 6; ++q)
                {
                  const unsigned int i = index[p][0], j = index[p][1],
                                     k = index[q][0], l = index[q][1];
                  double cA = i == k ? -tau_P[j][l] : 0.;
                  for (unsigned int J = 0; J < 3; ++J)
                    for (unsigned int L = 0; L < 3; ++L)
                      cA += r.A[i][J][k][L] * F[j][J] * F[l][L];
                  e_c = std::max(e_c, std::abs(c.D[p][q] - cA));
                }
            err_spatial =
              std::max(err_spatial,
                       e_tau / std::max(tau_P.norm(), 1.) +
                         e_c / std::max(r.A.norm() * F.norm() * F.norm(), 1.));
          }

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
    if (dynamic_cast<const HyperelasticMaterial *>(&m) != nullptr)
      deallog << "spatial tau, c (stress_b) vs P F^T and A: "
              << error_bound(err_spatial) << std::endl;

    // at rest
    MaterialResponse r0;
    m.evaluate(unit_symmetric_tensor<3>(), X0, r0);
    deallog << "|P(I)| " << error_bound(r0.P.norm()) << ", Psi(I) "
            << error_bound(std::abs(r0.psi)) << std::endl;
    // Lame equivalents from the tangent at rest (fiber along x does not
    // touch A_1111, A_1122 and A_1212 = A_0101)
    const double mu     = r0.A[0][1][0][1];
    const double lambda = r0.A[1][1][2][2];
    deallog << "mu = " << mu << ", lambda = " << lambda << "; minus the table: "
            << error_bound(std::abs(mu - expected_mu) / std::abs(expected_mu))
            << ", "
            << error_bound(std::abs(lambda - expected_l) / std::abs(expected_l))
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

  /** Psi, P (row by row), |A| and G : A : H at F_ref, from
   * contrib/material_reference.py. */
  struct Reference
  {
    double                psi;
    std::array<double, 9> P;
    double                norm_A, G_A_H;
  };

  void
  compare_with_reference(const Material &m, const Reference &ref)
  {
    const double F_ref[3][3] = {{1.1, 0.2, -0.1},
                                {0.05, 0.9, 0.15},
                                {-0.12, 0.08, 1.05}};
    const double G[3][3]     = {{1, 2, 0}, {0, -1, 3}, {1, 0, 1}};
    const double H[3][3]     = {{0, 1, -1}, {2, 1, 0}, {0, 3, 1}};
    Tensor<2, 3> F;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J = 0; J < 3; ++J)
        F[i][J] = F_ref[i][J];
    MaterialResponse r;
    m.evaluate(F, X0, r);
    double dP = 0., nP = 0., nA = 0., GAH = 0.;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J = 0; J < 3; ++J)
        {
          dP += std::pow(r.P[i][J] - ref.P[3 * i + J], 2);
          nP += std::pow(ref.P[3 * i + J], 2);
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int L = 0; L < 3; ++L)
              {
                nA += std::pow(r.A[i][J][k][L], 2);
                GAH += G[i][J] * r.A[i][J][k][L] * H[k][L];
              }
        }
    deallog << m.name() << ": Psi "
            << error_bound(std::abs(r.psi - ref.psi) / std::abs(ref.psi), -15)
            << ", P " << error_bound(std::sqrt(dP / nP), -15) << ", |A| "
            << error_bound(std::abs(std::sqrt(nA) - ref.norm_A) / ref.norm_A,
                           -15)
            << ", G:A:H "
            << error_bound(std::abs(GAH - ref.G_A_H) / std::abs(ref.G_A_H), -15)
            << std::endl;
  }

  /** Corotated against linear elasticity (doc/theory/03-materials.md sec.
   * 3.6): the same stress to first order in a small displacement gradient
   * (the difference falls with its square, relative to the stress linearly),
   * zero stress under a rotation
   * by 90 degrees where linear elasticity's is of the order of mu, and a
   * rotated stretch loaded by 90 degrees gives the rotated stress. */
  void
  corotated_against_linear(const double mu, const double lambda)
  {
    deallog << "--- corotated against linear elasticity" << std::endl;
    const Corotated     corotated(mu, lambda);
    const LinearElastic linear(mu, lambda);
    const Tensor<2, 3>  I = unit_symmetric_tensor<3>();
    Tensor<2, 3>        H;
    const double        h_entries[3][3] = {{0.3, -0.2, 0.5},
                                           {0.1, -0.4, 0.2},
                                           {0.6, 0.3, 0.1}};
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int J = 0; J < 3; ++J)
        H[i][J] = h_entries[i][J];
    for (const double g : {1e-2, 1e-3, 1e-4})
      {
        const Tensor<2, 3> F  = I + g * H;
        const Tensor<2, 3> Pc = corotated.first_piola_kirchhoff(F, X0);
        const Tensor<2, 3> Pl = linear.first_piola_kirchhoff(F, X0);
        deallog << "|grad u| = " << g * H.norm()
                << ": |P_corotated - P_linear| / |P_linear| = "
                << std::setprecision(2) << (Pc - Pl).norm() / Pl.norm()
                << std::setprecision(6) << std::endl;
      }
    // rotation by 90 degrees about z
    Tensor<2, 3> Q;
    Q[0][1] = -1.;
    Q[1][0] = 1.;
    Q[2][2] = 1.;
    deallog << "F = Q (90 degrees): |P| / mu corotated "
            << error_bound(corotated.first_piola_kirchhoff(Q, X0).norm() / mu)
            << ", linear " << std::setprecision(3)
            << linear.first_piola_kirchhoff(Q, X0).norm() / mu
            << std::setprecision(6) << std::endl;
    const Tensor<2, 3> F = I + 0.1 * H;
    deallog << "F -> QF (90 degrees): |P(QF) - Q P(F)| / |P(F)| corotated "
            << error_bound((corotated.first_piola_kirchhoff(Q * F, X0) -
                            Q * corotated.first_piola_kirchhoff(F, X0))
                             .norm() /
                           corotated.first_piola_kirchhoff(F, X0).norm())
            << ", linear " << std::setprecision(3)
            << (linear.first_piola_kirchhoff(Q * F, X0) -
                Q * linear.first_piola_kirchhoff(F, X0))
                   .norm() /
                 linear.first_piola_kirchhoff(F, X0).norm()
            << std::setprecision(6) << std::endl;
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

  /** The uncoupled forms separate volume and shape (doc/theory/03-materials.md
   * sec. 3.7): under F = s I the Cauchy stress is the pressure U'(J) I with
   * U'(J) = kappa/2 (J - 1/J), the same for every isochoric energy; under a
   * deformation with det F = 1 it is traceless. */
  void
  uncoupled_split()
  {
    deallog << "--- uncoupled forms: volume and shape apart" << std::endl;
    const double       kappa = 40.;
    const Tensor<2, 3> I     = unit_symmetric_tensor<3>();
    Tensor<2, 3>       shear = I; // det = 1
    shear[0][1]              = 0.4;
    shear[2][0]              = -0.3;
    const Tensor<2, 3> stretch =
      Tensor<2, 3>({{1.3, 0., 0.}, {0., 1. / 1.3, 0.}, {0., 0., 1.}});
    const UncoupledNeoHookean   nh(3., kappa);
    const UncoupledMooneyRivlin mr(5., 1., kappa);
    const UncoupledVeronda      ve(7., 8., kappa);
    for (const Material *m :
         std::initializer_list<const Material *>{&nh, &mr, &ve})
      {
        double err_p = 0., err_tr = 0.;
        for (const double s : {0.8, 0.95, 1.1})
          {
            const Tensor<2, 3> F = s * I;
            const double       J = s * s * s;
            const Tensor<2, 3> sigma =
              m->first_piola_kirchhoff(F, X0) * transpose(F) / J;
            const double p = 0.5 * kappa * (J - 1. / J);
            err_p = std::max(err_p, (sigma - p * I).norm() / std::abs(p));
          }
        for (const Tensor<2, 3> &F : {shear, stretch, shear * stretch})
          {
            const Tensor<2, 3> sigma =
              m->first_piola_kirchhoff(F, X0) * transpose(F);
            err_tr = std::max(err_tr, std::abs(trace(sigma)) / sigma.norm());
          }
        deallog << m->name() << ": F = s I, |sigma - U'(J) I| / |U'(J)| "
                << error_bound(err_p) << "; det F = 1, |tr sigma| / |sigma| "
                << error_bound(err_tr) << std::endl;
      }
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
  check(Corotated(3., 5.), 3., 5.);
  corotated_against_linear(3., 5.);
  check(UncoupledNeoHookean(3., 50.), 3., 50. - 2.);
  check(UncoupledMooneyRivlin(5., 1., 60.), 12., 60. - 8.);
  check(UncoupledVeronda(7., 8., 500.), 56., 500. - 112. / 3.);
  uncoupled_split();
  check(FiberReinforcement(
          std::make_unique<MooneyRivlin>(5., 1., 50.), 2., 3., fiber_x),
        12.,
        204.);
  {
    // at rest the fiber adds C_f = 4 alpha_f beta_f^2 f x f x f x f
    // (doc/theory/03-materials.md, sec. 3.5)
    MaterialResponse with, without;
    FiberReinforcement(std::make_unique<MooneyRivlin>(5., 1., 50.),
                       2.,
                       3.,
                       fiber_x)
      .evaluate(unit_symmetric_tensor<3>(), X0, with);
    MooneyRivlin(5., 1., 50.).evaluate(unit_symmetric_tensor<3>(), X0, without);
    const double added = with.A[0][0][0][0] - without.A[0][0][0][0];
    deallog << "fiber stiffness added to A_xxxx: " << added
            << "; minus 4 alpha beta^2: "
            << error_bound(std::abs(added - 4. * 2. * 9.) / 72.) << std::endl;
  }
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
  expect_error([] { UncoupledMooneyRivlin(5., 1., -1.); });
  expect_error([] { UncoupledVeronda(7., 8., 0.); });

  // against the independent symbolic evaluation
  deallog << "--- against contrib/material_reference.py at F_ref" << std::endl;
  const Reference references[] = {
    // neo-Hookean(3, 5)
    {0.32445399650303897,
     {0.50845421483899567,
      0.81093673939319488,
      -0.63510517463883442,
      0.80225828635058838,
      -0.71986798760881876,
      0.78510517463883434,
      -0.71904125854160827,
      0.74864178293394501,
      0.21782972191019911},
     26.841408718912469,
     45.89942604232143},
    // Mooney-Rivlin(5, 1, 50)
    {1.3358272120284773,
     {2.3707757442557442,
      3.3946010289710289,
      -2.5376047552447552,
      3.3133428271728271,
      -2.5913481718281717,
      3.333684755244755,
      -2.8932836663336663,
      3.1649393606393605,
      1.2778583916083917},
     693.43624046823709,
     275.71102715012262},
    // Veronda(7, 8, 100)
    {25.907496393812622,
     {588.26221048996979,
      116.57665715928793,
      -64.355483914309303,
      37.399654324787015,
      461.78340545855394,
      88.175214682652765,
      -75.925353820048286,
      50.711587195383508,
      554.63019033101693},
     34540.817676244493,
     54160.20050114717},
    // Saint Venant-Kirchhoff(3, 5)
    {0.33309509874999998,
     {1.5708850000000001,
      0.80610999999999999,
      -0.72972499999999996,
      0.64807749999999997,
      0.23131499999999999,
      0.64563749999999998,
      -0.80565299999999995,
      0.54410199999999997,
      1.1283075},
     29.554317243720924,
     72.061599999999999},
    // linear(Z(3), Z(5))
    {0.31945000000000001,
     {0.84999999999999998,
      0.75,
      -0.66000000000000003,
      0.75,
      -0.34999999999999998,
      0.68999999999999995,
      -0.66000000000000003,
      0.68999999999999995,
      0.55000000000000004},
     24.919871588754223,
     52},
    // Mooney-Rivlin(5, 1, 50) + fiber(2, 3, e_x)
    {1.9249470727403033,
     {15.244206824953796,
      3.3946010289710289,
      -2.5376047552447552,
      3.8984987853863751,
      -2.5913481718281717,
      3.333684755244755,
      -4.2976579660461809,
      3.1649393606393605,
      1.2778583916083917},
     766.21692272169298,
     289.64846121871392},
    // corotated(3, 5)
    {0.32325846573181843,
     {0.89826498293655732,
      0.78397253775359677,
      -0.62689987300239935,
      0.71666826042602472,
      -0.29893925236621177,
      0.72093683820679777,
      -0.70621547011036823,
      0.66054696290618009,
      0.58591237044449407},
     24.941569367548293,
     52.011194148183598}, // uncoupled neo-Hookean(3, 50)
    {0.32425937120783566,
     {0.34675242204413448,
      0.8225895971113758,
      -0.65405261440937112,
      0.83942716933232975,
      -0.91707125078826812,
      0.80395269766869826,
      -0.73931639399101035,
      0.77754474162047582,
      0.048192829402095821},
     165.61155194431879,
     61.35642534686523},
    // uncoupled Mooney-Rivlin(5, 1, 60)
    {1.3346922741744542,
     {1.2401691979749039,
      3.4771579074341683,
      -2.6711121286987858,
      3.5744079239787498,
      -3.9720924156492754,
      3.4664647596209086,
      -3.0361805757378497,
      3.3680212689857809,
      0.091210267815012597},
     213.75936601189909,
     205.75115927722953},
    // uncoupled Veronda(7, 8, 500)
    {25.346557365822786,
     {58.474337902569161,
      153.42589471696138,
      -125.33996633243254,
      157.73519370893564,
      -182.21156806836584,
      148.60372275627213,
      -141.1217765481081,
      144.0925499210997,
      -0.65630598693419007},
     7710.9055805311937,
     31335.113109138383},
  };
  const std::unique_ptr<Material> models[] = {
    std::make_unique<NeoHookean>(3., 5.),
    std::make_unique<MooneyRivlin>(5., 1., 50.),
    std::make_unique<Veronda>(7., 8., 100.),
    std::make_unique<SaintVenantKirchhoff>(3., 5.),
    std::make_unique<LinearElastic>(3., 5.),
    std::make_unique<FiberReinforcement>(
      std::make_unique<MooneyRivlin>(5., 1., 50.), 2., 3., fiber_x),
    std::make_unique<Corotated>(3., 5.),
    std::make_unique<UncoupledNeoHookean>(3., 50.),
    std::make_unique<UncoupledMooneyRivlin>(5., 1., 60.),
    std::make_unique<UncoupledVeronda>(7., 8., 500.)};
  for (unsigned int m = 0; m < 10; ++m)
    compare_with_reference(*models[m], references[m]);
}
