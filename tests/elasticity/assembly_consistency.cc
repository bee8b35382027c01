// Element level, on a distorted two-body P1 and P2 mesh with gravity and a
// traction: the assembled residual equals the finite-difference gradient of
// the total potential energy, the assembled tangent equals the
// finite-difference derivative of the residual and is symmetric, the total
// external force equals rho g V + t A, and an inverted element is reported;
// the unknowns renumbered, on the mesh as it is and on the mesh ordered by
// order_mesh_by_cuthill_mckee(), give the same residual and tangent; on a
// renumbered mesh two threads assemble the same bits as one.

#include "../distorted_box.h"
#include "../tests.h"

#include <tissue_contact/base/mesh_order.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/materials/fiber_reinforcement.h>
#include <tissue_contact/materials/mooney_rivlin.h>
#include <tissue_contact/materials/uncoupled_material.h>
#include <tissue_contact/materials/veronda.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <map>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

// the unit cube in n x n x n subcubes of tetrahedra, distorted, two bodies:
// material 1 where x > 0.5, 0 elsewhere
void
two_body_cube(Triangulation<3> &tria, const unsigned int n)
{
  distorted_box(tria, {{n, n, n}}, Point<3>(1, 1, 1), 0.2, 7, 0.5);
}

void
check(const unsigned int degree)
{
  deallog << "=== P" << degree << std::endl;
  Triangulation<3> tria;
  two_body_cube(tria, 2);
  for (const auto &cell : tria.active_cell_iterators())
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && std::abs(face->center()[0] - 1.) < 1e-10)
        face->set_boundary_id(1);

  auto fiber = std::make_shared<FunctionParser<3>>(3);
  fiber->initialize("x,y,z", "1; y; z", std::map<std::string, double>());
  const Materials::FiberReinforcement m0(
    std::make_unique<Materials::MooneyRivlin>(5., 1., 50.), 2., 3., fiber);
  const Materials::Veronda m1(7., 8., 100.);

  const Discretization  disc(tria, degree);
  Elasticity::DeadLoads loads;
  loads.gravity      = Tensor<1, 3>({0., 0., -2.});
  loads.tractions[1] = Tensor<1, 3>({0.5, 0.3, -1.});
  Elasticity::ElasticAssembler assembler(disc,
                                         {{0, {&m0, 3.}}, {1, {&m1, 1.}}},
                                         loads);

  // total external force, summed per component, against rho0 g V per body
  // (volumes from the vertices) plus t A (the face x = 1 has area 1)
  Tensor<1, 3>                total;
  const std::vector<unsigned> component = disc.dof_components();
  for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
    total[component[i]] += assembler.external_force()[i];
  double mass = 0.;
  for (const auto &cell : tria.active_cell_iterators())
    mass += (cell->material_id() == 0 ? 3. : 1.) *
            ((cell->vertex(1) - cell->vertex(0)) *
             cross_product_3d(cell->vertex(2) - cell->vertex(0),
                              cell->vertex(3) - cell->vertex(0))) /
            6.;
  const Tensor<1, 3> expected = mass * loads.gravity + loads.tractions[1];
  deallog << "total external force " << total << ", error "
          << error_bound((total - expected).norm()) << std::endl;

  Vector<double> u(disc.n_dofs());
  for (auto &v : u)
    v = random_value(-0.05, 0.05);
  const double lambda = 0.7;

  Vector<double>       R(disc.n_dofs());
  SparseMatrix<double> K(disc.sparsity_pattern);
  const bool           valid = assembler.assemble(u, lambda, R, &K);
  deallog << "valid " << valid << ", min J "
          << (assembler.min_jacobian(u) > 0.5 ? "> 0.5" : "<= 0.5")
          << ", unknowns " << disc.n_dofs() << std::endl;

  // residual vs gradient of the energy, tangent vs FD of the residual
  const FiniteDifferenceErrors e =
    finite_difference_errors(assembler, u, lambda, R, K);
  deallog << "residual vs FD gradient of the energy: relative error "
          << error_bound(e.residual) << std::endl;
  deallog << "tangent vs FD of the residual: relative error "
          << error_bound(e.tangent) << std::endl;
  deallog << "tangent asymmetry max |K - K^T| / max|K| "
          << error_bound(e.asymmetry) << std::endl;

  // the tangent added at precomputed positions (use_matrix_pattern()) is
  // the row-searched one, on a pattern widened as contact couplings widen
  // it (every fifth DoF coupled with every other)
  DynamicSparsityPattern wide(disc.n_dofs());
  for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
    for (auto e = disc.sparsity_pattern.begin(i);
         e != disc.sparsity_pattern.end(i);
         ++e)
      wide.add(i, e->column());
  for (types::global_dof_index i = 0; i < disc.n_dofs(); i += 5)
    for (types::global_dof_index j = 0; j < disc.n_dofs(); ++j)
      {
        wide.add(i, j);
        wide.add(j, i);
      }
  SparsityPattern wide_pattern;
  wide_pattern.copy_from(wide);
  SparseMatrix<double> K_searched(wide_pattern), K_positions(wide_pattern);
  assembler.assemble(u, lambda, R, &K_searched);
  assembler.use_matrix_pattern(wide_pattern);
  assembler.assemble(u, lambda, R, &K_positions);
  K_positions.add(-1., K_searched);
  deallog << "tangent at precomputed positions - searched, max |entry|: "
          << K_positions.linfty_norm() << std::endl;

  // an inverted element is reported, not assembled
  Vector<double>                       u_bad(u);
  const auto                           cell = disc.dof_handler.begin_active();
  std::vector<types::global_dof_index> dofs(disc.fe.n_dofs_per_cell());
  cell->get_dof_indices(dofs);
  for (unsigned int k = 0; k < dofs.size(); ++k)
    if (disc.fe.system_to_component_index(k).first == 0)
      u_bad[dofs[k]] = -3. * disc.support_points()[dofs[k]][0];
  deallog << "inverted element: assemble() returns "
          << assembler.assemble(u_bad, lambda, R, nullptr)
          << ", energy() = " << assembler.energy(u_bad, lambda) << std::endl;

  // the DoFs numbered point by point in Cuthill-McKee order (as the
  // constructor numbers them with DoF numbering = Cuthill-McKee), on this
  // mesh and on the mesh renumbered by order_mesh_by_cuthill_mckee() (as
  // the scene orders it with that setting): each point's DoFs at 3 g + c, a
  // narrower band, and the same residual and tangent entry by entry to
  // rounding (their sums run in another order; the traction and the
  // materials there only where the boundary and material ids were kept)
  Triangulation<3> ordered;
  ordered.copy_triangulation(tria);
  order_mesh_by_cuthill_mckee(ordered);
  unsigned int n_loaded = 0, n_loaded_ordered = 0;
  for (const auto &face : tria.active_face_iterators())
    n_loaded += face->at_boundary() && face->boundary_id() == 1;
  for (const auto &face : ordered.active_face_iterators())
    n_loaded_ordered += face->at_boundary() && face->boundary_id() == 1;
  bool         by_lowest_vertex = true;
  unsigned int previous         = 0;
  for (const auto &cell : ordered.active_cell_iterators())
    {
      unsigned int lowest = cell->vertex_index(0);
      for (const unsigned int v : cell->vertex_indices())
        lowest = std::min(lowest, cell->vertex_index(v));
      by_lowest_vertex = by_lowest_vertex && lowest >= previous;
      previous         = lowest;
    }
  deallog << "mesh ordered: cells " << tria.n_active_cells() << " -> "
          << ordered.n_active_cells() << ", vertices " << tria.n_vertices()
          << " -> " << ordered.n_vertices() << ", loaded faces " << n_loaded
          << " -> " << n_loaded_ordered << ", cells by their lowest vertex "
          << by_lowest_vertex << std::endl;

  for (Triangulation<3> *mesh : {&tria, &ordered})
    {
      Discretization renumbered(*mesh, degree);
      const bool     did = renumbered.renumber_by_points();
      const auto     X = disc.support_points(), Y = renumbered.support_points();
      const auto     component_of = renumbered.dof_components();
      std::map<std::pair<std::array<double, 3>, unsigned int>,
               types::global_dof_index>
           dof_at;
      bool grouped = true;
      for (types::global_dof_index j = 0; j < renumbered.n_dofs(); ++j)
        {
          dof_at[{{{Y[j][0], Y[j][1], Y[j][2]}}, component_of[j]}] = j;
          grouped = grouped && component_of[j] == j % 3 && Y[j] == Y[j - j % 3];
        }
      // DoF i here is DoF to[i] there: the same point and component
      std::vector<types::global_dof_index> to(disc.n_dofs());
      for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
        to[i] = dof_at.at({{{X[i][0], X[i][1], X[i][2]}}, component[i]});
      Elasticity::ElasticAssembler assembler_renumbered(
        renumbered, {{0, {&m0, 3.}}, {1, {&m1, 1.}}}, loads);
      Vector<double> u_renumbered(disc.n_dofs()), R_renumbered(disc.n_dofs());
      for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
        u_renumbered[to[i]] = u[i];
      SparseMatrix<double> K_renumbered(renumbered.sparsity_pattern);
      assembler.assemble(u, lambda, R, &K);
      assembler_renumbered.assemble(u_renumbered,
                                    lambda,
                                    R_renumbered,
                                    &K_renumbered);
      double dR = 0., dK = 0.;
      for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
        dR = std::max(dR, std::abs(R_renumbered[to[i]] - R[i]));
      for (const auto &e : K)
        dK = std::max(dK,
                      std::abs(K_renumbered.el(to[e.row()], to[e.column()]) -
                               e.value()));
      deallog << (mesh == &tria ? "renumbered by points" :
                                  "the ordered mesh renumbered by points")
              << ": " << did << ", each point's DoFs at 3 g + c: " << grouped
              << ", bandwidth " << disc.sparsity_pattern.bandwidth() << " -> "
              << renumbered.sparsity_pattern.bandwidth()
              << ", residual and tangent the same to "
              << error_bound(dR / R.linfty_norm()) << ", "
              << error_bound(dK / K.linfty_norm()) << std::endl;
    }
}


