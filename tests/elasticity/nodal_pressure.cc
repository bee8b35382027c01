// The volume term at the vertices (doc/theory/08-nodal-pressure.md): on a
// distorted P1 mesh of two bodies (fiber-reinforced uncoupled Mooney-Rivlin
// and uncoupled neo-Hookean, different bulk moduli) sharing a face, at a
// random displacement, the residual equals the finite-difference gradient of
// the energy (N1), the tangent (N3)-(N5) the finite-difference derivative of
// the residual, and is symmetric; the residual vanishes at rest; under a
// uniform dilation (every J_a = J_e) the energy equals the pointwise
// formulation's; the widened sparsity pattern is counted; P2 is refused.
// The element's mean dilatation (doc/theory/09-mean-dilatation.md) on the
// same mesh in P2: residual = FD gradient of (D1), tangent (D3)-(D4) = FD of
// the residual, symmetric, zero at rest, the pointwise energy under a uniform
// dilation; on P1 it is the pointwise formulation (J is constant).

#include "../distorted_box.h"
#include "../tests.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/materials/fiber_reinforcement.h>
#include <tissue_contact/materials/uncoupled_material.h>

#include <deal.II/base/function_parser.h>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  Triangulation<3> tria;
  distorted_box(tria, {{2, 2, 2}}, Point<3>(1, 1, 1), 0.2, 7, 0.5);

  auto fiber = std::make_shared<FunctionParser<3>>(3);
  fiber->initialize("x,y,z", "1; y; z", std::map<std::string, double>());
  const double kappa0 = 60., kappa1 = 150.;
  // the materials without their volume term, which goes to the vertices,
  // and the same materials with it at the points
  const Materials::FiberReinforcement m0(
    std::make_unique<Materials::UncoupledMooneyRivlin>(5., 1., kappa0, false),
    2.,
    3.,
    fiber);
  const Materials::UncoupledNeoHookean m1(7., kappa1, false);
  const Materials::FiberReinforcement  p0(
    std::make_unique<Materials::UncoupledMooneyRivlin>(5., 1., kappa0),
    2.,
    3.,
    fiber);
  const Materials::UncoupledNeoHookean p1(7., kappa1);

  const Discretization  disc(tria, 1);
  Elasticity::DeadLoads loads;
  loads.gravity    = Tensor<1, 3>({0., 0., -2.});
  using VolumeTerm = Elasticity::BodyData::VolumeTerm;
  const std::map<types::material_id, Elasticity::BodyData> nodal_bodies = {
    {0, {&m0, 3., true, VolumeTerm::nodal_average, kappa0}},
    {1, {&m1, 1., true, VolumeTerm::nodal_average, kappa1}}};
  const std::map<types::material_id, Elasticity::BodyData> element_bodies = {
    {0, {&m0, 3., true, VolumeTerm::element_average, kappa0}},
    {1, {&m1, 1., true, VolumeTerm::element_average, kappa1}}};
  const std::map<types::material_id, Elasticity::BodyData> pointwise_bodies = {
    {0, {&p0, 3.}}, {1, {&p1, 1.}}};
  Elasticity::ElasticAssembler assembler(disc, nodal_bodies, loads);
  Elasticity::ElasticAssembler pointwise(disc, pointwise_bodies, loads);
  const SparsityPattern       &pattern = assembler.sparsity_pattern();
  deallog << "unknowns " << disc.n_dofs() << ", stiffness entries: "
          << disc.sparsity_pattern.n_nonzero_elements()
          << " element couplings, " << pattern.n_nonzero_elements()
          << " with the vertex couplings" << std::endl;

  // at rest
  Vector<double>       u(disc.n_dofs()), R(disc.n_dofs());
  SparseMatrix<double> K(pattern);
  assembler.assemble(u, 0., R, &K);
  deallog << "at rest: |R| " << error_bound(R.l2_norm()) << std::endl;

  // uniform dilation x = 1.1 X: J_a = J_e = 1.331 everywhere
  const std::vector<Point<3>> X         = disc.support_points();
  const std::vector<unsigned> component = disc.dof_components();
  for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
    u[i] = 0.1 * X[i][component[i]];
  const double W_nodal = assembler.energy(u, 0.),
               W_point = pointwise.energy(u, 0.);
  deallog << "uniform dilation: energy " << W_nodal
          << ", pointwise formulation's " << W_point << ", relative difference "
          << error_bound(std::abs(W_nodal - W_point) / W_point) << std::endl;

  for (auto &v : u)
    v = random_value(-0.05, 0.05);
  const double lambda = 0.7;
  const bool   valid  = assembler.assemble(u, lambda, R, &K);
  deallog << "random displacement: valid " << valid << std::endl;

  const FiniteDifferenceErrors e =
    finite_difference_errors(assembler, u, lambda, R, K);
  deallog << "residual vs FD gradient of the energy: relative error "
          << error_bound(e.residual, -8) << std::endl;
  deallog << "tangent vs FD of the residual: relative error "
          << error_bound(e.tangent, -8) << std::endl;
  deallog << "tangent asymmetry max |K - K^T| / max|K| "
          << error_bound(e.asymmetry) << std::endl;

  // on P1 the mean dilatation is the pointwise volume term
  {
    Elasticity::ElasticAssembler element(disc, element_bodies, loads);
    Vector<double>               R_point(disc.n_dofs()), R_element(R_point);
    pointwise.assemble(u, lambda, R_point, nullptr);
    element.assemble(u, lambda, R_element, nullptr);
    const double W_point = pointwise.energy(u, lambda);
    R_element -= R_point;
    deallog << "P1, element average against pointwise: energy "
            << error_bound(std::abs(element.energy(u, lambda) - W_point) /
                           std::abs(W_point))
            << ", residual " << error_bound(R_element.l2_norm() / R.l2_norm())
            << std::endl;
  }

  // P2 with the nodal average is refused by name
  const Discretization disc2(tria, 2);
  try
    {
      Elasticity::ElasticAssembler a2(disc2, nodal_bodies, loads);
      deallog << "P2 accepted (wrong)" << std::endl;
    }
  catch (const std::exception &e)
    {
      deallog << "P2: " << error_message(e) << std::endl;
    }

  // P2 with the element's mean dilatation
  Elasticity::ElasticAssembler element(disc2, element_bodies, loads);
  Elasticity::ElasticAssembler point2(disc2, pointwise_bodies, loads);
  Vector<double>               u2(disc2.n_dofs()), R2(disc2.n_dofs());
  SparseMatrix<double>         K2(element.sparsity_pattern());
  element.assemble(u2, 0., R2, &K2);
  deallog << "P2, element average: unknowns " << disc2.n_dofs()
          << ", at rest |R| " << error_bound(R2.l2_norm()) << std::endl;
  const std::vector<Point<3>> X2         = disc2.support_points();
  const std::vector<unsigned> component2 = disc2.dof_components();
  for (types::global_dof_index i = 0; i < disc2.n_dofs(); ++i)
    u2[i] = 0.1 * X2[i][component2[i]];
  deallog << "P2, element average: uniform dilation, relative difference to "
             "pointwise "
          << error_bound(
               std::abs(element.energy(u2, 0.) - point2.energy(u2, 0.)) /
               point2.energy(u2, 0.))
          << std::endl;
  for (auto &v : u2)
    v = random_value(-0.05, 0.05);
  deallog << "P2, element average: random displacement valid "
          << element.assemble(u2, lambda, R2, &K2) << std::endl;
  const FiniteDifferenceErrors e2 =
    finite_difference_errors(element, u2, lambda, R2, K2);
  deallog << "P2, element average: residual vs FD gradient of the energy "
          << error_bound(e2.residual, -8) << ", tangent vs FD of the residual "
          << error_bound(e2.tangent, -8) << ", asymmetry "
          << error_bound(e2.asymmetry) << std::endl;
}
