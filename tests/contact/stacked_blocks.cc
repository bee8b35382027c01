// Two stacked blocks with non-matching meshes (meshes/stacked_blocks.geo),
// the lower one clamped at its bottom, the upper one pressed down by a
// traction p on its top (which is held in x and y), in contact through
// both directions (upper triangles against lower tetrahedra and vice
// versa). For penalty factors 1e3 and 1e4: the contact force carried from
// the upper to the lower block equals the load, and the penetration falls
// as 1/eps (two directions, each with pressure eps d: p = 2 eps d).
// The contact patch test: the pressure field. With the area-integrated
// penalty the pressure at a point of a contact surface is eps times its
// depth inside the other body, per direction; the two flat surfaces overlap
// by the same depth, so the pressure at a contact vertex is p_h = 2 eps d.
// Printed: p_h / p over all contact vertices of both surfaces, and over
// those at least 0.15 from the blocks' sides (the rim of a free-sided
// patch carries a boundary layer). The same from the run's results
// (StepResults, what the output files hold): each pair's force on its
// surface body and contact area (the overlap, 1 x 1, widened by the
// bulge); the upper block receives pair 0's force and the reaction to pair
// 1's, which together carry the load; the traction integrated over all
// contact vertices is the sum of the pairs' forces; and the contact
// pressure field p_a = -t_a.n_a: with both directions declared each
// surface's triangles carry their own direction's share, so p_a is about
// p / 2 on each surface (printed as 2 p_a / p).

#include "../tests.h"

#include <tissue_contact/simulation/static_simulation.h>
#include <tissue_contact/simulation/step_results.h>

#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  std::string
  scene(const std::string &eps)
  {
    return std::string(R"(
subsection Mesh
  set Source = file
  set File   = )") +
           SOURCE_DIR + R"(/stacked_blocks.msh
end
subsection Bodies
  set Number of bodies = 2
  subsection Body 0
    set Material id = 1
    set Mu          = 100
    set Lambda      = 100
  end
  subsection Body 1
    set Material id = 2
    set Mu          = 100
    set Lambda      = 100
  end
end
subsection Boundary conditions
  set Number of Dirichlet conditions = 2
  set Number of tractions = 1
  subsection Dirichlet 0
    set Boundary id = 1
  end
  subsection Dirichlet 1
    set Boundary id = 2
    set Components  = xy
  end
  subsection Traction 0
    set Boundary id = 2
    set Traction    = 0, 0, -10
  end
end
subsection Contact
  set Contact surfaces = 3, 4
  set Number of pairs  = 2
  subsection Pair 0
    set Surface body   = 2
    set Volume body    = 1
    set Penalty factor = )" +
           eps + R"(
  end
  subsection Pair 1
    set Surface body   = 1
    set Volume body    = 2
    set Penalty factor = )" +
           eps + R"(
  end
end
subsection Newton
  set Quasi-viscosity = true
  set Maximum line search halvings = 25
end
subsection Output
  set Write VTU    = false
  set Print timing = false
  set Directory    = .
end
)";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double load = 10.;
  for (const std::string eps : {"1e3", "1e4"})
    {
      std::ostringstream log;
      StaticSimulation   sim(Scene::SceneParameters::from_string(scene(eps)),
                           log);
      const auto         stats = sim.run();
      const auto        &u     = sim.solution();
      const auto        *c     = sim.problem().contact_assembler();

      // contact force on the upper block: -dW/du summed over its DoFs
      Vector<double> R(u.size());
      c->assemble(u, R, nullptr);
      const auto       &disc      = sim.problem().discretization();
      const auto        component = disc.dof_components();
      std::vector<bool> upper(u.size(), false);
      std::vector<types::global_dof_index> dofs(disc.fe.n_dofs_per_cell());
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        if (cell->material_id() == 2)
          {
            cell->get_dof_indices(dofs);
            for (const auto i : dofs)
              upper[i] = true;
          }
      Tensor<1, 3> F;
      for (types::global_dof_index i = 0; i < u.size(); ++i)
        if (upper[i])
          F[component[i]] -= R[i];
      const double d = c->max_body_penetration(u);
      deallog << "eps = " << eps << ": contact force on the upper block / load "
              << std::setprecision(4) << F[2] / load << std::setprecision(6)
              << ", max penetration " << std::setprecision(3) << d
              << ", eps * penetration / p " << std::stod(eps) * d / load
              << std::setprecision(6) << ", Newton iterations "
              << stats.newton_iterations << std::endl;

      const auto &vertices =
        disc.dof_handler.get_triangulation().get_vertices();
      for (const bool interior : {false, true})
        {
          double       sum = 0., lo = 1e300, hi = 0.;
          unsigned int n = 0;
          for (const auto &[v, depth] : c->body_penetrations(u))
            {
              const Point<3> &X = vertices[v];
              if (interior && (std::min(X[0], 1. - X[0]) < 0.15 ||
                               std::min(X[1], 1. - X[1]) < 0.15))
                continue;
              const double ratio = 2. * std::stod(eps) * depth / load;
              sum += ratio;
              lo = std::min(lo, ratio);
              hi = std::max(hi, ratio);
              ++n;
            }
          deallog << "  pressure 2 eps d / p at " << n
                  << (interior ? " interior" : "") << " contact vertices: mean "
                  << std::setprecision(3) << sum / n << ", min " << lo
                  << ", max " << hi << std::setprecision(6) << std::endl;
        }

      // the run's results: forces, areas and the pressure field
      const StepResults r(sim.problem(), u, 1.);
      const auto       &pairs = r.contact.interactions;
      Tensor<1, 3>      T;
      for (unsigned int v = 0; v < vertices.size(); ++v)
        T += r.contact.traction[v] * r.contact.area[v];
      deallog
        << "  pair forces on their surface bodies z / load "
        << std::setprecision(4) << pairs[0].force[2] / load << " and "
        << pairs[1].force[2] / load << ", upper block's share "
        << (pairs[0].force[2] - pairs[1].force[2]) / load << ", areas "
        << pairs[0].area << " and " << pairs[1].area << std::setprecision(6)
        << "; traction integrated - sum of the pair forces "
        << error_bound((T - pairs[0].force - pairs[1].force).norm() / load, -12)
        << std::endl;
      for (const bool interior : {false, true})
        {
          double       sum = 0., lo = 1e300, hi = -1e300;
          unsigned int n = 0;
          for (unsigned int v = 0; v < vertices.size(); ++v)
            {
              if (r.contact.area[v] == 0.)
                continue;
              const Point<3> &X = vertices[v];
              if (interior && (std::min(X[0], 1. - X[0]) < 0.15 ||
                               std::min(X[1], 1. - X[1]) < 0.15))
                continue;
              const double ratio = 2. * r.contact.pressure[v] / load;
              sum += ratio;
              lo = std::min(lo, ratio);
              hi = std::max(hi, ratio);
              ++n;
            }
          deallog << "  2 contact_pressure / p at " << n
                  << (interior ? " interior" : "") << " surface vertices: mean "
                  << std::setprecision(3) << sum / n << ", min " << lo
                  << ", max " << hi << std::setprecision(6) << std::endl;
        }
    }
}
