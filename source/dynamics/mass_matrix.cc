#include <tissue_contact/dynamics/mass_matrix.h>

#include <deal.II/fe/fe_values.h>

#include <limits>

namespace TissueContact
{
  namespace Dynamics
  {
    namespace
    {
      /** Call @p f(cell, local matrix, local dofs) with the consistent
       * element mass matrix of every cell with positive density. */
      template <typename F>
      void
      for_each_cell_mass(
        const Discretization                                     &disc,
        const std::map<types::material_id, Elasticity::BodyData> &bodies,
        const F                                                  &f)
      {
        FEValues<3>                          fe_values(disc.mapping,
                              disc.fe,
                              disc.quadrature,
                              update_values | update_JxW_values);
        const unsigned int                   n = disc.fe.n_dofs_per_cell();
        FullMatrix<double>                   m(n, n);
        std::vector<types::global_dof_index> dofs(n);
        for (const auto &cell : disc.dof_handler.active_cell_iterators())
          {
            const auto body = bodies.find(cell->material_id());
            if (body == bodies.end() || !(body->second.density > 0.))
              continue;
            const double rho = body->second.density;
            fe_values.reinit(cell);
            cell->get_dof_indices(dofs);
            m = 0.;
            for (const unsigned int q : fe_values.quadrature_point_indices())
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int ci =
                    disc.fe.system_to_component_index(i).first;
                  for (unsigned int j = 0; j < n; ++j)
                    if (disc.fe.system_to_component_index(j).first == ci)
                      m(i, j) += rho * fe_values.shape_value(i, q) *
                                 fe_values.shape_value(j, q) * fe_values.JxW(q);
                }
            f(cell, m, dofs);
          }
      }
    } // namespace


    void
    assemble_consistent_mass(
      const Discretization                                     &disc,
      const std::map<types::material_id, Elasticity::BodyData> &bodies,
      SparseMatrix<double>                                     &M)
    {
      M = 0.;
      for_each_cell_mass(disc,
                         bodies,
                         [&](const auto &,
                             const FullMatrix<double>                   &m,
                             const std::vector<types::global_dof_index> &dofs) {
                           M.add(dofs, m);
                         });
    }


    Vector<double>
    lumped_mass(
      const Discretization                                     &disc,
      const std::map<types::material_id, Elasticity::BodyData> &bodies)
    {
      Vector<double> m_lumped(disc.n_dofs());
      for_each_cell_mass(disc,
                         bodies,
                         [&](const auto &,
                             const FullMatrix<double>                   &m,
                             const std::vector<types::global_dof_index> &dofs) {
                           // per component: the cell's mass (sum of all entries
                           // of that component's block) over the sum of the
                           // block's diagonal
                           std::array<double, 3> total{}, diagonal{};
                           for (unsigned int i = 0; i < m.m(); ++i)
                             {
                               const unsigned int c =
                                 disc.fe.system_to_component_index(i).first;
                               diagonal[c] += m(i, i);
                               for (unsigned int j = 0; j < m.n(); ++j)
                                 total[c] += m(i, j);
                             }
                           for (unsigned int i = 0; i < m.m(); ++i)
                             {
                               const unsigned int c =
                                 disc.fe.system_to_component_index(i).first;
                               m_lumped[dofs[i]] +=
                                 m(i, i) * total[c] / diagonal[c];
                             }
                         });
      return m_lumped;
    }


    double
    stable_time_step_estimate(
      const Discretization                                     &disc,
      const std::map<types::material_id, Elasticity::BodyData> &bodies)
    {
      double dt = std::numeric_limits<double>::infinity();
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          const auto body = bodies.find(cell->material_id());
          if (body == bodies.end() || !(body->second.density > 0.) ||
              body->second.material == nullptr)
            continue;
          const auto [mu, lambda] = body->second.material->lame_equivalents();
          const double c = std::sqrt((lambda + 2. * mu) / body->second.density);
          double       largest_face = 0.;
          for (const auto &face : cell->face_iterators())
            largest_face = std::max(largest_face, face->measure());
          const double h = 3. * cell->measure() / largest_face;
          dt             = std::min(dt, h / (disc.degree * c));
        }
      return dt;
    }
  } // namespace Dynamics
} // namespace TissueContact