// the rows of R and K split among the threads (ElasticAssembler::
// splits_rows(), doc/theory/02-weak-form-and-linearization.md sec. 2.3):
// on a renumbered mesh, the residual and tangent on two threads are those
// on one to the last bit, at precomputed positions and searched
void
check_threads()
{
  deallog << "=== threads" << std::endl;
  Triangulation<3> tria;
  two_body_cube(tria, 10);
  // the second body's volume term at the vertices: the cells that two
  // threads both compute write its element derivatives once
  const Materials::MooneyRivlin        m0(5., 1., 50.);
  const Materials::UncoupledNeoHookean m1(7., 100., false);
  Discretization                       disc(tria, 1);
  disc.renumber_by_points();
  Elasticity::DeadLoads loads;
  loads.gravity    = Tensor<1, 3>({0., 0., -2.});
  using VolumeTerm = Elasticity::BodyData::VolumeTerm;
  Elasticity::ElasticAssembler assembler(
    disc,
    {{0, {&m0, 3.}}, {1, {&m1, 1., true, VolumeTerm::nodal_average, 100.}}},
    loads);
  Vector<double> u(disc.n_dofs());
  for (auto &v : u)
    v = random_value(-0.005, 0.005);
  for (const bool positions : {false, true})
    {
      if (positions)
        assembler.use_matrix_pattern(assembler.sparsity_pattern());
      Vector<double>       R1(disc.n_dofs()), R2(disc.n_dofs());
      SparseMatrix<double> K1(assembler.sparsity_pattern()),
        K2(assembler.sparsity_pattern());
      MultithreadInfo::set_thread_limit(1);
      const bool valid1 = assembler.assemble(u, 0.7, R1, &K1);
      MultithreadInfo::set_thread_limit(2);
      const bool split  = assembler.splits_rows();
      const bool valid2 = assembler.assemble(u, 0.7, R2, &K2);
      R2 -= R1;
      K2.add(-1., K1);
      deallog << (positions ? "at positions" : "searched") << ": valid "
              << valid1 << " " << valid2 << ", rows split among 2 threads "
              << split
              << ", residual and tangent equal to one thread's to the last bit "
              << (R2.linfty_norm() == 0. && K2.linfty_norm() == 0.)
              << std::endl;
    }
  MultithreadInfo::set_thread_limit(1);
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  check(1);
  check(2);
  check_threads();
}
