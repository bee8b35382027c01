// Benchmark (not a test): residual + tangent assembly throughput in
// tetrahedra per second for P1 and P2, every material and three mesh sizes,
// on one thread and on all threads; then the time split of one Newton
// iteration (assembly / linear solve) for each linear solver.
//
//   cmake --build build --target performance
//   build/tests/performance/assembly_throughput [--quick]

#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/materials/corotated.h>
#include <tissue_contact/materials/fiber_reinforcement.h>
#include <tissue_contact/materials/linear_elastic.h>
#include <tissue_contact/materials/mooney_rivlin.h>
#include <tissue_contact/materials/neo_hookean.h>
#include <tissue_contact/materials/saint_venant_kirchhoff.h>
#include <tissue_contact/materials/veronda.h>
#include <tissue_contact/solvers/linear_solver.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/matrix_tools.h>

#include <iomanip>
#include <iostream>
#include <memory>

using namespace dealii;
using namespace TissueContact;

namespace
{
  std::vector<std::unique_ptr<Materials::Material>>
  all_materials()
  {
    auto fiber = std::make_shared<FunctionParser<3>>(3);
    fiber->initialize("x,y,z", "1; 0; 0", std::map<std::string, double>());
    std::vector<std::unique_ptr<Materials::Material>> m;
    m.push_back(std::make_unique<Materials::LinearElastic>(3., 5.));
    m.push_back(std::make_unique<Materials::Corotated>(3., 5.));
    m.push_back(std::make_unique<Materials::SaintVenantKirchhoff>(3., 5.));
    m.push_back(std::make_unique<Materials::NeoHookean>(3., 5.));
    m.push_back(std::make_unique<Materials::MooneyRivlin>(5., 1., 50.));
    m.push_back(std::make_unique<Materials::Veronda>(7., 8., 100.));
    m.push_back(std::make_unique<Materials::FiberReinforcement>(
      std::make_unique<Materials::MooneyRivlin>(5., 1., 50.), 2., 3., fiber));
    return m;
  }

  // A smooth displacement with J > 0 (so every material is evaluated).
  Vector<double>
  some_displacement(const Discretization &disc)
  {
    const auto     X         = disc.support_points();
    const auto     component = disc.dof_components();
    Vector<double> u(disc.n_dofs());
    for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
      u[i] =
        0.05 * std::sin(3. * X[i][0] + component[i]) * std::cos(2. * X[i][1]) +
        0.02 * X[i][2];
    return u;
  }

  // Seconds per residual + tangent assembly (best of a few repetitions), the
  // tangent added at precomputed positions as a run's Problem has it added
  // (use_matrix_pattern()).
  double
  time_assembly(Elasticity::ElasticAssembler &assembler,
                const Discretization         &disc,
                const Vector<double>         &u)
  {
    Vector<double>       R(disc.n_dofs());
    SparseMatrix<double> K(disc.sparsity_pattern);
    assembler.use_matrix_pattern(disc.sparsity_pattern);
    double best = 1e300;
    for (unsigned int r = 0; r < 3; ++r)
      {
        Timer timer;
        assembler.assemble(u, 1., R, &K);
        timer.stop();
        best = std::min(best, timer.wall_time());
      }
    return best;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc,
                                       argv,
                                       numbers::invalid_unsigned_int);
  const bool         quick     = argc > 1 && std::string(argv[1]) == "--quick";
  const unsigned int n_threads = MultithreadInfo::n_threads();
  const auto         materials = all_materials();

  std::cout << "Residual + tangent assembly throughput, in 1e6 tetrahedra "
               "per second (best of 3)\n"
            << "threads: 1 and " << n_threads << "\n\n"
            << std::left << std::setw(4) << "P" << std::setw(10) << "tets"
            << std::setw(10) << "dofs" << std::setw(26) << "material"
            << std::setw(12) << "1 thread" << std::setw(12)
            << (std::to_string(n_threads) + " threads") << "\n";

