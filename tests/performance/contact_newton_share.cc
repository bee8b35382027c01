// Benchmark (not a test): the share of contact in one Newton iteration of
// the contact patch scene (prm/stacked_blocks.prm: two blocks with
// non-matching meshes pressed together) at three mesh sizes, at the
// converged state: residual + tangent assembly (elasticity and contact),
// the contact part alone, the sparsity check of the contact couplings, and
// one linear solve (direct; GMRES + AMG to 1e-8).
//
//   cmake --build build --target performance
//   build/tests/performance/contact_newton_share
//
// Needs gmsh on the PATH (the meshes are generated from
// meshes/stacked_blocks.geo into the system's temporary folder).

#include <tissue_contact/simulation/static_simulation.h>

#include <deal.II/base/timer.h>
#include <deal.II/numerics/matrix_tools.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace TissueContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  const std::string                source(SOURCE_DIR "/../..");
  std::ifstream                    in(source + "/prm/stacked_blocks.prm");
  std::stringstream                text;
  text << in.rdbuf();

  std::cout << "One Newton iteration of prm/stacked_blocks.prm at its "
               "solution, "
            << MultithreadInfo::n_threads() << " thread(s); times in ms\n\n"
            << std::left << std::setw(9) << "tets" << std::setw(9) << "dofs"
            << std::setw(11) << "assembly" << std::setw(10) << "contact"
            << std::setw(10) << "pattern" << std::setw(10) << "direct"
            << std::setw(10) << "AMG" << std::setw(16) << "contact share"
            << "\n";
  for (const double scale : {1., 0.5, 0.3})
    {
      const std::string mesh =
        (std::filesystem::temp_directory_path() /
         ("tissue_contact_stacked_" + std::to_string(scale) + ".msh"))
          .string();
      std::ostringstream cmd;
      cmd << "gmsh -3 -format msh2 -setnumber lower " << 0.34 * scale
          << " -setnumber upper " << 0.26 * scale << " " << source
          << "/meshes/stacked_blocks.geo -o " << mesh << " > /dev/null";
      AssertThrow(std::system(cmd.str().c_str()) == 0,
                  ExcMessage("gmsh failed: " + cmd.str()));
      std::string prm = text.str();
      prm.replace(prm.find("../meshes/stacked_blocks.msh"),
                  std::string("../meshes/stacked_blocks.msh").size(),
                  mesh);
      prm += "\nsubsection Output\n  set Write VTU = false\n  set Print "
             "timing = false\nend\n";
      std::ostringstream log;
      StaticSimulation   sim(Scene::SceneParameters::from_string(prm), log);
      sim.solve_quietly();
      const Vector<double> &u = sim.solution();
      const auto            n = sim.problem().n_dofs();

      SparseMatrix<double> K(sim.problem().sparsity_pattern());
      Vector<double>       R(n), Rc(n), du(n);
      Timer                timer;
      const unsigned int   repeat = 3;
      for (unsigned int r = 0; r < repeat; ++r)
        sim.problem().assemble(u, 1., R, &K);
      const double t_assembly = timer.wall_time() / repeat;
      timer.restart();
      for (unsigned int r = 0; r < repeat; ++r)
        sim.problem().contact_assembler()->assemble(u, Rc, &K);
      const double t_contact = timer.wall_time() / repeat;
      timer.restart();
      sim.problem().contact_assembler()->has_couplings(
        u, sim.problem().sparsity_pattern());
      const double t_pattern = timer.wall_time();

      sim.problem().assemble(u, 1., R, &K);
      std::map<types::global_dof_index, double> zero;
      for (const auto &t : sim.problem().prescribed_values(1.))
        zero[t.first] = 0.;
      Vector<double> rhs(R);
      rhs *= -1.;
      MatrixTools::apply_boundary_values(zero, K, du, rhs, true);
      double t_solve[2];
      for (const unsigned int s : {0u, 1u})
        {
          Solvers::LinearSolver::Parameters lp;
          lp.type               = s == 0 ? "direct" : "GMRES+AMG";
          lp.relative_tolerance = 1e-8;
          const Solvers::LinearSolver solver(lp,
                                             sim.problem().near_null_space());
          du = 0.;
          timer.restart();
          solver.solve(K, du, rhs);
          t_solve[s] = timer.wall_time();
        }
      const auto n_tets = sim.problem()
                            .discretization()
                            .dof_handler.get_triangulation()
                            .n_active_cells();
      std::ostringstream share;
      share << std::fixed << std::setprecision(0)
            << 100. * t_contact / (t_assembly + t_solve[0]) << " % / "
            << 100. * t_contact / (t_assembly + t_solve[1]) << " %";
      std::cout << std::setw(9) << n_tets << std::setw(9) << n << std::fixed
                << std::setprecision(1) << std::setw(11) << 1e3 * t_assembly
                << std::setw(10) << 1e3 * t_contact << std::setw(10)
                << 1e3 * t_pattern << std::setw(10) << 1e3 * t_solve[0]
                << std::setw(10) << 1e3 * t_solve[1] << std::setw(16)
                << share.str() << std::defaultfloat << "\n";
      std::filesystem::remove(mesh);
    }
  std::cout << "\ncontact share: contact assembly / (assembly + linear "
               "solve), direct / AMG\n";
}
