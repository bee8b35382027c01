// Continuity of the contact force (dissertation 6.3, 6.5): two tetrahedra
// share a face, their interpolated material depths have different
// gradients. A tilted triangle slides across the shared face in steps of
// 1e-3. The area-integrated force on the triangle changes by O(step) from
// step to step; the point-collocation force jumps whenever one of the
// triangle's vertices crosses the face. The kernels are the hand-derived
// ones the contact assembler uses (contact/penalty_kernel.h).

#include "../tests.h"

#include <tissue_contact/contact/penalty_kernel.h>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main()
{
  initlog();
  const Point<3> A(0, 0, 0), B(1, 0, 0), C(0, 1, 0), D1(0.25, 0.25, 1.),
    D2(0.25, 0.25, -1.);
  const std::array<Point<3>, 4> K1 = {A, B, C, D1}, K2 = {A, C, B, D2};
  const std::array<double, 4>   g1 = {0.2, 0.3, 0.25, 0.9},
                              g2   = {0.2, 0.25, 0.3, 0.4}; // same A, B, C
  const double eps                 = 100.;

  const unsigned int n_steps = 600;
  const double       step    = 0.6 / n_steps;
  for (const bool collocation : {false, true})
    {
      Tensor<1, 3> previous;
      double       max_jump = 0., max_force = 0., jump_at = 0.;
      for (unsigned int i = 0; i <= n_steps; ++i)
        {
          const double                  z0  = 0.3 - i * step;
          const std::array<Point<3>, 3> tri = {Point<3>(0.2, 0.2, z0 - 0.1),
                                               Point<3>(0.35, 0.2, z0 + 0.05),
                                               Point<3>(0.2, 0.35, z0 + 0.1)};
          Tensor<1, 3>                  force;
          for (const auto &[K, g] :
               {std::make_pair(K1, g1), std::make_pair(K2, g2)})
            {
              Contact::PairKernel d;
              const bool          hit =
                collocation ?
                           Contact::collocation_kernel(K, tri, g, eps, false, d) :
                           Contact::penalty_kernel(K, tri, g, eps, false, d);
              if (!hit)
                continue;
              for (unsigned int a = 0; a < 3; ++a)
                for (unsigned int c = 0; c < 3; ++c)
                  force[c] -= d.gradient[12 + 3 * a + c];
            }
          max_force = std::max(max_force, force.norm());
          if (i > 0 && (force - previous).norm() > max_jump)
            {
              max_jump = (force - previous).norm();
              jump_at  = z0;
            }
          previous = force;
        }
      deallog << (collocation ? "point collocation" : "area integration ")
              << ": largest change of the force between steps of " << step
              << ": " << std::setprecision(2) << max_jump / max_force
              << " of the largest force, at z0 = " << jump_at
              << std::setprecision(6) << std::endl;
    }
}
