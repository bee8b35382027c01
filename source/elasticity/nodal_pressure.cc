#include <tissue_contact/elasticity/nodal_pressure.h>
#include <tissue_contact/materials/uncoupled_material.h>

#include <algorithm>
#include <map>
#include <utility>

namespace TissueContact
{
  namespace Elasticity
  {
    NodalPressure::NodalPressure(std::vector<Element> elements_in)
      : elements(std::move(elements_in))
    {
      // one group per (vertex, body)
      std::map<std::pair<unsigned int, types::material_id>, unsigned int>
        group_of;
      element_group.resize(elements.size() * 4);
      for (unsigned int k = 0; k < elements.size(); ++k)
        for (unsigned int a = 0; a < 4; ++a)
          {
            const auto key =
              std::make_pair(elements[k].vertices[a], elements[k].body);
            const auto it = group_of.emplace(key, group_V0.size()).first;
            if (it->second == group_V0.size())
              {
                group_V0.push_back(0.);
                group_kappa.push_back(elements[k].kappa);
                group_vertex.push_back(key.first);
              }
            element_group[k * 4 + a] = it->second;
            group_V0[it->second] += 0.25 * elements[k].V0;
          }

      // the elements around each group (CSR)
      const unsigned int n = group_V0.size();
      member_start.assign(n + 1, 0);
      for (const unsigned int g : element_group)
        ++member_start[g + 1];
      for (unsigned int g = 0; g < n; ++g)
        member_start[g + 1] += member_start[g];
      members.resize(member_start[n]);
      {
        std::vector<unsigned int> next(member_start.begin(),
                                       member_start.end() - 1);
        for (unsigned int k = 0; k < elements.size(); ++k)
          for (unsigned int a = 0; a < 4; ++a)
            members[next[element_group[k * 4 + a]]++] = k;
      }

      // each group's patch: the sorted DoFs of its elements, and where each
      // element DoF lies in it
      patch_start.assign(1, 0);
      member_positions.resize(members.size());
      std::vector<types::global_dof_index> patch;
      for (unsigned int g = 0; g < n; ++g)
        {
          patch.clear();
          for (unsigned int m = member_start[g]; m < member_start[g + 1]; ++m)
            patch.insert(patch.end(),
                         elements[members[m]].dofs.begin(),
                         elements[members[m]].dofs.end());
          std::sort(patch.begin(), patch.end());
          patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
          AssertThrow(patch.size() < 65536, ExcNotImplemented());
          for (unsigned int m = member_start[g]; m < member_start[g + 1]; ++m)
            for (unsigned int j = 0; j < 12; ++j)
              member_positions[m][j] =
                std::lower_bound(patch.begin(),
                                 patch.end(),
                                 elements[members[m]].dofs[j]) -
                patch.begin();
          patch_dofs.insert(patch_dofs.end(), patch.begin(), patch.end());
          patch_start.push_back(patch_dofs.size());
        }
    }


    NodalPressure::State
    NodalPressure::state(const std::vector<double> &J_e) const
    {
      AssertDimension(J_e.size(), elements.size());
      State s;
      s.J.assign(n_groups(), 0.);
      s.p.resize(n_groups());
      // J_a = v_a / V0_a, v_a = 1/4 sum_e V0_e J_e   (N1)
      for (unsigned int k = 0; k < elements.size(); ++k)
        for (unsigned int a = 0; a < 4; ++a)
          s.J[element_group[k * 4 + a]] += 0.25 * elements[k].V0 * J_e[k];
      for (unsigned int g = 0; g < n_groups(); ++g)
        {
          s.J[g] /= group_V0[g];
          s.p[g] = Materials::VolumetricEnergy{group_kappa[g]}.dU(s.J[g]);
        }
      return s;
    }


    double
    NodalPressure::element_pressure(const State       &state,
                                    const unsigned int k) const
    {
      const unsigned int *g = &element_group[k * 4];
      return 0.25 *
             (state.p[g[0]] + state.p[g[1]] + state.p[g[2]] + state.p[g[3]]);
    }


    double
    NodalPressure::element_energy_density(const State       &state,
                                          const unsigned int k) const
    {
      double U = 0.;
      for (unsigned int a = 0; a < 4; ++a)
        {
          const unsigned int g = element_group[k * 4 + a];
          U += Materials::VolumetricEnergy{group_kappa[g]}.U(state.J[g]);
        }
      return 0.25 * U;
    }


    double
    NodalPressure::energy(const State &state) const
    {
      double W = 0.;
      for (unsigned int g = 0; g < n_groups(); ++g)
        W += group_V0[g] *
             Materials::VolumetricEnergy{group_kappa[g]}.U(state.J[g]);
      return W;
    }


    void
    NodalPressure::add_tangent(
      const State                                    &state,
      const std::vector<std::array<Tensor<1, 3>, 4>> &dv,
      SparseMatrix<double>                           &K) const
    {
      AssertDimension(dv.size(), elements.size());
      std::vector<double> b, row;
      for (unsigned int g = 0; g < n_groups(); ++g)
        {
          // b_a = dv_a/dx = 1/4 sum_{e ni a} dv_e/dx   (N4)
          const unsigned int n = patch_start[g + 1] - patch_start[g];
          const types::global_dof_index *dofs = &patch_dofs[patch_start[g]];
          b.assign(n, 0.);
          row.resize(n);
          for (unsigned int m = member_start[g]; m < member_start[g + 1]; ++m)
            {
              const auto &v = dv[members[m]];
              for (unsigned int j = 0; j < 12; ++j)
                b[member_positions[m][j]] += 0.25 * v[j / 3][j % 3];
            }
          // K_kappa += U''(J_a) / V0_a b_a (x) b_a
          const double c =
            Materials::VolumetricEnergy{group_kappa[g]}.ddU(state.J[g]) /
            group_V0[g];
          for (unsigned int i = 0; i < n; ++i)
            {
              const double ci = c * b[i];
              for (unsigned int j = 0; j < n; ++j)
                row[j] = ci * b[j];
              K.add(dofs[i], n, dofs, row.data(), false, true);
            }
        }
    }


    void
    NodalPressure::add_couplings(DynamicSparsityPattern &dsp) const
    {
      for (unsigned int g = 0; g < n_groups(); ++g)
        {
          const types::global_dof_index *begin = &patch_dofs[patch_start[g]];
          const types::global_dof_index *end =
            &patch_dofs[0] + patch_start[g + 1];
          for (const types::global_dof_index *row = begin; row != end; ++row)
            dsp.add_entries(*row, begin, end, true);
        }
    }


    std::vector<double>
    NodalPressure::vertex_pressure(const State       &state,
                                   const unsigned int n_vertices) const
    {
      std::vector<double> p(n_vertices, 0.), V(n_vertices, 0.);
      for (unsigned int g = 0; g < n_groups(); ++g)
        {
          p[group_vertex[g]] += group_V0[g] * state.p[g];
          V[group_vertex[g]] += group_V0[g];
        }
      for (unsigned int v = 0; v < n_vertices; ++v)
        if (V[v] > 0.)
          p[v] /= V[v];
      return p;
    }
  } // namespace Elasticity
} // namespace TissueContact
