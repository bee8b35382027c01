#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <limits>
#include <tissue_contact/elasticity/elastic_assembler.h>

namespace TissueContact
{
  namespace Elasticity
  {
    namespace
    {
      /** Per-thread scratch: FEValues and the displacement gradients. */
      struct ScratchData
      {
        ScratchData(const Discretization &disc, const UpdateFlags flags)
          : fe_values(disc.mapping, disc.fe, disc.quadrature, flags)
          , grad_u(disc.quadrature.size())
          , component(disc.fe.n_dofs_per_cell())
        {
          for (unsigned int k = 0; k < disc.fe.n_dofs_per_cell(); ++k)
            component[k] = disc.fe.system_to_component_index(k).first;
        }
        ScratchData(const ScratchData &other)
          : fe_values(other.fe_values.get_mapping(),
                      other.fe_values.get_fe(),
                      other.fe_values.get_quadrature(),
                      other.fe_values.get_update_flags())
          , grad_u(other.grad_u)
          , component(other.component)
        {
        }

        FEValues<3>               fe_values;
        std::vector<Tensor<2, 3>> grad_u;
        std::vector<unsigned int> component;
      };

      struct CopyData
      {
        FullMatrix<double>                   K;
        Vector<double>                       r;
        std::vector<types::global_dof_index> dofs;
        bool                                 valid  = true;
        bool                                 active = false;
        double                               value  = 0.;
      };

      const FEValuesExtractors::Vector displacement(0);
    } // namespace


