// Shared by the dynamics tests: the scenes, and the clamped bar's lowest
// mode (inverse iteration with the consistent mass) and largest lumped
// frequency (power iteration on M_L^-1 K).
#pragma once

#include <tissue_contact/dynamics/mass_matrix.h>
#include <tissue_contact/simulation/problem.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/matrix_tools.h>

#include <sstream>

namespace DynamicsTestScenes
{
  using namespace dealii;
  using namespace TissueContact;

  /** A clamped linear elastic bar [0,1] x [0,0.2]^2, P1, density 1. */
  inline const char *bar = R"(
subsection Mesh
  set Source           = box
  set Box lower corner = 0, 0, 0
  set Box upper corner = 1, 0.2, 0.2
  set Box subdivisions = 10, 2, 2
end
subsection Bodies
  subsection Body 0
    set Model   = linear
    set Mu      = 1
    set Lambda  = 1
    set Density = 1
  end
end
subsection Boundary conditions
  set Number of Dirichlet conditions = 1
  subsection Dirichlet 0
    set Boundary id = 0
  end
end
subsection Output
  set Write VTU    = false
  set Print timing = false
  set Directory    = .
end
)";

  /** A neo-Hookean cube of side 0.2 above the plane z = 0, gravity 10,
   * contact on its bottom face (eps = 1e3). */
  inline const char *falling_block = R"(
subsection Mesh
  set Source           = box
  set Box lower corner = 0, 0, 0.1
  set Box upper corner = 0.2, 0.2, 0.3
  set Box subdivisions = 2, 2, 2
end
subsection Bodies
  subsection Body 0
    set Model   = neo-Hookean
    set Mu      = 100
    set Lambda  = 100
    set Density = 1
  end
end
subsection Boundary conditions
  set Number of Dirichlet conditions = 0
end
subsection Loads
  set Gravity = 0, 0, -10
end
subsection Contact
  set Contact surfaces    = 4
  set Number of obstacles = 1
  subsection Obstacle 0
    set Type           = plane
    set Point          = 0, 0, 0
    set Normal         = 0, 0, 1
    set Penalty factor = 1e3
  end
end
subsection Output
  set Write VTU    = false
  set Print timing = false
  set Directory    = .
