// The single-rotation element (tet10SR, doc/theory/10-single-rotation.md).
// PolarRotation: R orthogonal with R^T F symmetric, dR (SR2) and d2R (SR3)
// against central differences of the decomposition, d2R symmetric in its
// two directions. The element on a distorted two-body P2 mesh (body 0
// single-rotation, body 1 neo-Hookean) at a random displacement in a large
// rotation: residual (SR4) = FD gradient of the energy (SR1), tangent (SR5)
// = FD of the residual, symmetric; zero energy and residual under a rigid
// motion; energy unchanged and residual rotated under a superposed
// rotation; linear elasticity's residual to first order at small strain;
// on P1 the corotated material exactly; the 6-point P2 rule integrates its
// stiffness exactly.

#include "../distorted_box.h"
#include "../tests.h"

#include <tissue_contact/base/polar_rotation.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/materials/corotated.h>
#include <tissue_contact/materials/linear_elastic.h>
#include <tissue_contact/materials/neo_hookean.h>


using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  Tensor<2, 3>
  random_direction()
  {
    Tensor<2, 3> D;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        D[i][j] = random_value(-1., 1.);
    return D;
  }

  void
  check_polar_rotation()
  {
    double orthogonality = 0., symmetry = 0., first = 0., second = 0.,
           d2_symmetry = 0.;
    const double h     = 1e-6;
    for (unsigned int trial = 0; trial < 20; ++trial)
      {
        const Tensor<2, 3> F =
          random_rotation() * random_deformation_gradient(0.4);
        const PolarRotation p(F);
        const Tensor<2, 3>  R = p.R();
        orthogonality =
          std::max(orthogonality,
                   (transpose(R) * R - unit_symmetric_tensor<3>()).norm());
        const Tensor<2, 3> RtF = transpose(R) * F;
        symmetry = std::max(symmetry, (RtF - transpose(RtF)).norm() / F.norm());

        const Tensor<2, 3> D1 = random_direction(), D2 = random_direction();
        const Tensor<2, 3> fd1 =
          (PolarRotation(F + h * D1).R() - PolarRotation(F - h * D1).R()) /
          (2 * h);
        first = std::max(first, (p.dR(D1) - fd1).norm() / fd1.norm());
        const Tensor<2, 3> fd2 = (PolarRotation(F + h * D2).dR(D1) -
                                  PolarRotation(F - h * D2).dR(D1)) /
                                 (2 * h);
        const Tensor<2, 3> d2 = p.d2R(D1, D2);
        second = std::max(second, (d2 - fd2).norm() / fd2.norm());
        d2_symmetry =
          std::max(d2_symmetry, (d2 - p.d2R(D2, D1)).norm() / d2.norm());
      }
    deallog << "polar rotation: |R^T R - I| " << error_bound(orthogonality)
            << ", |R^T F - F^T R| / |F| " << error_bound(symmetry) << std::endl;
    deallog << "polar rotation: dR vs FD " << error_bound(first, -8)
            << ", d2R vs FD of dR " << error_bound(second, -8)
            << ", d2R asymmetry " << error_bound(d2_symmetry) << std::endl;
  }

  /** u of the motion x = Q (X - c) + c + t applied to @p u0's positions. */
  Vector<double>
  superpose(const Discretization &disc,
            const Vector<double> &u0,
            const Tensor<2, 3>   &Q,
            const Tensor<1, 3>   &t)
  {
    const std::vector<Point<3>> X         = disc.support_points();
    const std::vector<unsigned> component = disc.dof_components();
    // positions x_a, node by node
    std::map<std::pair<double, std::pair<double, double>>,
             std::array<types::global_dof_index, 3>>
      nodes;
    for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
      nodes[{X[i][0], {X[i][1], X[i][2]}}][component[i]] = i;
    Vector<double> u(u0.size());
    for (const auto &n : nodes)
      {
        const auto  &dofs = n.second;
        Tensor<1, 3> x;
        for (unsigned int d = 0; d < 3; ++d)
          x[d] = X[dofs[d]][d] + u0[dofs[d]];
        const Tensor<1, 3> y = Q * x + t;
        for (unsigned int d = 0; d < 3; ++d)
          u[dofs[d]] = y[d] - X[dofs[d]][d];
      }
    return u;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  check_polar_rotation();

  Triangulation<3> tria;
  distorted_box(tria, {{2, 1, 1}}, Point<3>(2, 1, 1), 0.2, 3, 1.5);

  const double                mu = 3., lambda = 5.;
  const Materials::Corotated  corotated(mu, lambda);
  const Materials::NeoHookean neo_hookean(2., 4.);
  using VolumeTerm = Elasticity::BodyData::VolumeTerm;
  const std::map<types::material_id, Elasticity::BodyData> bodies = {
    {0, {&corotated, 1., true, VolumeTerm::in_material, 0., true}},
    {1, {&neo_hookean, 1.}}};
  Elasticity::DeadLoads loads;
  loads.gravity = Tensor<1, 3>({0., 0., -1.});

  const Discretization         disc(tria, 2);
  Elasticity::ElasticAssembler assembler(disc, bodies, loads);
  Vector<double>               u(disc.n_dofs()), R(disc.n_dofs());
  SparseMatrix<double>         K(assembler.sparsity_pattern());
  assembler.assemble(u, 0., R, &K);
  deallog << "P2: unknowns " << disc.n_dofs() << ", at rest |R| "
          << error_bound(R.l2_norm()) << std::endl;

  // a random displacement in a large rotation
  for (auto &v : u)
    v = random_value(-0.04, 0.04);
  const Tensor<2, 3>   Q = random_rotation();
  const Tensor<1, 3>   t({0.3, -0.2, 0.1});
  const Vector<double> u_rotated = superpose(disc, u, Q, t);
  deallog << "P2, rotated random displacement: valid "
          << assembler.assemble(u_rotated, 0.6, R, &K) << std::endl;
  const FiniteDifferenceErrors e =
    finite_difference_errors(assembler, u_rotated, 0.6, R, K);
  deallog << "P2: residual vs FD gradient of the energy "
          << error_bound(e.residual, -8) << ", tangent vs FD of the residual "
          << error_bound(e.tangent, -8) << ", asymmetry "
          << error_bound(e.asymmetry) << std::endl;

  // the single-rotation body alone for the invariances
  const std::map<types::material_id, Elasticity::BodyData> single = {
    {0, {&corotated, 1., true, VolumeTerm::in_material, 0., true}},
    {1, {&corotated, 1., true, VolumeTerm::in_material, 0., true}}};
  Elasticity::ElasticAssembler sr(disc, single, Elasticity::DeadLoads());
  {
    const Vector<double> rigid =
      superpose(disc, Vector<double>(u.size()), Q, t);
    Vector<double> R_rigid(u.size());
    sr.assemble(rigid, 0., R_rigid, nullptr);
    deallog << "rigid motion: energy "
            << error_bound(std::abs(sr.energy(rigid, 0.))) << ", |R| "
            << error_bound(R_rigid.l2_norm()) << std::endl;

    Vector<double> R0(u.size()), R1(u.size());
    sr.assemble(u, 0., R0, nullptr);
    sr.assemble(u_rotated, 0., R1, nullptr);
    const double W0 = sr.energy(u, 0.), W1 = sr.energy(u_rotated, 0.);
    // R1 = Q R0 node by node: R1 - Q R0 as the residual of the rotation
    // of R0's "positions" with the translation removed
    Vector<double> QR0 = superpose(disc, R0, Q, Tensor<1, 3>());
    // superpose returns Q (X + R0) - X; remove Q X - X
    QR0 -= superpose(disc, Vector<double>(u.size()), Q, Tensor<1, 3>());
    QR0 -= R1;
    deallog << "superposed rotation: energy difference "
            << error_bound(std::abs(W1 - W0) / W0) << ", residual "
            << error_bound(QR0.l2_norm() / R0.l2_norm()) << std::endl;
  }

  // the reduced P2 quadrature (6 points, degree 3) integrates K_e exactly
  {
    const Discretization         reduced(tria, 2, true);
    Elasticity::ElasticAssembler sr_reduced(reduced,
                                            single,
                                            Elasticity::DeadLoads());
    const double                 W = sr.energy(u_rotated, 0.),
                 W_reduced         = sr_reduced.energy(u_rotated, 0.);
    deallog << "6-point quadrature: " << reduced.stiffness_quadrature.size()
            << " points, energy difference to 14 points "
            << error_bound(std::abs(W_reduced - W) / W) << std::endl;
  }

  // small strain: linear elasticity's residual to first order
  {
    const Materials::LinearElastic                           linear(mu, lambda);
    const std::map<types::material_id, Elasticity::BodyData> linear_bodies = {
      {0, {&linear, 1.}}, {1, {&linear, 1.}}};
    Elasticity::ElasticAssembler lin(disc,
                                     linear_bodies,
                                     Elasticity::DeadLoads());
    Vector<double>               direction(u.size());
    for (auto &v : direction)
      v = random_value(-1., 1.);
    for (const double amplitude : {1e-2, 1e-3, 1e-4})
      {
        Vector<double> v(direction), R_sr(u.size()), R_lin(u.size());
        v *= amplitude;
        sr.assemble(v, 0., R_sr, nullptr);
        lin.assemble(v, 0., R_lin, nullptr);
        R_sr -= R_lin;
        deallog << "small strain " << amplitude
                << ": relative difference to linear elasticity "
                << scientific(R_sr.l2_norm() / R_lin.l2_norm()) << std::endl;
      }
  }

  // P1: the corotated material
  {
    const Discretization                                     disc1(tria, 1);
    const std::map<types::material_id, Elasticity::BodyData> pointwise = {
      {0, {&corotated, 1.}}, {1, {&corotated, 1.}}};
    Elasticity::ElasticAssembler a(disc1, single, loads),
      b(disc1, pointwise, loads);
    Vector<double> u1(disc1.n_dofs());
    for (auto &v : u1)
      v = random_value(-0.1, 0.1);
    u1 = superpose(disc1, u1, Q, t);
    Vector<double>       Ra(u1.size()), Rb(u1.size());
    SparseMatrix<double> Ka(a.sparsity_pattern()), Kb(b.sparsity_pattern());
    a.assemble(u1, 0.6, Ra, &Ka);
    b.assemble(u1, 0.6, Rb, &Kb);
    const double Wa = a.energy(u1, 0.6), Wb = b.energy(u1, 0.6);
    Ra -= Rb;
    Ka.add(-1., Kb);
    deallog << "P1 against the corotated material: energy "
            << error_bound(std::abs(Wa - Wb) / std::abs(Wb)) << ", residual "
            << error_bound(Ra.l2_norm() / Rb.l2_norm()) << ", tangent "
            << error_bound(Ka.frobenius_norm() / Kb.frobenius_norm())
            << std::endl;
  }
}
