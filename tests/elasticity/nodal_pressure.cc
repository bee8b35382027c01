// The volume term at the vertices (doc/theory/08-nodal-pressure.md): on a
// distorted P1 mesh of two bodies (fiber-reinforced uncoupled Mooney-Rivlin
// and uncoupled neo-Hookean, different bulk moduli) sharing a face, at a
// random displacement, the residual equals the finite-difference gradient of
// the energy (N1), the tangent (N3)-(N5) the finite-difference derivative of
// the residual, and is symmetric; the residual vanishes at rest; under a
// uniform dilation (every J_a = J_e) the energy equals the pointwise
// formulation's; the widened sparsity pattern is counted; P2 is refused.

#include "../tests.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/materials/fiber_reinforcement.h>
#include <tissue_contact/materials/uncoupled_material.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  Triangulation<3> tria;
  GridGenerator::subdivided_hyper_rectangle_with_simplices(tria,
                                                           {2, 2, 2},
                                                           Point<3>(0, 0, 0),
                                                           Point<3>(1, 1, 1));
  GridTools::distort_random(0.2, tria, true, 7);
  for (const auto &cell : tria.active_cell_iterators())
    cell->set_material_id(cell->center()[0] > 0.5 ? 1 : 0);

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
  loads.gravity = Tensor<1, 3>({0., 0., -2.});
  Elasticity::ElasticAssembler assembler(
    disc, {{0, {&m0, 3., true, kappa0}}, {1, {&m1, 1., true, kappa1}}}, loads);
  Elasticity::ElasticAssembler pointwise(disc,
                                         {{0, {&p0, 3.}}, {1, {&p1, 1.}}},
                                         loads);
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

  // P2 is refused by name
  try
    {
      const Discretization         disc2(tria, 2);
      Elasticity::ElasticAssembler a2(disc2,
                                      {{0, {&m0, 3., true, kappa0}},
                                       {1, {&m1, 1., true, kappa1}}},
                                      loads);
      deallog << "P2 accepted (wrong)" << std::endl;
    }
  catch (const std::exception &e)
    {
      deallog << "P2: " << error_message(e) << std::endl;
    }
}
