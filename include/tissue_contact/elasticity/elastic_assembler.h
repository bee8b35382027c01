#pragma once

#include <tissue_contact/base/discretization.h>
#include <tissue_contact/elasticity/nodal_pressure.h>
#include <tissue_contact/elasticity/single_rotation.h>
#include <tissue_contact/materials/hyperelastic_material.h>
#include <tissue_contact/materials/material.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <map>
#include <memory>

namespace TissueContact
{
  namespace Elasticity
  {
    /**
     * What the volume of one body (a material id) contributes: its material
     * (or none for a rigid body, whose cells are skipped because all its
     * DoFs are prescribed) and its reference density @f$\rho_0@f$.
     */
    struct BodyData
    {
      const Materials::Material *material = nullptr;
      double                     density  = 0.;
      /** Whether gravity and tractions act on the body's cells: true for
       * deformable and free rigid bodies, false for a body whose motion is
       * prescribed (its loads would only enter the reactions). */
      bool loaded = true;
      /** Where the volume term @f$U(J)@f$ of an uncoupled material is
       * integrated: in the material (at the quadrature points), at the
       * vertices (doc/theory/08-nodal-pressure.md) or as the element's mean
       * dilatation (doc/theory/09-mean-dilatation.md). In the last two the
       * material evaluates the isochoric energy alone. */
      enum class VolumeTerm
      {
        in_material,
        nodal_average,
        element_average
      };
      VolumeTerm volume_term = VolumeTerm::in_material;
      /** The bulk modulus @f$\kappa@f$ of @f$U@f$ where volume_term is not
       * in_material. */
      double bulk_modulus = 0.;
      /** Whether the body's elements are single-rotation elements
       * (doc/theory/10-single-rotation.md): linear elasticity with the
       * material's Lame constants in the frame of one rotation per element,
       * from its corner vertices (tet10SR on P2 meshes). */
      bool single_rotation = false;
    };

    /** Dead external loads at load factor 1: body force per unit mass and
     * reference tractions @f$t_0@f$ per boundary id. */
    struct DeadLoads
    {
      Tensor<1, 3>                               gravity;
      std::map<types::boundary_id, Tensor<1, 3>> tractions;
    };

    /** Cell averages of derived fields, for output. */
    struct CellQuantities
    {
      Vector<double>                J, strain_energy_density, von_mises;
      std::array<Vector<double>, 6> cauchy_stress; // xx yy zz yz xz xy
    };

    /**
     * The volume weak form of finite-strain elasticity
     * (doc/theory/02-weak-form-and-linearization.md):
     * @f[ R_{ai}(u,\lambda) = \int_{\Omega_0} P_{iJ}(F)\,
     *       \partial_J N_a \,dV - \lambda f^{\rm ext}_{ai}, \qquad
     *   f^{\rm ext}_{ai} = \int_{\Omega_0}\rho_0 g_i N_a\,dV
     *       + \int_{\Gamma_t} t_{0,i} N_a\,dA, @f]
     * its exact tangent
     * @f$K_{ai,bk} = \int \partial_J N_a\,\mathcal{A}_{iJkL}\,
     *    \partial_L N_b\,dV@f$ (@f$=K_c + K_\sigma@f$), and the total
     * potential energy
     * @f$\Pi(u,\lambda) = \int\Psi(F)\,dV - \lambda f^{\rm ext}\cdot u@f$,
     * whose gradient the residual is. Assembly runs on all cores: each
     * thread adds the cells' entries in its own range of rows where few
     * cells have unknowns in two ranges (splits_rows()), else WorkStream
     * with one thread adding at a time. Vectors and matrices are assembled
     * without constraints; the solver imposes prescribed values. Bodies with
     * BodyData::VolumeTerm::nodal_average have their volume term at the
     * vertices (NodalPressure, doc/theory/08-nodal-pressure.md): the
     * elements get the mean vertex pressure, the tangent the vertex
     * stiffness, whose couplings sparsity_pattern() contains. Bodies with
     * BodyData::VolumeTerm::element_average have it as
     * @f$V_e U(\bar J_e)@f$ of each element's mean dilatation
     * @f$\bar J_e = v_e / V_e@f$ (doc/theory/09-mean-dilatation.md): the
     * element's pressure @f$\bar p_e = U'(\bar J_e)@f$ in its stress and a
     * rank-one term in its tangent. Bodies with BodyData::single_rotation
     * are assembled element by element by SingleRotationElement, whose
     * stiffness matrices are computed once here.
     */
    class ElasticAssembler
    {
    public:
      ElasticAssembler(const Discretization                         &disc,
                       const std::map<types::material_id, BodyData> &bodies,
                       const DeadLoads                              &loads);