    ElasticAssembler::ElasticAssembler(
      const Discretization                         &disc,
      const std::map<types::material_id, BodyData> &bodies,
      const DeadLoads                              &loads)
      : disc(disc)
      , bodies(bodies)
      , f_ext(disc.n_dofs())
    {
      // f_ext = int rho0 g N dV + int t0 N dA (dead loads, computed once)
      FEValues<3>                          fe_values(disc.mapping,
                            disc.fe,
                            disc.quadrature,
                            update_values | update_JxW_values);
      FEFaceValues<3>                      fe_face_values(disc.mapping,
                                     disc.fe,
                                     disc.face_quadrature,
                                     update_values | update_JxW_values);
      const unsigned int                   n = disc.fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs(n);
      Vector<double>                       local(n);
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          const BodyData *b = body(cell->material_id());
          if (b->material == nullptr)
            continue;
          local = 0.;
          if (b->density != 0. && loads.gravity.norm() > 0.)
            {
              fe_values.reinit(cell);
              for (unsigned int q = 0; q < disc.quadrature.size(); ++q)
                for (unsigned int k = 0; k < n; ++k)
                  {
                    const unsigned int c =
                      disc.fe.system_to_component_index(k).first;
                    local[k] += b->density * loads.gravity[c] *
                                fe_values.shape_value(k, q) * fe_values.JxW(q);
                  }
            }
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const auto t =
                  loads.tractions.find(cell->face(f)->boundary_id());
                if (t == loads.tractions.end())
                  continue;
                fe_face_values.reinit(cell, f);
                for (unsigned int q = 0; q < disc.face_quadrature.size(); ++q)
                  for (unsigned int k = 0; k < n; ++k)
                    {
                      const unsigned int c =
                        disc.fe.system_to_component_index(k).first;
                      local[k] += t->second[c] *
                                  fe_face_values.shape_value(k, q) *
                                  fe_face_values.JxW(q);
                    }
              }
          cell->get_dof_indices(dofs);
          f_ext.add(dofs, local);
        }
    }


    const BodyData *
    ElasticAssembler::body(const types::material_id id) const
    {
      const auto it = bodies.find(id);
      Assert(it != bodies.end(),
             ExcMessage("no body data for material id " + std::to_string(id)));
      return &it->second;
    }


    bool
    ElasticAssembler::assemble(const Vector<double> &u,
                               const double          load_factor,
                               Vector<double>       &R,
                               SparseMatrix<double> *K) const
    {
      R.reinit(disc.n_dofs());
      if (K != nullptr)
        *K = 0.;
      bool               valid = true;
      const unsigned int n     = disc.fe.n_dofs_per_cell();

      const auto worker = [&](const auto &cell, ScratchData &s, CopyData &c) {
        const BodyData *b = body(cell->material_id());
        c.active          = (b->material != nullptr);
        if (!c.active)
          return;
        c.valid = true;
        c.dofs.resize(n);
        cell->get_dof_indices(c.dofs);
        c.r.reinit(n);
        if (K != nullptr)
          c.K.reinit(n, n);
        s.fe_values.reinit(cell);
        s.fe_values[displacement].get_function_gradients(u, s.grad_u);

        Materials::MaterialResponse m;
        std::vector<Tensor<2, 3>>   B(n); // B_k = dN_k,J A_{c_k J . .}
        for (unsigned int q = 0; q < disc.quadrature.size(); ++q)
          {
            const Tensor<2, 3> F = unit_symmetric_tensor<3>() + s.grad_u[q];
            if (!(determinant(F) > 0.))
              {
                c.valid = false;
                return;
              }
            const double    JxW = s.fe_values.JxW(q);
            const Point<3> &X   = s.fe_values.quadrature_point(q);
            if (K == nullptr)
              m.P = b->material->first_piola_kirchhoff(F, X);
            else
              b->material->evaluate(F, X, m);

            for (unsigned int k = 0; k < n; ++k)
              {
                const unsigned int  ck = s.component[k];
                const Tensor<1, 3> &g  = s.fe_values.shape_grad(k, q);
                c.r[k] += (m.P[ck] * g) * JxW;
                if (K != nullptr)
                  for (unsigned int l = 0; l < 3; ++l)
                    for (unsigned int L = 0; L < 3; ++L)
                      B[k][l][L] = g[0] * m.A[ck][0][l][L] +
                                   g[1] * m.A[ck][1][l][L] +
                                   g[2] * m.A[ck][2][l][L];
              }
            if (K != nullptr)
              for (unsigned int k = 0; k < n; ++k)
                for (unsigned int l = k; l < n; ++l)
                  c.K(k, l) +=
                    (B[k][s.component[l]] * s.fe_values.shape_grad(l, q)) * JxW;
          }
        if (K != nullptr)
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int l = 0; l < k; ++l)
              c.K(k, l) = c.K(l, k);
      };

      const auto copier = [&](const CopyData &c) {
        if (!c.active)
          return;
        if (!c.valid)
          {
            valid = false;
            return;
          }
        R.add(c.dofs, c.r);
        if (K != nullptr)
          K->add(c.dofs, c.K);
      };

      const UpdateFlags flags =
        update_gradients | update_JxW_values | update_quadrature_points;
      WorkStream::run(disc.dof_handler.begin_active(),
                      disc.dof_handler.end(),
                      worker,
                      copier,
                      ScratchData(disc, flags),
                      CopyData());
      if (valid)
        R.add(-load_factor, f_ext);
      return valid;
    }


    double
    ElasticAssembler::energy(const Vector<double> &u,
                             const double          load_factor) const
    {
      ScratchData s(disc,
                    update_gradients | update_JxW_values |
                      update_quadrature_points);
      double      W = 0.;
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          const BodyData *b = body(cell->material_id());
          if (b->material == nullptr)
            continue;
          s.fe_values.reinit(cell);
          s.fe_values[displacement].get_function_gradients(u, s.grad_u);
          for (unsigned int q = 0; q < disc.quadrature.size(); ++q)
            {
              const Tensor<2, 3> F = unit_symmetric_tensor<3>() + s.grad_u[q];
              if (!(determinant(F) > 0.))
                return std::numeric_limits<double>::infinity();
              W += b->material->energy(F, s.fe_values.quadrature_point(q)) *
                   s.fe_values.JxW(q);
            }
        }
      return W - load_factor * (f_ext * u);
    }


    double
    ElasticAssembler::min_jacobian(const Vector<double> &u) const
    {
      ScratchData s(disc, update_gradients);
      double      J_min = std::numeric_limits<double>::max();
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          if (body(cell->material_id())->material == nullptr)
            continue;
          s.fe_values.reinit(cell);
          s.fe_values[displacement].get_function_gradients(u, s.grad_u);
          for (const auto &H : s.grad_u)
            J_min =
              std::min(J_min, determinant(unit_symmetric_tensor<3>() + H));
        }
      return J_min;
    }


    Vector<double>
    ElasticAssembler::quasi_viscosity_diagonal(const double eta) const
    {
      Vector<double>                       D(disc.n_dofs());
      FEValues<3>                          fe_values(disc.mapping,
                            disc.fe,
                            disc.quadrature,
                            update_JxW_values);
      const unsigned int                   n = disc.fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs(n);
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          const BodyData *b = body(cell->material_id());
          if (b->material == nullptr)
            continue;
          fe_values.reinit(cell);
          double volume = 0.;
          for (unsigned int q = 0; q < disc.quadrature.size(); ++q)
            volume += fe_values.JxW(q);
          const double mu_e = b->material->lame_equivalents().first;
          const double value =
            eta * mu_e * std::cbrt(volume) / (n / 3); // n/3 nodes per cell
          cell->get_dof_indices(dofs);
          for (const auto i : dofs)
            D[i] += value;
        }
      return D;
    }


    CellQuantities
    ElasticAssembler::cell_quantities(const Vector<double> &u) const
    {
      const unsigned int n_cells =
        disc.dof_handler.get_triangulation().n_active_cells();
      CellQuantities out;
      out.J.reinit(n_cells);
      out.strain_energy_density.reinit(n_cells);
      out.von_mises.reinit(n_cells);
      for (auto &v : out.cauchy_stress)
        v.reinit(n_cells);

      ScratchData        s(disc,
                    update_gradients | update_JxW_values |
                      update_quadrature_points);
      const unsigned int voigt[6][2] = {
        {0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          const unsigned int i = cell->active_cell_index();
          const BodyData    *b = body(cell->material_id());
          s.fe_values.reinit(cell);
          s.fe_values[displacement].get_function_gradients(u, s.grad_u);
          double       volume = 0., J = 0., psi = 0.;
          Tensor<2, 3> sigma;
          for (unsigned int q = 0; q < disc.quadrature.size(); ++q)
            {
              const Tensor<2, 3> F  = unit_symmetric_tensor<3>() + s.grad_u[q];
              const double       Jq = determinant(F);
              const double       w  = s.fe_values.JxW(q);
              volume += w;
              J += Jq * w;
              if (b->material != nullptr && Jq > 0.)
                {
                  const Point<3> &X = s.fe_values.quadrature_point(q);
                  psi += b->material->energy(F, X) * w;
                  sigma += b->material->first_piola_kirchhoff(F, X) *
                           transpose(F) * (w / Jq);
                }
            }
          out.J[i]                     = J / volume;
          out.strain_energy_density[i] = psi / volume;
          sigma /= volume;
          for (unsigned int c = 0; c < 6; ++c)
            out.cauchy_stress[c][i] = sigma[voigt[c][0]][voigt[c][1]];
          const Tensor<2, 3> dev =
            sigma - trace(sigma) / 3. * unit_symmetric_tensor<3>();
          out.von_mises[i] = std::sqrt(1.5 * scalar_product(dev, dev));
        }
      return out;
    }
  } // namespace Elasticity
} // namespace TissueContact