  for (const unsigned int degree : {1u, 2u})
    {
      const std::vector<unsigned int> sizes =
        quick       ? std::vector<unsigned int>{6} :
        degree == 1 ? std::vector<unsigned int>{8, 16, 28} :
                      std::vector<unsigned int>{6, 10, 16};
      for (const unsigned int n : sizes)
        {
          Triangulation<3> tria;
          GridGenerator::subdivided_hyper_rectangle_with_simplices(
            tria, {n, n, n}, Point<3>(0, 0, 0), Point<3>(1, 1, 1));
          const Discretization disc(tria, degree);
          // one row: the throughput of @p body on @p d, 1 and n threads
          const auto row = [&](const Discretization       &d,
                               const Elasticity::BodyData &body,
                               const std::string          &name) {
            Elasticity::ElasticAssembler assembler(d,
                                                   {{0, body}},
                                                   Elasticity::DeadLoads());
            const Vector<double>         u = some_displacement(d);
            MultithreadInfo::set_thread_limit(1);
            const double t1 = time_assembly(assembler, d, u);
            MultithreadInfo::set_thread_limit(n_threads);
            const double tn = time_assembly(assembler, d, u);
            std::cout << std::setw(4) << degree << std::setw(10)
                      << tria.n_active_cells() << std::setw(10) << d.n_dofs()
                      << std::setw(26) << name << std::fixed
                      << std::setprecision(3) << std::setw(12)
                      << tria.n_active_cells() / t1 / 1e6 << std::setw(12)
                      << tria.n_active_cells() / tn / 1e6 << std::defaultfloat
                      << "\n";
          };
          // every material, and the corotated one again with one rotation
          // per element (Rotation = element, doc/theory/10)
          for (const auto &m : materials)
            {
              row(disc, {m.get(), 1.}, m->name());
              if (m->name() == "corotated")
                {
                  Elasticity::BodyData body{m.get(), 1.};
                  body.single_rotation = true;
                  row(disc, body, "corotated, 1 rotation");
                }
            }
          if (degree == 2)
            {
              // P2 with the reduced stiffness quadrature (6 points)
              const Discretization          reduced(tria, 2, true);
              const Materials::MooneyRivlin mr(5., 1., 50.);
              row(reduced, {&mr, 1.}, "Mooney-Rivlin, 6 points");
            }
        }
    }

  // One Newton iteration of a clamped cube under a body load.
  std::cout << "\nOne Newton iteration (Mooney-Rivlin cube, bottom clamped): "
               "seconds, "
            << n_threads << " threads\n"
            << std::setw(4) << "P" << std::setw(10) << "dofs" << std::setw(16)
            << "solver" << std::setw(10) << "rel.tol" << std::setw(12)
            << "assembly" << std::setw(12) << "solve" << std::setw(10)
            << "lin.its"
            << "\n";
  const Materials::MooneyRivlin mr(5., 1., 50.);
  for (const auto &[degree, n] :
       std::vector<std::pair<unsigned, unsigned>>{{1, quick ? 6u : 20u},
                                                  {2, quick ? 4u : 10u}})
    {
      Triangulation<3> tria;
      GridGenerator::subdivided_hyper_rectangle_with_simplices(
        tria, {n, n, n}, Point<3>(0, 0, 0), Point<3>(1, 1, 1));
      const Discretization  disc(tria, degree);
      Elasticity::DeadLoads loads;
      loads.gravity = Tensor<1, 3>({0., 0., -1.});
      const Elasticity::ElasticAssembler        assembler(disc,
                                                   {{0, {&mr, 1.}}},
                                                   loads);
      std::map<types::global_dof_index, double> clamp;
      const auto                                X = disc.support_points();
      for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
        if (X[i][2] < 1e-12)
          clamp[i] = 0.;
      // "GMRES+AMG6": AMG with the six rigid-body modes (AMG rotations)
      for (const auto &[type, tolerance] :
           std::vector<std::pair<std::string, double>>{{"direct", 0.},
                                                       {"MUMPS", 0.},
                                                       {"Cholesky", 0.},
                                                       {"GMRES+Jacobi", 0.1},
                                                       {"GMRES+AMG", 0.1},
                                                       {"GMRES+AMG6", 0.1},
                                                       {"GMRES+Jacobi", 1e-8},
                                                       {"GMRES+AMG", 1e-8},
                                                       {"GMRES+AMG6", 1e-8}})
        {
          Solvers::LinearSolver::Parameters p;
          p.type = type == "MUMPS" || type == "Cholesky" ? "direct" :
                   type == "GMRES+AMG6"                  ? "GMRES+AMG" :
                                                           type;
          p.direct_solver =
            type == "MUMPS" || type == "Cholesky" ? type : "UMFPACK";
          p.amg_rotations      = type == "GMRES+AMG6";
          p.relative_tolerance = tolerance;
          p.max_iterations     = 5000;
          const Solvers::LinearSolver solver(p, disc.rigid_body_modes());
          Vector<double> u(disc.n_dofs()), R(disc.n_dofs()), du(disc.n_dofs());
          SparseMatrix<double> K(disc.sparsity_pattern);
          Timer                timer;
          assembler.assemble(u, 1., R, &K);
          const double t_assembly = timer.wall_time();
          R *= -1.;
          MatrixTools::apply_boundary_values(clamp, K, du, R);
          timer.restart();
          const unsigned int its     = solver.solve(K, du, R);
          const double       t_solve = timer.wall_time();
          std::cout << std::setw(4) << degree << std::setw(10) << disc.n_dofs()
                    << std::setw(16) << type << std::setw(10)
                    << (tolerance > 0. ?
                          (tolerance < 1e-3 ? std::string("1e-8") :
                                              std::string("0.1")) :
                          std::string("-"))
                    << std::fixed << std::setprecision(3) << std::setw(12)
                    << t_assembly << std::setw(12) << t_solve
                    << std::defaultfloat << std::setw(10) << its << "\n";
        }
    }
}