      /**
       * Compute @p R and, when @p K is not null, the tangent at the
       * displacement @p u and load factor @p load_factor. @p K's sparsity
       * pattern must contain the discretization's. Returns false, leaving R
       * and K unspecified, if @f$\det F \le 0@f$ at a quadrature point of
       * any deformable cell (an inverted element).
       */
      bool
      assemble(const Vector<double> &u,
               const double          load_factor,
               Vector<double>       &R,
               SparseMatrix<double> *K) const;

      /**
       * Whether assemble() splits the rows of R and K among the threads at
       * the current thread count (each thread adds the cells' entries in
       * its range of rows; the same sums to the last bit as on one thread,
       * doc/theory/02-weak-form-and-linearization.md sec. 2.3), rather
       * than adding every cell's entries on one thread at a time.
       */
      bool
      splits_rows() const;

      /**
       * Find, once, where each cell's tangent entries lie in the value
       * array of a matrix built on @p pattern (SparsityPattern::operator()).
       * assemble() then adds a cell's entries at these positions instead of
       * searching every row for its columns; a row widened by contact
       * couplings made that search most of the elastic assembly. Call again
       * whenever @p pattern changes; a matrix on another pattern, or on
       * this one after its number of entries changed, is assembled by
       * searching as before. The offsets are stored within each row: a
       * row with the columns it had in the pattern of the last call keeps
       * them in every cell, and only the rows the contact couplings changed
       * are searched again.
       */
      void
      use_matrix_pattern(const SparsityPattern &pattern);

      /**
       * The sparsity pattern of the tangent this assembler writes: the
       * discretization's, widened by the vertex-stiffness couplings where a
       * body's volume term is at the vertices.
       */
      const SparsityPattern &
      sparsity_pattern() const
      {
        return nodal ? widened_pattern : disc.sparsity_pattern;
      }

      /** The vertex pressure @f$p_a@f$ of bodies whose volume term is at
       * the vertices, per mesh vertex (0 elsewhere); empty if there are
       * none. */
      std::vector<double>
      vertex_pressure(const Vector<double> &u) const;

      /** @f$\Pi(u,\lambda)@f$, or +infinity if an element is inverted. */
      double
      energy(const Vector<double> &u, const double load_factor) const;

      /** The external force vector at load factor 1. */
      const Vector<double> &
      external_force() const
      {
        return f_ext;
      }

      /** The mean of @f$|\Omega_e|^{1/3}@f$ over the deformable cells
       * (0 if there are none). */
      double
      mean_element_size() const
      {
        return element_size;
      }

      /** Smallest @f$\det F@f$ over quadrature points of deformable cells. */
      double
      min_jacobian(const Vector<double> &u) const;

      /**
       * The quasi-viscosity diagonal of dissertation eq. (4.48)-(4.51):
       * @f$D_{ai} = \eta\sum_{e\ni a} \mu_e h_e / n_e@f$ with the element
       * size @f$h_e = |\Omega_e|^{1/3}@f$, its small-strain shear modulus
       * @f$\mu_e@f$ and @f$n_e@f$ nodes per element, so that @f$\eta@f$ is
       * a dimensionless fraction of the stiffness diagonal.
       */
      Vector<double>
      quasi_viscosity_diagonal(const double eta) const;

      /** Per-cell averages of @f$J@f$, Cauchy stress
       * @f$\sigma = J^{-1} P F^T@f$, von Mises stress and @f$\Psi@f$. */
      CellQuantities
      cell_quantities(const Vector<double> &u) const;

    private:
      const Discretization                        &disc;
      const std::map<types::material_id, BodyData> bodies;
      Vector<double>                               f_ext;

