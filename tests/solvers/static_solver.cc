// The static solver on whole problems:
//  1. patch test: a homogeneous deformation imposed on the boundary of a
//     distorted mesh is reproduced inside to machine precision (P1, P2);
//  2. cantilever under a small gravity load vs Euler-Bernoulli (P2; P1 for
//     comparison);
//  3. a 90 degree rigid rotation gives zero stress (and the linear model's
//     spurious stress for comparison);
//  4. the line search: a 60 degree twist in one increment needs halved
//     steps and converges; without halvings it fails with a clear error;
//  5. quadratic convergence near the solution (direct solver);
//  6. every linear solver and the quasi-viscosity reach the same solution;
//  7. a rigid body (the skin layer of the layered block) rotated by 30
//     degrees carries the free elastic body along without stressing it.

#include "../distorted_box.h"
#include "../tests.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/nonzero_matrix.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/materials/mooney_rivlin.h>
#include <tissue_contact/simulation/static_simulation.h>
#include <tissue_contact/solvers/amg_preconditioner.h>
#include <tissue_contact/solvers/cholesky_factorization.h>
#include <tissue_contact/solvers/stagnation_control.h>

#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <cmath>
#include <iomanip>
#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  /** A problem with an arbitrary prescribed displacement on the whole
   * boundary: shows the solver needs nothing but NonlinearProblem. */
  class PatchProblem : public Solvers::NonlinearProblem
  {
  public:
    PatchProblem(const Discretization               &disc,
                 const Elasticity::ElasticAssembler &assembler,
                 const Tensor<2, 3>                 &H)
      : disc(disc)
      , assembler(assembler)
      , H(H)
      , X(disc.support_points())
    {
      std::vector<types::global_dof_index> face_dofs(disc.fe.n_dofs_per_face());
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int k = 0; k < face_dofs.size(); ++k)
                boundary[face_dofs[k]] =
                  disc.fe.face_system_to_component_index(k, f).first;
            }
    }
    types::global_dof_index
    n_dofs() const override
    {
      return disc.n_dofs();
    }
    const SparsityPattern &
    sparsity_pattern() const override
    {
      return disc.sparsity_pattern;
    }
    bool
    assemble(const Vector<double> &u,
             const double          l,
             Vector<double>       &R,
             SparseMatrix<double> *K) override
    {
      return assembler.assemble(u, l, R, K);
    }
    std::map<types::global_dof_index, double>
    prescribed_values(const double l) const override
    {
      std::map<types::global_dof_index, double> v;
      for (const auto &b : boundary)
        v[b.first] = l * (H * X[b.first])[b.second];
      return v;
    }
    double
    external_force_norm(const double) const override
    {
      return 0.;
    }
    Vector<double>
    quasi_viscosity_diagonal(const double eta) const override
    {
      return assembler.quasi_viscosity_diagonal(eta);
    }

    double
    max_error(const Vector<double> &u) const
    {
      const std::vector<unsigned int> component = disc.dof_components();
      double                          e         = 0.;
      for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
        e = std::max(e, std::abs(u[i] - (H * X[i])[component[i]]));
      return e;
    }

  private:
    const Discretization                       &disc;
    const Elasticity::ElasticAssembler         &assembler;
    const Tensor<2, 3>                          H;
    const std::vector<Point<3>>                 X;
    std::map<types::global_dof_index, unsigned> boundary;
  };

  void
  patch_test(const unsigned int degree)
  {
    Triangulation<3> tria;
    distorted_box(tria, {{3, 3, 3}}, Point<3>(1, 1, 1), 0.25, 3);
    const Materials::MooneyRivlin      material(5., 1., 50.);
    const Discretization               disc(tria, degree);
    const Elasticity::ElasticAssembler assembler(disc,
                                                 {{0, {&material, 1.}}},
                                                 Elasticity::DeadLoads());
    const Tensor<2, 3>                 H(
      {{0.15, 0.1, 0.}, {-0.05, -0.1, 0.08}, {0., 0.05, 0.2}});
    PatchProblem                                 problem(disc, assembler, H);
    Solvers::IncrementalNewtonSolver::Parameters p;
    p.initial_increment = 1.;
    Solvers::IncrementalNewtonSolver solver(p);
    Vector<double>                   u(disc.n_dofs());
    const auto                       stats = solver.solve(problem, u);
    deallog << "patch test P" << degree << " (" << disc.n_dofs()
            << " unknowns, " << stats.newton_iterations
            << " Newton iterations): max |u - H X| "
            << error_bound(problem.max_error(u), -14) << std::endl;
  }

  // A scene as prm text: a beam or cube, with placeholders filled in.
  std::string
  scene(const std::string &body, const std::string &rest)
  {
    return "subsection Output\n set Write VTU = false\n"
           " set Directory = .\nend\n"
           "subsection Bodies\n subsection Body 0\n" +
           body + " end\nend\n" + rest;
  }

  std::unique_ptr<StaticSimulation>
  solve(const std::string &text, std::ostream &log)
  {
    auto sim = std::make_unique<StaticSimulation>(
      Scene::SceneParameters::from_string(text), log);
    sim->run();
    return sim;
  }

  // Average of a displacement component over the DoFs of a boundary id.
  double
  boundary_average(const StaticSimulation  &sim,
                   const types::boundary_id id,
                   const unsigned int       component)
  {
    const auto &disc = sim.problem().discretization();
    std::map<types::global_dof_index, double> values;
    std::vector<types::global_dof_index> face_dofs(disc.fe.n_dofs_per_face());
    for (const auto &cell : disc.dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id)
          {
            cell->face(f)->get_dof_indices(face_dofs);
            for (unsigned int k = 0; k < face_dofs.size(); ++k)
              if (disc.fe.face_system_to_component_index(k, f).first ==
                  component)
                values[face_dofs[k]] = sim.solution()[face_dofs[k]];
          }
    double sum = 0.;
    for (const auto &v : values)
      sum += v.second;
    return sum / values.size();
  }

  void
  cantilever(const unsigned int degree, const unsigned int n_length)
  {
    // E = 1000, nu = 0 (mu = 500, lambda = 0), L = 1, b = h = 0.1,
    // q = rho g A = 0.01 * 0.01: w = q L^4 / (8 E I), I = b h^3 / 12
    const double E = 1000., g = 0.01, b = 0.1, h = 0.1, L = 1.;
    const double w_eb =
      g * b * h * std::pow(L, 4) / (8. * E * b * h * h * h / 12.);
    // Timoshenko: the shear deflection q L^2 / (2 kappa G A) added, with
    // kappa = 5/6, G = E / 2 (nu = 0), q = g A
    const double w_timoshenko = w_eb + g * L * L / (2. * 5. / 6. * 0.5 * E);
    std::ostringstream log;
    const auto         sim = solve(
      scene("set Model = neo-Hookean\n set Mu = 500\n set Lambda = 0\n",
            "subsection Mesh\n set Box upper corner = 1, 0.1, 0.1\n"
                    " set Box subdivisions = " +
              std::to_string(n_length) +
              ", 2, 2\nend\n"
                      "subsection Discretization\n set Polynomial degree = " +
              std::to_string(degree) +
              "\nend\n"
                      "subsection Loads\n set Gravity = 0, 0, -0.01\nend\n"
                      "subsection Load stepping\n set Initial increment = 1\nend\n"),
      log);
    const double w = -boundary_average(*sim, 1, 2);
    deallog << "cantilever P" << degree << " " << n_length
            << "x2x2: tip deflection / Euler-Bernoulli = " << std::fixed
            << std::setprecision(3) << w / w_eb
            << ", / Timoshenko = " << w / w_timoshenko
            << " (Timoshenko / Euler-Bernoulli " << w_timoshenko / w_eb << ")"
            << std::defaultfloat << std::setprecision(6) << std::endl;
  }

  void
  rigid_rotation(const std::string &model)
  {
    std::string bcs = "subsection Boundary conditions\n"
                      " set Number of Dirichlet conditions = 6\n";
    for (unsigned int i = 0; i < 6; ++i)
      bcs += " subsection Dirichlet " + std::to_string(i) +
             "\n  set Boundary id = " + std::to_string(i) +
             "\n  set Rotation axis = 1, 1, 0\n  set Rotation angle = 90\n"
             "  set Rotation center = 0.5, 0.5, 0.5\n end\n";
    std::ostringstream log;
    const auto         sim =
      solve(scene("set Model = " + model + "\n set Mu = 3\n set Lambda = 5\n",
                  "subsection Mesh\n set Box subdivisions = 2, 2, 2\n"
                  " set Distortion = 0.2\nend\n" +
                    bcs + "end\n"),
            log);
    const auto q =
      sim->problem().elastic_assembler().cell_quantities(sim->solution());
    deallog << "90 degree rigid rotation, " << model << ": max von Mises / mu "
            << error_bound(q.von_mises.linfty_norm() / 3., -10)
            << ", max |J - 1| "
            << error_bound(
                 [&] {
                   double e = 0.;
                   for (const double J : q.J)
                     e = std::max(e, std::abs(J - 1.));
                   return e;
                 }(),
                 -10)
            << std::endl;
  }

  // A 60 degree twist of a Mooney-Rivlin beam in one increment.
  std::string
  twist(const std::string &extra)
  {
    return scene(
      "set Model = Mooney-Rivlin\n set C1 = 5\n set C2 = 1\n set a = 50\n",
      "subsection Mesh\n set Box upper corner = 1, 0.2, 0.2\n"
      " set Box subdivisions = 6, 2, 2\nend\n"
      "subsection Boundary conditions\n"
      " set Number of Dirichlet conditions = 2\n"
      " subsection Dirichlet 0\n  set Boundary id = 0\n end\n"
      " subsection Dirichlet 1\n  set Boundary id = 1\n"
      "  set Rotation axis = 1, 0, 0\n  set Rotation center = 0, 0.1, 0.1\n"
      "  set Rotation angle = 60\n end\nend\n" +
        extra);
  }

  // Newton rows of the screen log: the step lengths of the iterations.
  std::vector<std::pair<double, double>> // (residual, step)
  rows(const std::string &log)
  {
    std::vector<std::pair<double, double>> r;
    std::istringstream                     in(log);
    std::string                            line;
    while (std::getline(in, line))
      {
        std::istringstream l(line);
        unsigned int       it;
        double             res;
        if (line.size() > 2 && line[0] == ' ' && (l >> it >> res))
          {
            double du, s;
            if (l >> du >> s)
              r.emplace_back(res, s);
            else
              r.emplace_back(res, 0.);
          }
      }
    return r;
  }

  /** The problem of a scene, watched: every state the solver assembles a
   * tangent at (the start of a Newton iteration, i.e. every accepted
   * iterate and the increment's initial guess) is checked for inverted
   * elements. */
  class WatchedProblem : public Solvers::ForwardingProblem
  {
  public:
    explicit WatchedProblem(Problem &problem)
      : Solvers::ForwardingProblem(problem)
      , problem(problem)
    {}
    bool
    assemble(const Vector<double> &u,
             const double          load_factor,
             Vector<double>       &R,
             SparseMatrix<double> *K) override
    {
      if (K != nullptr)
        {
          ++n_iterates;
          min_J = std::min(min_J, problem.elastic_assembler().min_jacobian(u));
        }
      return problem.assemble(u, load_factor, R, K);
    }
    unsigned int n_iterates = 0;
    double       min_J      = 1e300;

  private:
    Problem &problem;
  };

  /** A double well in three uncoupled unknowns, Pi(x) = sum_i (a_i x_i^2 / 2
   * + x_i^4 / 4) - lambda f.x with a = (-1, 1, 1): at x = 0 the tangent
   * diag(a_i + 3 x_i^2) = diag(-1, 1, 1) is indefinite, and x_0 = 0 is the
   * top of the well along x_0. */
  class DoubleWell : public Solvers::NonlinearProblem
  {
  public:
    DoubleWell()
    {
      DynamicSparsityPattern dsp(3, 3);
      for (unsigned int i = 0; i < 3; ++i)
        dsp.add(i, i);
      pattern.copy_from(dsp);
    }
    types::global_dof_index
    n_dofs() const override
    {
      return 3;
    }
    const SparsityPattern &
    sparsity_pattern() const override
    {
      return pattern;
    }
    bool
    assemble(const Vector<double> &x,
             const double          l,
             Vector<double>       &R,
             SparseMatrix<double> *K) override
    {
      for (unsigned int i = 0; i < 3; ++i)
        {
          R[i] = a[i] * x[i] + x[i] * x[i] * x[i] - l * f[i];
          if (K != nullptr)
            K->set(i, i, a[i] + 3. * x[i] * x[i]);
        }
      return true;
    }
    double
    energy(const Vector<double> &x, const double l) const override
    {
      double E = 0.;
      for (unsigned int i = 0; i < 3; ++i)
        E +=
          0.5 * a[i] * x[i] * x[i] + 0.25 * std::pow(x[i], 4) - l * f[i] * x[i];
      return E;
    }
    std::map<types::global_dof_index, double>
    prescribed_values(const double) const override
    {
      return {};
    }
    double
    external_force_norm(const double l) const override
    {
      return l * std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    }
    Vector<double>
    quasi_viscosity_diagonal(const double) const override
    {
      return Vector<double>(3);
    }

    const double a[3] = {-1., 1., 1.};
    const double f[3] = {0.1, 0.1, 0.1};

  private:
    SparsityPattern pattern;
  };

  // The definite steps of the Cholesky factorization (doc/theory/
  // 04-solver.md sec. 4.3.1) from the top of the double well: the tangent
  // diag(-1, 1, 1) is refused, and so is it shifted by 10^e |K_ii| up to
  // e = 0 (diag(0, 2, 2)); e = 1 gives diag(9, 11, 11), and the steps go
  // down to the well's bottom x_0 = 1.0467 (x^3 - x = 0.1), where the
  // tangent 3 x_0^2 - 1 is positive: a minimum. UMFPACK's LU takes the
  // plain Newton steps, which descend as a whole (R.du = -|f|^2 + 2 f_0^2
  // < 0) but climb along x_0, and converge to x_0 = -0.1010, where the
  // tangent is negative: a saddle of the energy, an equilibrium no
  // minimization would stop at. Conjugate gradients with AMG (Type =
  // GMRES+AMG, its definite steps; doc/theory/04-solver.md sec. 4.3.2)
  // refuse the tangent too and reach the bottom as the Cholesky
  // factorization does (a shifted matrix made singular, a negative
  // diagonal entry met by sigma = 1, whose coarse level KLU cannot
  // factorize, refused as well).
  void
  definite_steps()
  {
    for (const std::string direct : {"Cholesky", "UMFPACK", "CG+AMG"})
      {
        DoubleWell                                   problem;
        Solvers::IncrementalNewtonSolver::Parameters p;
        p.initial_increment = 1.;
        if (direct == "CG+AMG")
          p.linear_solver.type = "GMRES+AMG";
        else
          p.linear_solver.direct_solver = direct;
        Solvers::IncrementalNewtonSolver solver(p);
        Vector<double>                   x(3);
        try
          {
            const SolveStatistics s = solver.solve(problem, x);
            deallog << "double well from its top, " << direct
                    << ": converged, x = " << std::fixed << std::setprecision(4)
                    << x[0] << " " << x[1] << " " << x[2] << std::defaultfloat
                    << std::setprecision(6) << ", tangent there "
                    << (problem.a[0] + 3. * x[0] * x[0] > 0. ? "positive" :
                                                               "NOT positive")
                    << ", " << s.newton_iterations << " Newton iterations, "
                    << s.tangent_shifts << " with a shifted tangent"
                    << std::endl;
          }
        catch (const std::exception &e)
          {
            deallog << "double well from its top, " << direct
                    << ": error: " << error_message(e) << std::endl;
          }
      }
  }

  void
  line_search()
  {
    std::ostringstream log;
    const std::string  one_step =
      "subsection Load stepping\n set Initial increment = 1\n"
      " set Minimum increment = 1\nend\n";
    solve(twist(one_step), log);
    unsigned int halved = 0;
    std::string  steps;
    for (const auto &r : rows(log.str()))
      {
        if (r.second > 0. && r.second < 1.)
          ++halved;
        if (r.second > 0.)
          steps += " " + std::to_string(r.second).substr(0, 6);
      }
    deallog << "60 degree twist in one increment: converged, "
            << "step lengths" << steps << std::endl;
    deallog << "iterations with a halved step: " << halved << std::endl;
    {
      // the line search never accepts an inverted element: the smallest
      // det F over every iterate Newton continued from
      const auto parameters = Scene::SceneParameters::from_string(
        twist(one_step) +
        "subsection Output\n set Write VTU = false\n set Directory = .\nend\n");
      Problem                          problem(parameters);
      WatchedProblem                   watched(problem);
      Solvers::IncrementalNewtonSolver solver(parameters.solver);
      Vector<double>                   u(problem.n_dofs());
      solver.solve(watched, u);
      deallog << "iterates assembled: " << watched.n_iterates
              << ", smallest det F among them "
              << (watched.min_J > 0. ? "positive" : "NOT positive") << " ("
              << std::setprecision(3) << watched.min_J << std::setprecision(6)
              << ")" << std::endl;
    }

    // without halvings: the LU's Newton steps (UMFPACK) need one and fail
    // with the line search's message; the Cholesky default's definite
    // steps (doc/theory/04-solver.md sec. 4.3.1) need none
    const std::string no_halvings =
      one_step + "subsection Newton\n set Maximum line search halvings = 0\n"
                 "end\n";
    try
      {
        std::ostringstream log2;
        solve(twist(no_halvings + "subsection Linear solver\n"
                                  " set Direct solver = UMFPACK\nend\n"),
              log2);
        deallog << "without halvings, UMFPACK: converged (unexpected)"
                << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << "without halvings, UMFPACK: error: " << error_message(e)
                << std::endl;
      }
    {
      std::ostringstream log2;
      solve(twist(no_halvings), log2);
      unsigned int its = 0;
      for (const auto &r : rows(log2.str()))
        its += (r.second > 0.);
      deallog << "without halvings, Cholesky: converged, " << its
              << " Newton iterations" << std::endl;
    }
  }

  void
  quadratic_convergence()
  {
    std::ostringstream log;
    solve(twist("subsection Load stepping\n set Initial increment = 0.25\n"
                " set Maximum increment = 0.25\nend\n"),
          log);
    // the last increment: p_k = log(r_k+1 / r_k) / log(r_k / r_k-1)
    const auto          all = rows(log.str());
    std::vector<double> r;
    for (auto it = all.rbegin(); it != all.rend(); ++it)
      {
        r.insert(r.begin(), it->first);
        if (it != all.rbegin() && it->second == 0.)
          {
            r.erase(r.begin());
            break;
          }
      }
    deallog << "last increment, residuals:";
    for (const double v : r)
      deallog << " " << scientific(v);
    deallog << std::defaultfloat << std::setprecision(6) << std::endl;
    deallog << "convergence order estimates:";
    for (unsigned int k = 1; k + 1 < r.size(); ++k)
      if (r[k + 1] > 1e-12 * r[0])
        deallog << " " << std::fixed << std::setprecision(1)
                << std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]);
    deallog << std::defaultfloat << std::setprecision(6) << std::endl;
    deallog << "r_k+1 / r_k^2 (bounded for quadratic convergence):";
    for (unsigned int k = 0; k + 1 < r.size(); ++k)
      if (r[k + 1] > 1e-12 * r[0])
        deallog << " " << scientific(r[k + 1] / (r[k] * r[k]));
    deallog << std::defaultfloat << std::setprecision(6) << std::endl;
  }

  void
  solvers_agree()
  {
    std::ostringstream log;
    const std::string  stepping =
      "subsection Load stepping\n set Initial increment = 0.5\nend\n";
    const auto reference = solve(twist(stepping), log);
    const auto compare   = [&](const std::string &name,
                             const std::string &extra) {
      std::ostringstream log;
      const auto         sim = solve(twist(stepping + extra), log);
      Vector<double>     d(sim->solution());
      d -= reference->solution();
      unsigned int its = 0;
      for (const auto &r : rows(log.str()))
        its += (r.second > 0.);
      deallog << name << ": |u - u_direct| / |u_direct| "
              << error_bound(d.l2_norm() / reference->solution().l2_norm(), -10)
              << std::endl;
      return its;
    };
    const unsigned int jacobi =
      compare("GMRES+Jacobi (rel. tol. 0.1)",
              "subsection Linear solver\n set Type = GMRES+Jacobi\nend\n");
    const unsigned int amg =
      compare("GMRES+AMG (rel. tol. 0.1)",
              "subsection Linear solver\n set Type = GMRES+AMG\nend\n");
    const unsigned int adaptive =
      compare("GMRES+AMG (Eisenstat-Walker, hierarchy reused)",
              "subsection Linear solver\n set Type = GMRES+AMG\n"
              " set Forcing term = Eisenstat-Walker\n"
              " set Reuse preconditioner = true\nend\n");
    const unsigned int viscous =
      compare("direct with quasi-viscosity",
              "subsection Newton\n set Quasi-viscosity = true\nend\n");
    unsigned int direct = 0;
    for (const auto &r : rows(log.str()))
      direct += (r.second > 0.);
    // exact counts for the quadratically converging variants; the inexact
    // GMRES+Jacobi Newton count moves with rounding, so only its bracket
    deallog << "Newton iterations: direct " << direct << ", GMRES+AMG " << amg
            << ", direct + quasi-viscosity " << viscous
            << "; GMRES+Jacobi (inexact) between direct and 3x direct: "
            << (jacobi > direct && jacobi < 3 * direct)
            << "; GMRES+AMG (Eisenstat-Walker) at most 2x direct: "
            << (adaptive <= 2 * direct) << std::endl;
  }

  // The Eisenstat-Walker forcing term (doc/theory/04-solver.md, 4.5.1)
  // against the formula, branch by branch.
  void
  forcing_term()
  {
    Solvers::LinearSolver::Parameters p;
    p.type               = "GMRES+AMG";
    p.relative_tolerance = 0.5;
    const Solvers::LinearSolver fixed(p);
    p.forcing_term = "Eisenstat-Walker";
    const Solvers::LinearSolver ew(p);
    deallog << "forcing terms: fixed " << fixed.forcing(0.1, 1., 0.5, 0.)
            << "; first iteration " << ew.forcing(1., 0., 0., 0.)
            << "; 0.9 (0.1/1)^2 = " << ew.forcing(0.1, 1., 0.01, 0.)
            << "; safeguard 0.9 0.4^2 = " << ew.forcing(0.01, 0.1, 0.4, 0.)
            << "; capped 0.9 (0.9)^2 -> " << ew.forcing(0.9, 1., 0.01, 0.)
            << "; floor 0.5 tol / r = " << ew.forcing(1e-3, 1., 0.01, 2e-4)
            << std::endl;
  }

  // The five-point Laplacian on an m x m grid, its x couplings scaled by
  // ax, in one pattern for every ax.
  class Laplacian
  {
  public:
    explicit Laplacian(const unsigned int m)
      : m(m)
      , n(m * m)
    {
      DynamicSparsityPattern dsp(n, n);
      for_each_entry(1.,
                     [&](const unsigned int k, const unsigned int l, double) {
                       dsp.add(k, l);
                     });
      pattern.copy_from(dsp);
    }

    SparseMatrix<double>
    operator()(const double ax) const
    {
      SparseMatrix<double> A(pattern);
      for_each_entry(ax,
                     [&](const unsigned int k,
                         const unsigned int l,
                         const double       v) { A.set(k, l, v); });
      return A;
    }

    const unsigned int m, n;

  private:
    // f(row, column, value) for every entry
    template <typename F>
    void
    for_each_entry(const double ax, const F &f) const
    {
      for (unsigned int k = 0; k < n; ++k)
        {
          const unsigned int j = k % m;
          f(k, k, 2. + 2. * ax);
          if (k >= m)
            f(k, k - m, -1.);
          if (k + m < n)
            f(k, k + m, -1.);
          if (j > 0)
            f(k, k - 1, -ax);
          if (j + 1 < m)
            f(k, k + 1, -ax);
        }
    }

    SparsityPattern pattern;
  };

  // A kept AMG hierarchy on a matrix that has drifted from it (doc/theory/
  // 04-solver.md, 4.5.1): GMRES stops once the iterations beyond the fresh
  // hierarchy's reach a setup's cost (50), a new hierarchy goes on from the
  // iterate reached, and the result meets the target. Five-point Laplacian
  // on a 60 x 60 grid, then the same grid with its x couplings 1000 times
  // stronger. Then a solve from a given x: none from the solution itself,
  // fewer than from zero from the solution of a nearby system.
  void
  kept_hierarchy()
  {
    const Laplacian            laplacian(60);
    const unsigned int         n  = laplacian.n;
    const SparseMatrix<double> A1 = laplacian(1.), A2 = laplacian(1000.);
    Vector<double>             b(n), x(n), r(n);
    b = 1.;
    Solvers::LinearSolver::Parameters p;
    p.type                 = "GMRES+AMG";
    p.reuse_preconditioner = true;
    // a kept hierarchy that is not refreshed (plain aggregation's is)
    p.amg_aggregation               = "smoothed";
    const double                tol = 1e-6;
    const Solvers::LinearSolver kept(p), fresh(p);
    const unsigned int          n1     = kept.solve(A1, x, b, tol);
    const unsigned int          n2     = kept.solve(A2, x, b, tol);
    const double                r2     = A2.residual(r, x, b) / b.l2_norm();
    const unsigned int          nf     = fresh.solve(A2, x, b, tol);
    const unsigned int          budget = n1 + 50;
    deallog << "kept hierarchy on a drifted matrix: residual below 1e-6: "
            << (r2 <= tol) << ", iterations within the budget (" << budget
            << ") plus a fresh solve's (" << nf << "): " << (n2 <= budget + nf)
            << ", more than the budget (the hierarchy replaced): "
            << (n2 > budget) << std::endl;

    // two solvers with the same history (a hierarchy of A1): one goes on
    // from A1's solution, the other from zero
    const SparseMatrix<double>  A3 = laplacian(1.2);
    const Solvers::LinearSolver warm(p), cold(p);
    Vector<double>              y(n);
    warm.solve(A1, x, b, tol);
    cold.solve(A1, y, b, tol);
    const unsigned int again     = warm.solve(A1, x, b, tol, true);
    const unsigned int from_near = warm.solve(A3, x, b, tol, true);
    const unsigned int from_zero = cold.solve(A3, y, b, tol);
    const double       r3        = A3.residual(r, x, b) / b.l2_norm();
    deallog << "from the solution: " << again
            << " iterations; a system with x couplings 1.2 times stronger from "
               "the first one's solution: "
            << from_near << " iterations (from zero: " << from_zero
            << "), residual below 1e-6: " << (r3 <= tol) << std::endl;
  }

  // GMRES's restart (Linear solver/GMRES restart; doc/theory/04-solver.md,
  // 4.5.2): GMRES+Jacobi on the 30 x 30 Laplacian to 1e-8, restarted after
  // every 10 Krylov vectors, needs more iterations than with 150 kept, where
  // it does not restart before it converges.
  void
  gmres_restart()
  {
    const Laplacian            laplacian(30);
    const SparseMatrix<double> A = laplacian(1.);
    Vector<double>             b(laplacian.n), x(laplacian.n), r(laplacian.n);
    b = 1.;
    Solvers::LinearSolver::Parameters p;
    p.type          = "GMRES+Jacobi";
    p.gmres_restart = 10;
    const Solvers::LinearSolver restarted(p);
    p.gmres_restart = 150;
    const Solvers::LinearSolver kept(p);
    const unsigned int          n_10  = restarted.solve(A, x, b, 1e-8);
    const unsigned int          n_150 = kept.solve(A, x, b, 1e-8);
    deallog << "GMRES restart: Jacobi iterations to 1e-8 restarted after 10 "
            << n_10 << ", after 150 " << n_150 << "; fewer: " << (n_150 < n_10)
            << "; residual below 1e-8: "
            << (A.residual(r, x, b) <= 1e-8 * b.l2_norm()) << std::endl;
  }

  // @p W: @p A with zeros stored in more places of its pattern (@p
  // pattern: A's and the couplings of every i with i + 7, cyclically), as a
  // contact pattern that kept the couplings of pairs no longer in contact
  void
  with_zeros_stored(const SparseMatrix<double> &A,
                    SparsityPattern            &pattern,
                    SparseMatrix<double>       &W)
  {
    const unsigned int     n = A.m();
    DynamicSparsityPattern dsp(n, n);
    for (const auto &e : A)
      dsp.add(e.row(), e.column());
    for (unsigned int i = 0; i < n; ++i)
      {
        dsp.add(i, (i + 7) % n);
        dsp.add((i + 7) % n, i);
      }
    pattern.copy_from(dsp);
    W.reinit(pattern);
    for (const auto &e : A)
      W.set(e.row(), e.column(), e.value());
  }

  // The direct fallback of GMRES+AMG chosen by Type = automatic
  // (doc/theory/04-solver.md, 4.5.1) on the 100 x 100 Laplacian shifted into
  // indefiniteness (minus 2 I: eigenvalues between -2 and 6), with GMRES
  // restarted after 2 vectors: its restart cycles stagnate, the solve stops
  // long before the cap of 1 000 iterations, and the direct solver makes
  // the step from the matrix's nonzeros: the same matrix with zeros stored
  // in more places of its pattern (as a contact pattern that kept the
  // couplings of pairs no longer in contact) gives the same step to the
  // last bit, that of UMFPACK on the matrix itself. UMFPACK given the
  // stored zeros too orders its pivots otherwise and rounds otherwise.
  void
  direct_fallback()
  {
    const Laplacian      laplacian(100);
    const auto           n = laplacian.n;
    SparseMatrix<double> A = laplacian(1.);
    for (unsigned int i = 0; i < n; ++i)
      A.diag_element(i) -= 2.;
    SparsityPattern      wide_pattern;
    SparseMatrix<double> W;
    with_zeros_stored(A, wide_pattern, W);
    Vector<double> b(n), x(n), y(n), z(n), z_wide(n);
    b = 1.;
    Solvers::LinearSolver::Parameters p;
    p.type            = "GMRES+AMG";
    p.direct_fallback = true;
    p.gmres_restart   = 2;
    const Solvers::LinearSolver narrow(p), wide(p);
    const unsigned int          iterations = narrow.solve(A, x, b, 1e-8);
    wide.solve(W, y, b, 1e-8);
    SparseDirectUMFPACK lu, lu_wide;
    lu.initialize(A);
    lu.vmult(z, b);
    lu_wide.initialize(W);
    lu_wide.vmult(z_wide, b);
    deallog << "direct fallback: GMRES(2) with AMG on the indefinite "
               "Laplacian stops after "
            << iterations << " iterations (before the cap: "
            << (iterations < p.max_iterations) << "), fell back "
            << narrow.direct_fallbacks() << " and " << wide.direct_fallbacks()
            << " times; the step equals UMFPACK's on the matrix bit for bit: "
            << (x == z)
            << ", with zeros stored in more places too: " << (y == z)
            << " (UMFPACK given them rounds otherwise: " << (z_wide != z) << ")"
            << std::endl;
  }

  // The definiteness test of conjugate gradients with AMG
  // (LinearSolver::solve_definite(), doc/theory/04-solver.md sec. 4.3.1) on
  // the 30 x 30 Laplacian, whose eigenvalues are (2 - 2 cos(i pi/31)) +
  // (2 - 2 cos(j pi/31)), the smallest 0.0205, the next 0.0512: as it is,
  // solved to the tolerance (1e-8 of |b|); minus 0.03 I (one eigenvalue
  // negative, -0.0095) refused, with a direction p of curvature p.Kp <= 0
  // for the right-hand side of ones, which has a component along that
  // eigenvector; shifted by sigma |K_ii| with sigma ten times the
  // -p.Kp / p.Dp that direction asks for, accepted and solved; made
  // unsymmetric by 1e-9 of an entry, refused as such.
  void
  definite_cg()
  {
    const Laplacian      laplacian(30);
    const auto           n = laplacian.n;
    SparseMatrix<double> A = laplacian(1.), B = laplacian(1.);
    for (unsigned int i = 0; i < n; ++i)
      B.diag_element(i) -= 0.03;
    Solvers::LinearSolver::Parameters p;
    p.type = "GMRES+AMG";
    const Solvers::LinearSolver solver(p);
    Vector<double>              b(n), x(n), p_found, r(n);
    b = 1.;
    unsigned int its_A, its_B, its_shifted;
    using D            = Solvers::LinearSolver::Definiteness;
    const D    found_A = solver.solve_definite(A, x, b, 1e-8, its_A, p_found);
    const bool solved_A =
      A.residual(r, x, b) <= 1e-8 * b.l2_norm() && p_found.size() == 0;
    const D found_B = solver.solve_definite(B, x, b, 1e-8, its_B, p_found);
    Vector<double> Bp(n);
    double         curvature = 0., pDp = 0.;
    if (p_found.size() == n)
      {
        B.vmult(Bp, p_found);
        curvature = p_found * Bp;
        for (unsigned int i = 0; i < n; ++i)
          pDp += std::abs(B.diag_element(i)) * p_found[i] * p_found[i];
      }
    const double sigma = -10. * curvature / pDp;
    for (unsigned int i = 0; i < n; ++i)
      B.diag_element(i) += sigma * std::abs(B.diag_element(i));
    const D found_shifted =
      solver.solve_definite(B, x, b, 1e-8, its_shifted, p_found);
    const bool solved_shifted = B.residual(r, x, b) <= 1e-8 * b.l2_norm();
    A.set(0, 1, A.el(0, 1) * (1. + 1e-9));
    const D found_unsymmetric =
      solver.solve_definite(A, x, b, 1e-8, its_A, p_found);
    deallog << "definite steps by CG with AMG: the Laplacian positive definite "
            << (found_A == D::positive_definite) << ", solved " << solved_A
            << "; minus 0.03 I refused "
            << (found_B == D::not_positive_definite)
            << ", with a direction of curvature <= 0: " << (curvature <= 0.)
            << " (sigma = 10 times its Rayleigh quotient: "
            << std::setprecision(2) << sigma << std::setprecision(6)
            << "); shifted by it positive definite "
            << (found_shifted == D::positive_definite) << ", solved "
            << solved_shifted << "; unsymmetric by 1e-9 refused as such "
            << (found_unsymmetric == D::not_symmetric) << std::endl;
  }

  // Direct solver = Cholesky (Solvers::CholeskyFactorization; doc/theory/
  // 04-solver.md, 4.5.3) on the 30 x 30 Laplacian: its solution is
  // UMFPACK's to rounding; a second matrix of the same pattern reuses the
  // symbolic analysis, one of another pattern (zeros stored in more
  // places) makes a new one; the Laplacian shifted into indefiniteness
  // (minus 2 I) and one made unsymmetric by 1e-9 of an entry are refused
  // (1e-15, rounding, is not). Through LinearSolver a refused tangent is
  // factorized by LU, and after a refusal the next 1, 2, 4, 8 solves go to
  // the LU without trying (fewer refusals than solves of an indefinite
  // run); a positive definite tangent after that is factorized by
  // Cholesky again.
  void
  cholesky()
  {
    const Laplacian      laplacian(30);
    const auto           n = laplacian.n;
    SparseMatrix<double> A = laplacian(1.), B = laplacian(3.),
                         C = laplacian(1.), U = laplacian(1.),
                         S = laplacian(1.);
    for (unsigned int i = 0; i < n; ++i)
      C.diag_element(i) -= 2.;
    U.set(5, 4, U(5, 4) * (1. + 1e-9));
    S.set(5, 4, S(5, 4) * (1. + 1e-15));
    SparsityPattern      wide_pattern;
    SparseMatrix<double> W;
    with_zeros_stored(A, wide_pattern, W);

    Vector<double> b(n), x(n), z(n);
    for (unsigned int i = 0; i < n; ++i)
      b[i] = std::sin(0.1 * i + 0.3);
    // |x - UMFPACK's solution| / |UMFPACK's solution|
    const auto difference = [&](const SparseMatrix<double> &M) {
      SparseDirectUMFPACK lu;
      lu.initialize(M);
      lu.vmult(z, b);
      z -= x;
      return z.l2_norm() / x.l2_norm();
    };
    Solvers::CholeskyFactorization cholesky;
    double                         largest = 0.;
    std::ostringstream             accepted;
    for (const SparseMatrix<double> *M : {&A, &B, &W})
      {
        accepted << cholesky.factorize(*M) << " ";
        cholesky.solve(x, b);
        largest = std::max(largest, difference(*M));
      }
    // an indefinite matrix small enough for the simplicial L D L^T, which
    // meets no zero pivot: refused by the signs of D (the 1D Laplacian
    // 2 - 1/2 on its diagonal, smallest eigenvalue 2 - 2 cos(pi / 11) - 1/2)
    DynamicSparsityPattern tridiagonal(10, 10);
    for (unsigned int i = 0; i < 10; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(i + 2, 10u); ++j)
        tridiagonal.add(i, j);
    SparsityPattern small_pattern;
    small_pattern.copy_from(tridiagonal);
    SparseMatrix<double> T(small_pattern);
    for (unsigned int i = 0; i < 10; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(i + 2, 10u); ++j)
        T.set(i, j, i == j ? 1.5 : -1.);
    accepted << "analyses " << cholesky.n_analyses() << "; indefinite "
             << cholesky.factorize(C) << " and " << cholesky.factorize(T)
             << " (by L D L^T), unsymmetric by 1e-9 " << cholesky.factorize(U)
             << " (seen as such: " << !cholesky.was_symmetric()
             << "), by 1e-15 " << cholesky.factorize(S);
    deallog << "Cholesky: factorized A, B (same pattern), W (wider): "
            << accepted.str() << "; largest difference from UMFPACK "
            << error_bound(largest, -13) << std::endl;

    Solvers::LinearSolver::Parameters p;
    p.type          = "direct";
    p.direct_solver = "Cholesky";
    const Solvers::LinearSolver solver(p);
    std::ostringstream          fallbacks;
    largest = 0.;
    // 7 indefinite solves: refused at the 1st, 3rd and 6th (then skipping
    // 1, 2 and 4 solves), so the 7th and the first three definite ones go
    // to the LU directly; the 4th definite one is factorized by Cholesky,
    // which clears the backoff
    for (const SparseMatrix<double> *M :
         {&C, &C, &C, &C, &C, &C, &C, &A, &A, &A, &A, &A, &B})
      {
        solver.solve(*M, x, b);
        largest = std::max(largest, difference(*M));
        fallbacks << solver.cholesky_fallbacks() << " ";
      }
    deallog << "Cholesky in LinearSolver: LU solves after each of 7 "
               "indefinite, then 6 definite tangents: "
            << fallbacks.str() << "; largest difference from UMFPACK "
            << error_bound(largest, -13) << std::endl;
  }

  // The stop of a stagnating restarted GMRES (Solvers::StagnationControl;
  // doc/theory/04-solver.md, 4.5.1), GMRES(10) to 1e-8 within 1 000
  // iterations: on the cyclic shift of 200 unknowns with b = e_0 every
  // Krylov space short of the 200th misses the solution e_199, the
  // residual stays 1, and a plain SolverControl runs to the cap while the
  // stagnation control stops after the first cycle; on the 30 x 30
  // Laplacian with Jacobi, where the restarted GMRES converges slowly but
  // at a steady rate, it changes nothing: the same iterations and the same
  // solution to the last bit.
  void
  stagnation_control()
  {
    const auto run = [](const SparseMatrix<double> &A,
                        const Vector<double>       &b,
                        const auto                 &P,
                        SolverControl              &control,
                        Vector<double>             &x) {
      SolverGMRES<Vector<double>>::AdditionalData data;
      data.max_n_tmp_vectors     = 12;
      data.right_preconditioning = true;
      SolverGMRES<Vector<double>> gmres(control, data);
      x              = 0.;
      bool converged = true;
      try
        {
          gmres.solve(A, x, b, P);
        }
      catch (const SolverControl::NoConvergence &)
        {
          converged = false;
        }
      return converged;
    };

    const unsigned int     n = 200;
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      dsp.add((i + 1) % n, i);
    SparsityPattern shift_pattern;
    shift_pattern.copy_from(dsp);
    SparseMatrix<double> shift(shift_pattern);
    for (unsigned int i = 0; i < n; ++i)
      shift.set((i + 1) % n, i, 1.);
    Vector<double> e0(n), x(n), y(n);
    e0[0] = 1.;
    SolverControl              plain(1000, 1e-8, false, false);
    Solvers::StagnationControl stopping(1000, 1e-8, 10);
    const PreconditionIdentity identity;
    const bool plain_converged    = run(shift, e0, identity, plain, x);
    const bool stopping_converged = run(shift, e0, identity, stopping, y);
    deallog << "stagnation: on the cyclic shift a plain control runs to "
            << plain.last_step()
            << " iterations (converged: " << plain_converged
            << "), the stagnation control stops at " << stopping.last_step()
            << " (converged: " << stopping_converged
            << ", stagnated: " << stopping.has_stagnated() << ")";

    const Laplacian            laplacian(30);
    const SparseMatrix<double> A = laplacian(1.);
    Vector<double>             b(laplacian.n);
    x.reinit(laplacian.n);
    y.reinit(laplacian.n);
    b = 1.;
    PreconditionJacobi<SparseMatrix<double>> jacobi;
    jacobi.initialize(A);
    SolverControl              plain_laplacian(1000, 1e-8, false, false);
    Solvers::StagnationControl steady(1000, 1e-8, 10);
    const bool                 both =
      run(A, b, jacobi, plain_laplacian, x) && run(A, b, jacobi, steady, y);
    bool same = true;
    for (unsigned int i = 0; i < x.size(); ++i)
      same = same && x[i] == y[i];
    deallog << "; on the Laplacian both converge: " << both << ", in "
            << plain_laplacian.last_step() << " and " << steady.last_step()
            << " iterations, the same solution bit for bit: " << same
            << std::endl;
  }

  // The V-cycle whose levels run on deal.II's threads (doc/theory/
  // 04-solver.md, 4.5.2) against ML's own cycle with the same settings, on
  // Laplacians with x couplings 10 times stronger, of 60 x 60 (two levels)
  // and 160 x 160 (three): GMRES needs about as many iterations with either
  // (the Chebyshev smoothing alone, without the coarse correction, needs
  // many more); the preconditioner is a linear operator (GMRES keeps it
  // across iterations); and with rows of negative diagonal, as an
  // indefinite contact tangent has, it stays finite. The plain-aggregation
  // hierarchy (AMG aggregation = plain) is a working preconditioner too:
  // far fewer iterations than the smoother alone. On the 30 x 30 Laplacian
  // the hierarchy is a single level, solved exactly.
  void
  threaded_amg()
  {
    // the right-hand side of n rows, and GMRES's iterations to 1e-8 from
    // zero on M x = r, right-preconditioned by P
    const auto rhs = [](const unsigned int n) {
      Vector<double> r(n);
      for (unsigned int k = 0; k < n; ++k)
        r[k] = std::sin(0.37 * k) + 0.5;
      return r;
    };
    const auto iterations = [](const SparseMatrix<double> &M,
                               const Vector<double>       &r,
                               const auto                 &P) {
      ReductionControl control(500, 1e-300, 1e-8, false, false);
      SolverGMRES<Vector<double>>::AdditionalData data;
      data.right_preconditioning = true;
      SolverGMRES<Vector<double>> gmres(control, data);
      Vector<double>              y(r.size());
      gmres.solve(M, y, r, P);
      return control.last_step();
    };
    const Laplacian      laplacian(60);
    const unsigned int   n                = laplacian.n;
    SparseMatrix<double> A                = laplacian(10.);
    const Vector<double> b                = rhs(n);
    const auto           gmres_iterations = [&](const auto &P) {
      return iterations(A, b, P);
    };
    Solvers::AMGPreconditioner threaded;
    threaded.initialize(A, {}, 0, true);
    TrilinosWrappers::PreconditionAMG                 ml;
    TrilinosWrappers::PreconditionAMG::AdditionalData ml_data;
    ml_data.elliptic              = true;
    ml_data.higher_order_elements = false;
    ml_data.smoother_sweeps       = 2;
    ml_data.aggregation_threshold = 1e-4;
    ml.initialize(A, ml_data);
    PreconditionChebyshev<SparseMatrix<double>, Vector<double>> smoothing;
    PreconditionChebyshev<SparseMatrix<double>, Vector<double>>::AdditionalData
      smoothing_data;
    smoothing_data.degree          = 2;
    smoothing_data.smoothing_range = 10.;
    smoothing_data.preconditioner =
      std::make_shared<DiagonalMatrix<Vector<double>>>();
    smoothing_data.preconditioner->get_vector().reinit(n);
    for (unsigned int k = 0; k < n; ++k)
      smoothing_data.preconditioner->get_vector()[k] = 1. / A.diag_element(k);
    smoothing.initialize(A, smoothing_data);
    Solvers::AMGPreconditioner plain;
    plain.initialize(A, {}, 0, false);
    const unsigned int n_plain     = gmres_iterations(plain);
    const unsigned int n_threaded  = gmres_iterations(threaded),
                       n_ml        = gmres_iterations(ml),
                       n_smoothing = gmres_iterations(smoothing);

    Vector<double> b2(n), y1(n), y2(n), y(n);
    for (unsigned int k = 0; k < n; ++k)
      b2[k] = std::cos(1.3 * k);
    threaded.vmult(y1, b);
    threaded.vmult(y2, b2);
    b2.sadd(3., b); // 3 b2 + b
    threaded.vmult(y, b2);
    y.add(-3., y2, -1., y1);
    const bool linear = y.l2_norm() < 1e-12 * y1.l2_norm();

    // every 50th row's diagonal turned negative
    for (unsigned int k = 0; k < n; k += 50)
      A.set(k, k, -A.diag_element(k));
    Solvers::AMGPreconditioner indefinite;
    indefinite.initialize(A, {}, 0, true);
    indefinite.vmult(y, b);
    deallog << "threaded V-cycle: GMRES iterations to 1e-8 " << n_threaded
            << ", ML's own cycle " << n_ml << ", its smoother alone "
            << (n_smoothing > 5 * n_ml ? "more than 5x" : "at most 5x")
            << "; within 1.5x ML's + 2: " << (n_threaded <= 1.5 * n_ml + 2)
            << "; linear to 1e-12: " << linear
            << "; finite with negative diagonals: "
            << std::isfinite(y.l2_norm()) << std::endl;
    deallog << "plain aggregation: GMRES iterations to 1e-8 " << n_plain
            << "; fewer than the smoother alone: " << (n_plain < n_smoothing)
            << std::endl;

    // a hierarchy of three levels, whose middle one is smoothed (ML stops
    // coarsening below 2 000 rows): the 160 x 160 Laplacian
    const Laplacian            large(160);
    const SparseMatrix<double> L = large(10.);
    const Vector<double>       c = rhs(large.n);
    Solvers::AMGPreconditioner three;
    three.initialize(L, {}, 0, true);
    TrilinosWrappers::PreconditionAMG ml_three;
    ml_three.initialize(L, ml_data);
    const unsigned int n_three    = iterations(L, c, three),
                       n_ml_three = iterations(L, c, ml_three);
    deallog << "on the 160 x 160 Laplacian: levels " << three.n_levels()
            << ", GMRES iterations to 1e-8 " << n_three << ", ML's own cycle "
            << n_ml_three
            << "; within 1.5x ML's + 2: " << (n_three <= 1.5 * n_ml_three + 2)
            << std::endl;

    // a hierarchy of plain aggregation refreshed (doc/theory/04-solver.md,
    // 4.5.1): with its own matrix, the coarse operators as the project's
    // Galerkin products instead of ML's, the same V-cycle to rounding; with
    // the x couplings ten times stronger (100 instead of 10), on the
    // aggregates of the first, fewer iterations than without the refresh;
    // and back to the operators accepted before, the V-cycle of those bit
    // for bit
    Solvers::AMGPreconditioner refreshed, stale, fresh;
    refreshed.initialize(L, {}, 0, false);
    stale.initialize(L, {}, 0, false);
    Vector<double> v_built(large.n), v_refreshed(large.n);
    refreshed.vmult(v_built, c);
    refreshed.refresh(L);
    refreshed.vmult(v_refreshed, c);
    Vector<double> difference = v_refreshed;
    difference -= v_built;
    const bool same = difference.l2_norm() < 1e-12 * v_built.l2_norm();
    refreshed.accept();
    const SparseMatrix<double> L100 = large(100.);
    fresh.initialize(L100, {}, 0, false);
    refreshed.refresh(L100);
    const unsigned int n_stale     = iterations(L100, c, stale),
                       n_refreshed = iterations(L100, c, refreshed),
                       n_fresh     = iterations(L100, c, fresh);
    Vector<double> v_100(large.n);
    refreshed.vmult(v_100, c);
    // refreshed with the finest level's nonzeros given (shared with the
    // caller, as LinearSolver shares its copy): the same V-cycle bit for
    // bit, and once accepted those nonzeros are the ones kept
    Solvers::AMGPreconditioner shared;
    shared.initialize(L, {}, 0, false);
    shared.accept();
    const bool own_kept = shared.accepted_finest() != nullptr;
    const auto nonzeros = std::make_shared<NonzeroMatrix>();
    nonzeros->copy_from(L100);
    shared.refresh(L100, nonzeros);
    Vector<double> v_shared(large.n);
    shared.vmult(v_shared, c);
    v_shared -= v_100;
    shared.accept();
    deallog << "refreshed with shared nonzeros: the V-cycle bit for bit "
            << (v_shared.l2_norm() == 0.) << "; kept before " << own_kept
            << ", after: the shared ones "
            << (shared.accepted_finest() == nonzeros.get()) << std::endl;
    const bool     restored = refreshed.restore();
    Vector<double> v_restored(large.n);
    refreshed.vmult(v_restored, c);
    difference = v_restored;
    difference -= v_refreshed;
    deallog << "plain aggregation refreshed with its own matrix: levels "
            << refreshed.n_levels() << ", the same V-cycle to 1e-12: " << same
            << "; x couplings 10 times stronger: GMRES iterations to 1e-8 "
            << "with the hierarchy kept " << n_stale << ", refreshed "
            << n_refreshed << ", new " << n_fresh
            << "; refreshed fewer than kept: " << (n_refreshed < n_stale)
            << "; the accepted operators restored: " << restored
            << ", their V-cycle bit for bit: " << (difference.l2_norm() == 0.)
            << ", again: " << refreshed.restore() << std::endl;

    // and a single level (below ML's coarse size of 2 000 rows): the
    // cycle's correction is then the exact solve, and GMRES converges in
    // one or two iterations
    const Laplacian            small(30);
    const SparseMatrix<double> S = small(10.);
    Solvers::AMGPreconditioner one;
    one.initialize(S, {}, 0, true);
    const unsigned int n_one = iterations(S, rhs(small.n), one);
    deallog << "on the 30 x 30 Laplacian: levels " << one.n_levels()
            << ", GMRES iterations to 1e-8 " << n_one << std::endl;
  }

  // GMRES's operator and the AMG cycle's finest level, the tangent's
  // nonzeros in groups of three rows (doc/theory/04-solver.md, 4.5.2), on
  // the 60 x 60 Laplacian with the off-diagonals of every 7th row and
  // column zeroed as constrain_prescribed() leaves them: it keeps the
  // nonzeros and every diagonal, and its products and residuals are those
  // of the matrix bit for bit; taken again after other entries have become
  // zero and zeros nonzero, the same; and on the 61 x 61 Laplacian, whose
  // last group has one row, the same, and its entries are the matrix's.
  void
  nonzero_operator()
  {
    NonzeroMatrix N; // taken anew from each matrix
    // the copy of A taken, its count of entries kept against @p nonzeros, and
    // its products, residuals and entries against A's
    const auto compare = [&N](const SparseMatrix<double> &A,
                              const std::size_t           nonzeros) {
      const unsigned int n = A.m();
      Vector<double>     x(n), b(n), y(n), z(n);
      for (unsigned int k = 0; k < n; ++k)
        {
          x[k] = std::sin(0.37 * k) + 1e-3 * k;
          b[k] = std::cos(0.11 * k);
        }
      N.copy_from(A);
      bool same = N.n_nonzero_elements() == nonzeros;
      A.vmult(y, x);
      N.vmult(z, x);
      for (unsigned int k = 0; k < n; ++k)
        same = same && y[k] == z[k];
      A.residual(y, x, b);
      N.residual(z, x, b);
      for (unsigned int k = 0; k < n; ++k)
        same = same && y[k] == z[k];
      for (unsigned int i = 0; i < n; i += 13)
        for (auto entry = A.begin(i); entry != A.end(i); ++entry)
          same = same && N.el(i, entry->column()) == entry->value();
      return std::make_pair(N.n_nonzero_elements(), same);
    };
    const auto check = [&](const unsigned int m, const unsigned int p) {
      const Laplacian      laplacian(m);
      const unsigned int   n        = laplacian.n;
      SparseMatrix<double> A        = laplacian(10.);
      std::size_t          nonzeros = 0;
      for (unsigned int i = 0; i < n; ++i)
        for (auto entry = A.begin(i); entry != A.end(i); ++entry)
          {
            if (entry->column() != i &&
                (i % p == 0 || entry->column() % p == 0))
              entry->value() = 0.;
            nonzeros += (entry->value() != 0. || entry->column() == i);
          }
      return compare(A, nonzeros);
    };
    // a vector-valued matrix as the tangents store them: each vertex's
    // three rows with the same columns (whole 3 x 3 blocks) on a 40 x 40
    // grid of vertices, its rows and columns of every 7th DoF zeroed but
    // for the diagonal, and the blocks of every 5th vertex pair zeroed (a
    // contact candidate not in contact)
    const auto check_blocks = [&]() {
      const unsigned int     m = 40, n = 3 * m * m;
      DynamicSparsityPattern dsp(n, n);
      const auto             for_each_block = [&](const auto &f) {
        for (unsigned int a = 0; a < m * m; ++a)
          for (const int d :
               {-int(m) - 1, -int(m), -1, 0, 1, int(m), int(m) + 1})
            if (int(a) + d >= 0 && int(a) + d < int(m * m))
              f(a, a + d);
      };
      for_each_block([&](const unsigned int a, const unsigned int b) {
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int e = 0; e < 3; ++e)
            dsp.add(3 * a + c, 3 * b + e);
      });
      SparsityPattern pattern;
      pattern.copy_from(dsp);
      SparseMatrix<double> A(pattern);
      std::size_t          nonzeros = 0;
      for_each_block([&](const unsigned int a, const unsigned int b) {
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int e = 0; e < 3; ++e)
            {
              const unsigned int i = 3 * a + c, j = 3 * b + e;
              double v = std::sin(0.3 * i + 0.7 * j) + (i == j ? 9. : 0.);
              if (i != j && (i % 7 == 0 || j % 7 == 0 || (a + b) % 5 == 0))
                v = 0.;
              A.set(i, j, v);
              nonzeros += (v != 0. || i == j);
            }
      });
      return compare(A, nonzeros);
    };
    const auto [kept_7, same_7]   = check(60, 7);
    const auto [kept_5, same_5]   = check(60, 5);
    const auto [kept_61, same_61] = check(61, 7);
    deallog << "nonzero operator: " << kept_7 << " of "
            << Laplacian(60)(10.).n_nonzero_elements()
            << " entries kept, products bit for bit: " << same_7
            << ", again with other zeros: " << same_5 << " (" << kept_5
            << " kept), with a last group of one row: " << same_61 << " ("
            << kept_61 << " kept)" << std::endl;
    const auto [kept_blocks, same_blocks] = check_blocks();
    deallog << "nonzero operator of 3 x 3 blocks: " << kept_blocks
            << " entries kept, products, residuals and entries bit for bit: "
            << same_blocks << std::endl;
  }

  void
  rigid_body()
  {
    std::ostringstream log;
    const auto         sim = solve(
      "subsection Output\n set Write VTU = false\n set Directory = .\nend\n"
              "subsection Mesh\n set Source = file\n set File = " SOURCE_DIR
      "/../scene/layered_block_v2.msh\nend\n"
              "subsection Bodies\n set Number of bodies = 2\n"
              " subsection Body 0\n  set Material id = 1\n  set Model = Veronda\n"
              "  set Alpha = 7\n  set Beta = 8\n  set a = 100\n end\n"
              " subsection Body 1\n  set Material id = 2\n  set Model = rigid\n"
              "  subsection Rigid motion\n   set Rotation axis = 1, 1, 1\n"
              "   set Rotation center = 0.5, 0.25, 0.3\n   set Rotation angle = 30\n"
              "   set Translation = 0.1, 0, 0\n  end\n end\nend\n"
              "subsection Boundary conditions\n"
              " set Number of Dirichlet conditions = 0\nend\n",
      log);
    const auto &disc = sim->problem().discretization();
    const auto  X    = disc.support_points();
    const auto &body =
      sim->problem().get_scene().parameters.bodies[1].rigid_motion;
    const std::vector<unsigned int> component = disc.dof_components();
    double                          error = 0., u_max = 0.;
    for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
      {
        const double expected = body.displacement(X[i], 1.)[component[i]];
        error = std::max(error, std::abs(sim->solution()[i] - expected));
        u_max = std::max(u_max, std::abs(expected));
      }
    const auto q =
      sim->problem().elastic_assembler().cell_quantities(sim->solution());
    deallog << "rigid skin layer rotated 30 degrees: free muscle follows, "
            << "max |u - rigid motion| / max |u| "
            << error_bound(error / u_max, -10) << ", max von Mises / mu "
            << error_bound(q.von_mises.linfty_norm() / 56., -8) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  patch_test(1);
  patch_test(2);
  cantilever(2, 16);
  cantilever(1, 16);
  rigid_rotation("neo-Hookean");
  rigid_rotation("linear");
  line_search();
  definite_steps();
  quadratic_convergence();
  solvers_agree();
  forcing_term();
  kept_hierarchy();
  gmres_restart();
  stagnation_control();
  direct_fallback();
  cholesky();
  definite_cg();
  threaded_amg();
  nonzero_operator();
  rigid_body();
}
