#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>

#include <array>
#include <vector>

namespace TissueContact
{
  namespace Elasticity
  {
    using namespace dealii;

    /**
     * The volume term of uncoupled bodies integrated at the vertices of a P1
     * mesh: the average nodal pressure tetrahedron, written as an energy
     * (doc/theory/08-nodal-pressure.md, (N1)-(N5)). A vertex group is a
     * vertex of one body (material id), with the reference volume
     * @f$V^0_a = \frac14\sum_{e\ni a}V^0_e@f$ of its share of the body's
     * elements around it, its volume ratio
     * @f$J_a = \frac14\sum_{e\ni a}V^0_eJ_e / V^0_a@f$ and its pressure
     * @f$p_a = U'(J_a)@f$. ElasticAssembler adds the element terms (the mean
     * vertex pressure @f$\bar p_e@f$ in each element's stress and initial
     * stress tangent); this class owns the vertex groups, the energy
     * @f$\sum_a V^0_aU(J_a)@f$, the vertex stiffness
     * @f$K_\kappa = \sum_a U''(J_a)/V^0_a\,b_a\otimes b_a@f$ and the
     * sparsity couplings it needs.
     */
    class NodalPressure
    {
    public:
      /** A P1 element of a body whose volume term is at the vertices. */
      struct Element
      {
        types::material_id body = 0;
        /** Reference volume @f$V^0_e@f$. */
        double V0 = 0.;
        /** The body's bulk modulus @f$\kappa@f$. */
        double kappa = 0.;
        /** Global vertex index of each of the four vertices. */
        std::array<unsigned int, 4> vertices;
        /** DoF of displacement component i at vertex a: [a * 3 + i]. */
        std::array<types::global_dof_index, 12> dofs;
      };

      /** Vertex volume ratios and pressures at one displacement. */
      struct State
      {
        std::vector<double> J, p; // per vertex group
      };

      /** Build the vertex groups of @p elements (in the order given; the
       * other functions index elements in this order). */
      explicit NodalPressure(std::vector<Element> elements);

      unsigned int
      n_elements() const
      {
        return elements.size();
      }

      /** Number of vertex groups. */
      unsigned int
      n_groups() const
      {
        return group_V0.size();
      }

      /** @f$J_a@f$ and @f$p_a@f$ from the elements' @f$J_e@f$ (all
       * positive). */
      State
      state(const std::vector<double> &J_e) const;

      /** @f$\bar p_e = \frac14\sum_{a\in e}p_a@f$ of element @p k. */
      double
      element_pressure(const State &state, const unsigned int k) const;

      /** @f$\frac14\sum_{a\in e}U(J_a)@f$: element @p k's share of the
       * volume energy per unit reference volume. */
      double
      element_energy_density(const State &state, const unsigned int k) const;

      /** @f$\sum_a V^0_a\,U(J_a)@f$. */
      double
      energy(const State &state) const;

      /**
       * Add @f$K_\kappa@f$ (N4) to @p K, given
       * @p dv[k][b] @f$=\partial v_e/\partial x_b = V^0_e\operatorname{cof}
       * (F_e)\,\nabla N_b@f$ of every element. @p K's pattern must contain
       * add_couplings()'s.
       */
      void
      add_tangent(const State                                    &state,
                  const std::vector<std::array<Tensor<1, 3>, 4>> &dv,
                  SparseMatrix<double>                           &K) const;

      /** Add the couplings of @f$K_\kappa@f$: every pair of DoFs of the
       * elements around a vertex group. */
      void
      add_couplings(DynamicSparsityPattern &dsp) const;

      /** The pressure at every vertex of the mesh (@p n_vertices entries):
       * @f$p_a@f$, averaged by @f$V^0_a@f$ where a vertex belongs to two
       * bodies, 0 where it belongs to none. */
      std::vector<double>
      vertex_pressure(const State &state, const unsigned int n_vertices) const;

    private:
      std::vector<Element> elements;
      // group of vertex a of element k: [k * 4 + a]
      std::vector<unsigned int> element_group;
      std::vector<double>       group_V0, group_kappa;
      std::vector<unsigned int> group_vertex;
      // the DoFs of each group's patch, sorted: [patch_start[g],
      // patch_start[g + 1])
      std::vector<unsigned int>            patch_start;
      std::vector<types::global_dof_index> patch_dofs;
      // the elements around each group: [member_start[g], member_start[g +
      // 1])
      std::vector<unsigned int> member_start, members;
      // the patch position of DoF [b * 3 + i] of each member's element
      std::vector<std::array<unsigned short, 12>> member_positions;
    };
  } // namespace Elasticity
} // namespace TissueContact
