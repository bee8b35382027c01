// Mass matrices of two bodies with densities 2 and 3 on [0,1] x [0,1]^2
// and [1,2] x [0,1]^2, P1 and P2:
//  - consistent: symmetric; a rigid translation carries the total mass
//    (1^T M 1 = 5 per component); u = x e_1 gives u^T M u = int rho x^2 =
//    23/3 (exact: the quadrature integrates degree 2p);
//  - lumped (HRZ): the same total per component, all entries positive
//    (P2 too, where row sums give the vertices zero or negative mass), and
//    equal to the row sums for P1.

#include "../tests.h"

#include <tissue_contact/dynamics/mass_matrix.h>

#include <deal.II/grid/grid_generator.h>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main()
{
  initlog();
  Triangulation<3> tria;
  GridGenerator::subdivided_hyper_rectangle_with_simplices(tria,
                                                           {4, 2, 2},
                                                           Point<3>(0, 0, 0),
                                                           Point<3>(2, 1, 1));
  for (const auto &cell : tria.active_cell_iterators())
    cell->set_material_id(cell->center()[0] < 1. ? 1 : 2);
  const std::map<types::material_id, Elasticity::BodyData> bodies = {
    {1, {nullptr, 2.}}, {2, {nullptr, 3.}}};

  for (const unsigned int degree : {1u, 2u})
    {
      Discretization       disc(tria, degree);
      SparseMatrix<double> M(disc.sparsity_pattern);
      Dynamics::assemble_consistent_mass(disc, bodies, M);
      const Vector<double> lumped    = Dynamics::lumped_mass(disc, bodies);
      const auto           component = disc.dof_components();
      const auto           X         = disc.support_points();

      double asymmetry = 0.;
      for (auto it = M.begin(); it != M.end(); ++it)
        asymmetry =
          std::max(asymmetry,
                   std::abs(it->value() - M.el(it->column(), it->row())));
      Vector<double> ones(disc.n_dofs()), x(disc.n_dofs()), Mv(disc.n_dofs()),
        row_sum(disc.n_dofs());
      for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
        if (component[i] == 0)
          {
            ones[i] = 1.;
            x[i]    = X[i][0];
          }
      M.vmult(Mv, ones);
      const double translation = ones * Mv;
      M.vmult(Mv, x);
      const double   second_moment = x * Mv;
      double         lumped_total = 0., lumped_min = 1e300, row_error = 0.;
      Vector<double> all(disc.n_dofs());
      all = 1.;
      M.vmult(row_sum, all);
      for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
        {
          if (component[i] == 0)
            lumped_total += lumped[i];
          lumped_min = std::min(lumped_min, lumped[i]);
          row_error  = std::max(row_error, std::abs(lumped[i] - row_sum[i]));
        }
      double row_min = 1e300;
      for (const double r : row_sum)
        row_min = std::min(row_min, r);
      deallog << "P" << degree << ": |M - M^T| " << error_bound(asymmetry, -14)
              << ", 1^T M 1 - 5 "
              << error_bound(std::abs(translation - 5.), -12)
              << ", x^T M x - 23/3 "
              << error_bound(std::abs(second_moment - 23. / 3.), -12)
              << std::endl;
      deallog << "    lumped: total - 5 "
              << error_bound(std::abs(lumped_total - 5.), -12)
              << ", smallest entry "
              << (lumped_min > 0. ? "positive" : "NOT positive")
              << ", smallest row sum of M "
              << (row_min > 0. ? "positive" : "not positive")
              << ", |lumped - row sums| "
              << (degree == 1 ? error_bound(row_error, -12) :
                                "= " + scientific(row_error, 3))
              << std::endl;
    }
}
