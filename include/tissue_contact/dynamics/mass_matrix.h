#pragma once

#include <tissue_contact/base/discretization.h>
#include <tissue_contact/elasticity/elastic_assembler.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <map>

namespace TissueContact
{
  namespace Dynamics
  {
    using namespace dealii;

    /**
     * The consistent mass matrix of the vector-valued space
     * (doc/theory/06-dynamics.md, sec. 1):
     * @f[ M_{ij} = \int_{\Omega_0} \rho_0\, N_i \cdot N_j \, dV, @f]
     * with the reference density of each body (material id); cells of
     * bodies with zero density contribute nothing. @p M must use the
     * discretization's sparsity pattern (or a larger one).
     */
    void
    assemble_consistent_mass(
      const Discretization                                     &disc,
      const std::map<types::material_id, Elasticity::BodyData> &bodies,
      SparseMatrix<double>                                     &M);

    /**
     * The lumped (diagonal) mass by HRZ lumping: on every cell the
     * diagonal of the consistent element matrix, scaled so that each
     * component keeps the cell's mass @f$\rho_0 V_e@f$. For P1 this equals
     * the row sum (@f$\rho_0 V_e/4@f$ per vertex); for P2, where row sums
     * give the vertices zero or negative mass, every entry stays positive.
     */
    Vector<double>
    lumped_mass(
      const Discretization                                     &disc,
      const std::map<types::material_id, Elasticity::BodyData> &bodies);

    /**
     * The stable step of the explicit central difference scheme estimated
     * from element sizes and wave speeds (doc/theory/06-dynamics.md, sec.
     * 4): the smallest over the cells with positive density of
     * @f$h_e/(p\,c_e)@f$, with @f$h_e = 3V_e/A_{e,\max}@f$ the smallest
     * altitude, p the polynomial degree and
     * @f$c_e = \sqrt{(\lambda + 2\mu)/\rho_0}@f$ the dilatational wave
     * speed of the body's small-strain Lame parameters.
     */
    double
    stable_time_step_estimate(
      const Discretization                                     &disc,
      const std::map<types::material_id, Elasticity::BodyData> &bodies);
  } // namespace Dynamics
} // namespace TissueContact