end
)";

  /** The bar as an oscillator: its mass matrices, lowest mode phi (max
   * norm 1) with frequency omega and period T, and the largest frequency
   * of the lumped system. */
  struct BarOscillator
  {
    std::ostringstream      log;
    Problem                 sim;
    types::global_dof_index n;
    SparseMatrix<double>    M;
    Vector<double>          M_lumped, phi;
    double                  phi_M_phi = 0., omega = 0., T = 0., omega_max = 0.;

    BarOscillator()
      : sim(Scene::SceneParameters::from_string(bar))
      , n(sim.n_dofs())
      , M(sim.discretization().sparsity_pattern)
    {
      const auto &disc   = sim.discretization();
      const auto  bodies = sim.get_scene().body_data();
      Dynamics::assemble_consistent_mass(disc, bodies, M);
      M_lumped = Dynamics::lumped_mass(disc, bodies);

      // K with the clamped DoFs eliminated (identity rows and columns)
      SparseMatrix<double> K(sim.sparsity_pattern());
      Vector<double>       zero_u(n), R(n);
      sim.assemble(zero_u, 1., R, &K);
      std::map<types::global_dof_index, double> clamped;
      for (const auto &t : sim.prescribed_values(1.))
        clamped[t.first] = 0.;
      SparseMatrix<double> K_free(sim.sparsity_pattern());
      K_free.copy_from(K);
      {
        Vector<double> x(n), b(n);
        MatrixTools::apply_boundary_values(clamped, K_free, x, b, true);
      }
      const auto zero_clamped = [&](Vector<double> &x) {
        for (const auto &t : clamped)
          x[t.first] = 0.;
      };

      // lowest mode by inverse iteration
      SparseDirectUMFPACK K_inverse;
      K_inverse.initialize(K_free);
      Vector<double> tmp(n);
      phi.reinit(n);
      phi = 1.;
      zero_clamped(phi);
      for (unsigned int it = 0; it < 60; ++it)
        {
          M.vmult(tmp, phi);
          zero_clamped(tmp);
          K_inverse.vmult(phi, tmp);
          phi /= phi.linfty_norm();
        }
      M.vmult(tmp, phi);
      phi_M_phi = phi * tmp;
      K.vmult(tmp, phi);
      omega = std::sqrt((phi * tmp) / phi_M_phi);
      T     = 2. * numbers::PI / omega;

      // largest frequency of the lumped system by power iteration
      Vector<double> w(n);
      for (types::global_dof_index i = 0; i < n; ++i)
        w[i] = std::sin(1. + i);
      zero_clamped(w);
      for (unsigned int it = 0; it < 400; ++it)
        {
          K_free.vmult(tmp, w);
          zero_clamped(tmp);
          for (types::global_dof_index i = 0; i < n; ++i)
            tmp[i] /= M_lumped[i];
          omega_max = std::sqrt(tmp.l2_norm() / w.l2_norm());
          w         = tmp;
          w /= w.l2_norm();
        }
    }

    /** The modal coordinate of @p u: phi^T M u / phi^T M phi. */
    double
    modal(const Vector<double> &u) const
    {
      Vector<double> Mu(n);
      M.vmult(Mu, u);
      return (phi * Mu) / phi_M_phi;
    }
  };

  /** The falling block with its consistent mass and its mean height
   * (z displacement of the centre of mass). */
  struct FallingBlock
  {
    std::ostringstream      log;
    Problem                 sim;
    types::global_dof_index n;
    SparseMatrix<double>    M;
    Vector<double>          ez;
    double                  mass = 0.;

    FallingBlock()
      : sim(Scene::SceneParameters::from_string(falling_block))
      , n(sim.n_dofs())
      , M(sim.discretization().sparsity_pattern)
      , ez(n)
    {
      Dynamics::assemble_consistent_mass(sim.discretization(),
                                         sim.get_scene().body_data(),
                                         M);
      const auto component = sim.discretization().dof_components();
      for (types::global_dof_index i = 0; i < n; ++i)
        ez[i] = component[i] == 2 ? 1. : 0.;
      Vector<double> Mu(n);
      M.vmult(Mu, ez);
      mass = ez * Mu;
    }

    double
    mean_height(const Vector<double> &u) const
    {
      Vector<double> Mu(n);
      M.vmult(Mu, u);
      return (ez * Mu) / mass;
    }
  };

  /** The rods of prm/falling_rods.prm (radius 0.06, length 1 along
   * n = (1, 0, 1)/sqrt(2) from the slope): the DoFs of each rod's tip face
   * (support points at distance 1 from the slope along n, grouped into
   * rods by proximity) and the down-slope deflection of a tip, the mean
   * displacement of its face along (1, 0, -1)/sqrt(2). */
  struct RodTips
  {
    static constexpr double radius = 0.06, length = 1.;
    std::vector<Point<3>>   centres;
    std::vector<std::vector<types::global_dof_index>> dofs;
    std::vector<unsigned int>                         component;

    explicit RodTips(const Discretization &disc)
      : component(disc.dof_components())
    {
      const auto   X = disc.support_points();
      const double c = std::sqrt(0.5);
      for (types::global_dof_index i = 0; i < X.size(); ++i)
        if (c * (X[i][0] + X[i][2]) > length - 1e-9)
          {
            unsigned int k = 0;
            while (k < centres.size() &&
                   X[i].distance(centres[k]) > 2. * radius)
              ++k;
            if (k == centres.size())
              {
                centres.push_back(X[i]);
                dofs.emplace_back();
              }
            dofs[k].push_back(i);
          }
    }

    double
    deflection(const Vector<double> &u, const unsigned int k) const
    {
      Tensor<1, 3> mean;
      for (const auto i : dofs[k])
        mean[component[i]] += u[i];
      return 3. * std::sqrt(0.5) * (mean[0] - mean[2]) / dofs[k].size();
    }
  };
} // namespace DynamicsTestScenes