      /**
       * Reference geometry, computed once: the configuration of a total
       * Lagrangian formulation never changes, so the shape gradients
       * @f$\nabla_X N_a@f$, weights @f$JxW@f$ and points of every
       * quadrature point of every cell are stored instead of re-running
       * FEValues in every assembly (the hot loop touches only these arrays).
       */
      unsigned int                         n_q, n_nodes, n_local;
      double                               element_size = 0.;
      std::vector<Tensor<1, 3>>            grad_N;    // [cell][q][node]
      std::vector<double>                  JxW;       // [cell][q]
      std::vector<Point<3>>                X_q;       // [cell][q]
      std::vector<types::global_dof_index> cell_dofs; // [cell][k]
      // cell_dofs in ascending order, and the local index of each
      std::vector<types::global_dof_index>     sorted_dofs;   // [cell][j]
      std::vector<unsigned char>               sorted_local;  // [cell][j]
      std::vector<const Materials::Material *> cell_material; // null: rigid
      std::vector<const Materials::HyperelasticMaterial *> cell_hyperelastic;
      std::vector<unsigned int> local_component, local_node; // of dof k
      std::vector<unsigned int> deformable_cells;
      // kappa of each cell whose volume term is its mean dilatation, 0 for
      // the others; empty if there are none
      std::vector<double> mean_dilatation_kappa;
      // single-rotation elements: index per cell (-1: not one), and per
      // index the linear-elastic stiffness [n_local^2], the reference node
      // positions [n_nodes] and corner gradients [4] (doc/theory/10)
      std::vector<int>          single_rotation_index;
      std::vector<double>       single_rotation_K;
      std::vector<Point<3>>     single_rotation_X;
      std::vector<Tensor<1, 3>> single_rotation_grad;

      /** The single-rotation element of cell @p c, and the current
       * positions of its nodes at @p u in @p x. */
      SingleRotationElement
      single_rotation_element(const unsigned int    c,
                              const Vector<double> &u,
                              Point<3>             *x) const;

      // offsets of cell c's entry (i, j) in the values of row dofs[i] of a
      // matrix on positions_pattern, from the row's first value:
      // [c][i * n_local + j] (use_matrix_pattern())
      std::vector<unsigned int> positions;
      const SparsityPattern    *positions_pattern = nullptr;
      std::size_t               positions_entries = 0;
      // the rows the positions were found in: each row's first position
      // [n_rows + 1] and the columns, in the pattern's order
      std::vector<std::size_t>             positions_row_start;
      std::vector<types::global_dof_index> positions_columns;
      // the same per row and node, where each node's three DoFs are
      // consecutive and so are its columns in every row (empty otherwise):
      // [c][i * (n_nodes + 1) + b] the offset of column 3 b (of the first
      // column after the diagonal for row i's own node), [.. + n_nodes] the
      // diagonal's; a third of the offsets to read per cell
      std::vector<unsigned int> node_positions;

      // per cell its lowest and highest unknown
      std::vector<std::array<types::global_dof_index, 2>> cell_dof_range;

      /**
       * The rows of R and K split among threads (base/row_ranges.h): the
       * bounds of @p n_parts ranges of rows with about equal numbers of
       * (cell, row) incidences. A thread computes every cell with an
       * unknown in its rows; not usable (assemble() then adds every cell
       * on one thread) where that would compute more than 5/4 of the cells
       * in all: where many cells have unknowns in several ranges.
       */
      struct RowSplit
      {
        unsigned int                         n_parts = 0;
        bool                                 usable  = false;
        std::vector<types::global_dof_index> bounds;
      };

      RowSplit
      row_split(const unsigned int n_parts) const;

      // the split for the thread count at construction
      RowSplit split;

      // the volume term at the vertices: null if no body has it
      std::unique_ptr<NodalPressure> nodal;
      std::vector<int>               nodal_element; // [cell]: index or -1
      std::vector<unsigned int>      nodal_cells;   // [index]: cell
      SparsityPattern                widened_pattern;

      /** The vertex state at @p u; false in @p valid if an element of
       * such a body is inverted. */
      NodalPressure::State
      nodal_state(const Vector<double> &u, bool &valid) const;

      /** @f$\bar J_e = v_e / V_e@f$ of cell @p c (doc/theory/09, (D1)) and
       * its reference volume @p V; 0 if @f$\det F \le 0@f$ at one of its
       * quadrature points. */
      double
      mean_dilatation(const unsigned int    c,
                      const Vector<double> &u,
                      double               &V) const;

      /** @f$F = I + \sum_k u_k\, e_{c_k}\otimes\nabla N_{a_k}@f$ at
       * quadrature point @p q of cell @p c. */
      Tensor<2, 3>
      deformation_gradient(const unsigned int    c,
                           const unsigned int    q,
                           const Vector<double> &u) const;

      const BodyData *
      body(const types::material_id id) const;
    };
  } // namespace Elasticity
} // namespace TissueContact
