// A free rigid body (Rigid motion/Free, doc/theory/07) on the bar of
// meshes/two_materials.geo: material 1 on x in [0, 1] is an elastic strap
// clamped on x = 0, material 2 on [1, 2] a rigid block attached to it
// (shared nodes at x = 1), loaded by a dead traction on its face x = 2.
//  - R(theta) and its first and second derivatives against central finite
//    differences, at theta = 0 (the series' expansion point) and at a
//    rotation of 130 degrees;
//  - a linear strap with nu = 0 under an axial traction sigma: the block
//    translates by sigma L / E1 and does not turn (the exact solution,
//    uniaxial stress, is linear in x);
//  - a neo-Hookean strap under an oblique traction that bends it: the
//    block turns; force and moment balance of the whole bar, the clamp's
//    reaction against the load on the block (every element's internal
//    forces have zero resultant and moment, so only the block's
//    condensed equations can fail them);
//  - the condensed tangent against central differences of the condensed
//    residual, at a state away from equilibrium with the block turned;
//  - a Dirichlet condition on the block's face is refused by name.

#include "../tests.h"

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/rigid/rotation.h>
#include <tissue_contact/simulation/static_simulation.h>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  std::string
  strap(const std::string &material,
        const std::string &traction,
        const std::string &extra_conditions = "")
  {
    return "subsection Mesh\n set Source = file\n set File = " +
           std::string(SOURCE_DIR) +
           "/two_materials.msh\nend\n"
           "subsection Bodies\n set Number of bodies = 2\n"
           " subsection Body 0\n  set Name = strap\n  set Material id = 1\n" +
           material +
           " end\n"
           " subsection Body 1\n  set Name = block\n  set Material id = 2\n"
           "  set Model = rigid\n  subsection Rigid motion\n"
           "   set Free = true\n  end\n end\nend\n"
           "subsection Boundary conditions\n"
           " set Number of Dirichlet conditions = " +
           (extra_conditions.empty() ? "1" : "2") +
           "\n set Number of tractions = 1\n"
           " subsection Dirichlet 0\n  set Boundary id = 1\n end\n" +
           extra_conditions +
           " subsection Traction 0\n  set Boundary id = 2\n"
           "  set Traction = " +
           traction +
           "\n end\nend\n"
           "subsection Newton\n set Absolute tolerance = 1e-13\n"
           " set Residual tolerance = 1e-12\nend\n"
           "subsection Output\n set Write VTU = false\n"
           " set Print timing = false\n set Directory = .\nend\n";
  }

  void
  rotation_derivatives()
  {
    Tensor<1, 3> axis({0.3, -0.5, 0.8});
    axis /= axis.norm();
    for (const double degrees : {0., 130.})
      {
        const Tensor<1, 3> theta = degrees * M_PI / 180. * axis;
        const auto         r     = Rigid::rotation(theta);
        // R orthogonal with det 1, and R axis = axis
        const double orthogonality =
          (transpose(r.R) * r.R - unit_symmetric_tensor<3>()).norm();
        const double h  = 1e-5;
        double       e1 = 0., e2 = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          {
            Tensor<1, 3> dk;
            dk[k]                    = h;
            const auto         plus  = Rigid::rotation(theta + dk);
            const auto         minus = Rigid::rotation(theta - dk);
            const Tensor<2, 3> d     = (plus.R - minus.R) / (2. * h);
            e1                       = std::max(e1, (d - r.dR[k]).norm());
            for (unsigned int l = 0; l < 3; ++l)
              e2 = std::max(
                e2,
                ((plus.dR[l] - minus.dR[l]) / (2. * h) - r.d2R[k][l]).norm());
          }
        deallog << "R(theta) at " << degrees << " degrees: |R^T R - I| "
                << error_bound(orthogonality, -15) << ", det R "
                << determinant(r.R) << ", |R a - a| "
                << error_bound((r.R * axis - axis).norm(), -15)
                << "; dR vs differences " << error_bound(e1)
                << ", d2R vs differences of dR " << error_bound(e2)
                << std::endl;
      }
  }

  void
  axial_pull()
  {
    // E1 = 2 mu (nu = 0), L = 1, area 1
    const double     mu = 1.25, E1 = 2. * mu, sigma = 0.01;
    StaticSimulation sim(Scene::SceneParameters::from_string(
                           strap("  set Model = linear\n  set Mu = 1.25\n"
                                 "  set Lambda = 0\n",
                                 "0.01, 0, 0")),
                         deallog.get_file_stream());
    (void)mu;
    const auto   statistics = sim.solve_quietly();
    const auto  &rigid      = *sim.problem().free_rigid_bodies();
    const auto   t          = rigid.translation(sim.solution(), 0);
    const auto   theta      = rigid.rotation_vector(sim.solution(), 0);
    Tensor<1, 3> expected;
    expected[0] = sigma / E1;
    deallog << "linear strap, axial pull: block center at " << rigid.center(0)
            << ", moved by |t - sigma L / E1 e_x| / |t| "
            << error_bound((t - expected).norm() / expected.norm())
            << ", rotation " << error_bound(theta.norm(), -14) << "; "
            << statistics.newton_iterations << " Newton iterations"
            << std::endl;
  }

  void
  oblique_pull()
  {
    const Tensor<1, 3> traction({0.02, 0.05, -0.03}); // on the face x = 2
    StaticSimulation   sim(Scene::SceneParameters::from_string(
                           strap("  set Model = neo-Hookean\n  set Mu = 1\n"
                                   "  set Lambda = 2\n",
                                 "0.02, 0.05, -0.03")),
                         deallog.get_file_stream());
    const auto         statistics = sim.solve_quietly();
    Problem           &problem    = sim.problem();
    const auto        &rigid      = *problem.free_rigid_bodies();
    const auto        &u          = sim.solution();
    const auto         u_fe       = problem.displacement(u);
    const auto        &disc       = problem.discretization();
    const auto         X          = disc.support_points();
    const auto         comp       = disc.dof_components();
    const auto        &f_ext = problem.elastic_assembler().external_force();

    // R_fe = f_int - f_ext over the finite element DoFs
    Vector<double> R_fe;
    problem.elastic_assembler().assemble(u_fe, 1., R_fe, nullptr);
    Tensor<1, 3> F_clamp, M_clamp, F_load, M_load;
    for (unsigned int i = 0; i < X.size(); ++i)
      {
        Tensor<1, 3> e;
        e[comp[i]] = 1.;
        Point<3> x = X[i];
        for (unsigned int j = 0; j < X.size(); ++j)
          if (X[j] == X[i])
            x[comp[j]] += u_fe[j];
        if (std::abs(X[i][0]) < 1e-12) // clamped: the support force is R_fe
          {
            F_clamp += R_fe[i] * e;
            M_clamp += cross_product_3d(x, R_fe[i] * e);
          }
        F_load += f_ext[i] * e;
        M_load += cross_product_3d(x, f_ext[i] * e);
      }
    deallog << "neo-Hookean strap, oblique pull: block turned by " << std::fixed
            << std::setprecision(2)
            << rigid.rotation_vector(u, 0).norm() * 180. / M_PI
            << " degrees, center moved by " << std::setprecision(4)
            << rigid.translation(u, 0) << std::defaultfloat
            << std::setprecision(6) << "; load " << F_load << " (traction "
            << traction << " on area 1)" << std::endl
            << "  force balance |F_clamp + F_load| / |F_load| "
            << error_bound((F_clamp + F_load).norm() / F_load.norm())
            << ", moment balance |M_clamp + M_load| / |M_load| "
            << error_bound((M_clamp + M_load).norm() / M_load.norm()) << "; "
            << statistics.newton_iterations << " Newton iterations"
            << std::endl;

    // the tangent at a state away from equilibrium, block turned further
    const auto        n = problem.n_dofs();
    Vector<double>    u0(u), d(n);
    std::vector<bool> fixed(n, false);
    for (const auto &p : problem.prescribed_values(1.))
      fixed[p.first] = true;
    for (unsigned int i = 0; i < n; ++i)
      if (!fixed[i] && (i >= disc.n_dofs() || !rigid.is_slave(i)))
        {
          d[i] = random_value(-1., 1.);
          u0[i] += 0.02 * random_value(-1., 1.);
        }
    const auto q = rigid.first_unknown(0);
    u0[q + 3] += 0.4;
    u0[q + 4] -= 0.7;
    u0[q + 5] += 0.3;
    SparseMatrix<double> K(problem.sparsity_pattern());
    Vector<double>       R0, Rp, Rm, Kd(n);
    problem.assemble(u0, 1., R0, &K);
    K.vmult(Kd, d);
    const double   h = 1e-6;
    Vector<double> up(u0), um(u0);
    up.add(h, d);
    um.add(-h, d);
    problem.assemble(up, 1., Rp, nullptr);
    problem.assemble(um, 1., Rm, nullptr);
    Vector<double> fd(Rp);
    fd -= Rm;
    fd /= 2. * h;
    fd -= Kd;
    double asymmetry = 0., norm = 0.;
    for (unsigned int i = 0; i < n; ++i)
      for (auto e = K.begin(i); e != K.end(i); ++e)
        {
          asymmetry =
            std::max(asymmetry, std::abs(e->value() - K.el(e->column(), i)));
          norm = std::max(norm, std::abs(e->value()));
        }
    deallog << "condensed tangent at rotation " << std::setprecision(3)
            << rigid.rotation_vector(u0, 0).norm() * 180. / M_PI
            << std::setprecision(6)
            << " degrees: |K d - central difference| / |K d| "
            << error_bound(fd.l2_norm() / Kd.l2_norm()) << ", max |K - K^T| / "
            << "max |K| " << error_bound(asymmetry / norm, -15) << std::endl;
  }

  void
  prescribed_block_face()
  {
    try
      {
        const Problem problem(Scene::SceneParameters::from_string(
          strap("  set Model = linear\n  set Mu = 1\n  set Lambda = 0\n",
                "0.01, 0, 0",
                " subsection Dirichlet 1\n  set Boundary id = 2\n end\n")));
        deallog << "a Dirichlet condition on the block: accepted (wrong)"
                << std::endl;
      }
    catch (const std::exception &e)
      {
        deallog << "a Dirichlet condition on the block: " << error_message(e)
                << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  rotation_derivatives();
  axial_pull();
  oblique_pull();
  prescribed_block_face();
}
