#pragma once

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace TissueContact
{
  using namespace dealii;

  /**
   * The finite element space of the displacement: vector-valued
   * @f$P_p@f$ tetrahedra, @c FESystem<3>(FE_SimplexP<3>(p), 3) with
   * @f$p\in\{1,2\}@f$, the affine simplex mapping, Gauss quadratures exact
   * for the mass matrix (@f$2p@f$) in cells and faces, the quadrature of the
   * strain energy, its residual and tangent (P1: one point at the centroid,
   * exact, since F is constant in a linear tetrahedron and so is every
   * integrand, the dead body force's N too being integrated exactly; P2:
   * the same rule as the mass matrix, 14 points, or 6 points exact to
   * degree 3 when reduced), the DoF handler and the sparsity
   * pattern of the stiffness matrix.
   *
   * On request the DoFs are numbered support point by support point in
   * Cuthill-McKee order (renumber_by_points()): neighbouring points get
   * nearby numbers, so the rows a cell's entries go to, and the vector
   * entries a matrix row reads, lie close together in memory
   * (doc/theory/02-weak-form-and-linearization.md sec. 2.3).
   */
  class Discretization
  {
  public:
    /** Distribute DoFs of degree @p degree on @p triangulation (which must
     * outlive this object). With @p reduced_quadrature, P2's stiffness
     * quadrature has 6 points (exact to degree 3) instead of 14 (degree
     * 5). With @p renumber, the DoFs are numbered by
     * renumber_by_points(). */
    Discretization(const Triangulation<3> &triangulation,
                   const unsigned int      degree,
                   const bool              reduced_quadrature = false,
                   const bool              renumber           = false);

    const unsigned int     degree;
    const FESystem<3>      fe;
    const MappingFE<3>     mapping;
    const QGaussSimplex<3> quadrature;
    const QGaussSimplex<3> stiffness_quadrature;
    const QGaussSimplex<2> face_quadrature;
    DoFHandler<3>          dof_handler;
    SparsityPattern        sparsity_pattern;

    /**
     * Number the DoFs support point by support point in the Cuthill-McKee
     * order of the points' graph (two points joined where a cell holds
     * both), each point's x, y, z DoFs kept together as 3 g, 3 g + 1,
     * 3 g + 2 as distribute_dofs() gave them, and build the sparsity
     * pattern anew; left as they are if they are not so grouped. Returns
     * whether it renumbered. Call it before anything is built on the DoFs.
     */
    bool
    renumber_by_points();

    /** Whether the DoFs are numbered by renumber_by_points(). */
    bool points_renumbered = false;

    /** The sparsity pattern of the DoFs as they are numbered. */
    void
    make_sparsity_pattern();

    /** Number of displacement unknowns. */
    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }

    /** Reference position of the support point of every DoF. */
    std::vector<Point<3>>
    support_points() const;

    /** The displacement component (0, 1, 2) of every DoF. */
    std::vector<unsigned int>
    dof_components() const;

    /** For every DoF, the three DoFs (x, y, z) at its support point. */
    std::vector<std::array<types::global_dof_index, 3>>
    support_point_dofs() const;

    /** The mean @f$\bar X@f$ of the support points of all DoFs. */
    Point<3>
    mean_support_point() const;

    /**
     * The six rigid-body modes of the displacement field, the near-null
     * space of elasticity: the translations @f$e_c@f$ (c = 0, 1, 2), then
     * the infinitesimal rotations @f$e_a \times (X - \bar X)@f$ about the
     * axes through the mean support point @f$\bar X@f$ (a = 0, 1, 2), as
     * values at every DoF (n_dofs() entries each).
     */
    std::vector<Vector<double>>
    rigid_body_modes() const;
  };
} // namespace TissueContact
