#include <tissue_contact/base/polar_rotation.h>
#include <tissue_contact/base/row_ranges.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/materials/uncoupled_material.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <numeric>

namespace TissueContact
{
  namespace Elasticity
  {
    namespace
    {
      using Materials::VoigtTangent;

      /** Per-thread work space of the cell kernel. */
      struct ScratchData
      {
        // per node a: the spatial gradient n_a = F^-T grad N_a, the three
        // columns of c b_a (stored [p * 3 + k]) and tau n_a
        std::vector<Tensor<1, 3>>           n;
        std::vector<std::array<double, 18>> cb;
        std::vector<Tensor<1, 3>>           tau_n;
        // dv_e/dx_a of the mean dilatation (doc/theory/09, (D2))
        std::vector<Tensor<1, 3>> dv;
        // the material's response at a point (each evaluation sets what
        // the kernel reads: kept here, not zeroed for every cell)
        Materials::MaterialResponse m;
        VoigtTangent                CC;
        // whether this thread writes the cell's own outputs (dv_e/dx_b of
        // a vertex-pressure element): a cell with unknowns in two threads'
        // rows is computed by both, and written by one
        bool primary = true;
      };

      struct CopyData
      {
        FullMatrix<double> K;
        Vector<double>     r;
        unsigned int       cell  = 0;
        bool               valid = true;
        /** only K's node blocks (a, b) with a <= b are set: the copier adds
         * each block of the lower part as the transpose of its mirror */
        bool upper = false;
      };

      /**
       * Add the element terms of a pressure @f$\bar p@f$ constant over the
       * element, the mean of its vertex pressures ((N3), (N5) of
       * doc/theory/08-nodal-pressure.md) or its mean dilatation's
       * ((D3), (D4) of doc/theory/09-mean-dilatation.md), in the spatial
       * form of the assembly: @f$S_p = \bar p J C^{-1}@f$ and
       * @f$\mathbb{C}_p = \bar p J (C^{-1}\otimes C^{-1} - 2 C^{-1}\odot
       * C^{-1})@f$ pushed forward, @f$\tau_p = \bar p J I@f$ and, when
       * @p c is not null, @f$c_p = \bar p J (I\otimes I - 2\,I\odot I)@f$
       * (doc/theory/03-materials.md, (M3S)).
       */
      void
      add_pressure(const double pJ, SymmetricTensor<2, 3> &tau, VoigtTangent *c)
      {
        for (unsigned int i = 0; i < 3; ++i)
          tau[i][i] += pJ;
        if (c == nullptr)
          return;
        for (unsigned int p = 0; p < 6; ++p)
          {
            if (p < 3)
              for (unsigned int q = 0; q < 3; ++q)
                c->D[p][q] += pJ;
            c->D[p][p] -= p < 3 ? 2. * pJ : pJ;
          }
      }

      /**
       * The values of @p K as one array in the order of its sparsity
       * pattern, which the positions of use_matrix_pattern() index:
       * SparseMatrix stores them so, the first being the first stored entry
       * of the first row.
       */
      double *
      value_array(SparseMatrix<double> &K)
      {
        const auto first = K.get_sparsity_pattern().begin();
        AssertThrow(first->global_index() == 0, ExcInternalError());
        return &K(first->row(), first->column());
      }
    } // namespace


    ElasticAssembler::ElasticAssembler(
      const Discretization                         &disc,
      const std::map<types::material_id, BodyData> &bodies,
      const DeadLoads                              &loads)
      : disc(disc)
      , bodies(bodies)
      , f_ext(disc.n_dofs())
      , n_q(disc.stiffness_quadrature.size())
      , n_nodes(disc.fe.base_element(0).n_dofs_per_cell())
      , n_local(disc.fe.n_dofs_per_cell())
    {
      for (unsigned int k = 0; k < n_local; ++k)
        {
          local_component.push_back(disc.fe.system_to_component_index(k).first);
          local_node.push_back(disc.fe.system_to_component_index(k).second);
          // the kernels index the element matrix node by node: local dof
          // 3 a + i is component i of node a, as FESystem numbers one base
          // element of multiplicity 3
          AssertThrow(local_component[k] == k % 3 && local_node[k] == k / 3,
                      ExcInternalError());
        }

      // reference geometry of every cell, and f_ext = int rho0 g N dV +
      // int t0 N dA (dead loads)
      const unsigned int n_cells =
        disc.dof_handler.get_triangulation().n_active_cells();
      grad_N.resize(std::size_t(n_cells) * n_q * n_nodes);
      JxW.resize(std::size_t(n_cells) * n_q);
      X_q.resize(std::size_t(n_cells) * n_q);
      cell_dofs.resize(std::size_t(n_cells) * n_local);
      sorted_dofs.resize(std::size_t(n_cells) * n_local);
      sorted_local.resize(std::size_t(n_cells) * n_local);
      AssertThrow(n_local < 256, ExcNotImplemented());
      cell_material.resize(n_cells);
      cell_hyperelastic.resize(n_cells);

      FEValues<3>     fe_values(disc.mapping,
                            disc.fe,
                            disc.stiffness_quadrature,
                            update_values | update_gradients |
                              update_JxW_values | update_quadrature_points);
      FEFaceValues<3> fe_face_values(disc.mapping,
                                     disc.fe,
                                     disc.face_quadrature,
                                     update_values | update_JxW_values);
      // the reference positions of the nodes (single-rotation elements)
      FEValues<3> support_values(
        disc.mapping,
        disc.fe,
        Quadrature<3>(disc.fe.base_element(0).get_unit_support_points()),
        update_quadrature_points);
      std::vector<types::global_dof_index> dofs(n_local);
      Vector<double>                       local(n_local);
      std::vector<NodalPressure::Element>  nodal_elements;
      nodal_element.assign(n_cells, -1);
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          const unsigned int c = cell->active_cell_index();
          const BodyData    *b = body(cell->material_id());
          cell->get_dof_indices(dofs);
          std::copy(dofs.begin(), dofs.end(), &cell_dofs[c * n_local]);
          // ascending global order: SparseMatrix::add() then merges each
          // row in one pass instead of searching the sparsity pattern for
          // every entry (that search took 80 % of the assembly time)
          std::vector<unsigned int> order(n_local);
          std::iota(order.begin(), order.end(), 0u);
          std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
            return dofs[a] < dofs[b];
          });
          for (unsigned int j = 0; j < n_local; ++j)
            {
              sorted_dofs[c * n_local + j]  = dofs[order[j]];
              sorted_local[c * n_local + j] = order[j];
            }
          cell_material[c] = b->material;
          cell_hyperelastic[c] =
            dynamic_cast<const Materials::HyperelasticMaterial *>(b->material);
          if (b->material != nullptr)
            deformable_cells.push_back(c);

          fe_values.reinit(cell);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              JxW[c * n_q + q] = fe_values.JxW(q);
              X_q[c * n_q + q] = fe_values.quadrature_point(q);
            }
          for (unsigned int k = 0; k < n_local; ++k)
            if (local_component[k] == 0)
              for (unsigned int q = 0; q < n_q; ++q)
                grad_N[(c * n_q + q) * n_nodes + local_node[k]] =
                  fe_values.shape_grad(k, q);

          if (b->material != nullptr && b->single_rotation)
            {
              // K_e of linear elasticity, the nodes and corner gradients
              // (doc/theory/10, (SR1))
              AssertThrow(n_nodes >= 4 && n_local == 3 * n_nodes,
                          ExcInternalError());
              single_rotation_index.resize(n_cells, -1);
              const unsigned int k     = single_rotation_X.size() / n_nodes;
              single_rotation_index[c] = k;
              support_values.reinit(cell);
              for (unsigned int I = 0; I < n_nodes; ++I)
                single_rotation_X.push_back(support_values.quadrature_point(I));
              single_rotation_grad.resize(4 * (k + 1));
              SingleRotationElement::corner_gradients(
                &single_rotation_X[k * n_nodes], &single_rotation_grad[4 * k]);
              const auto lame = b->material->lame_equivalents();
              single_rotation_K.resize(std::size_t(k + 1) * n_local * n_local);
              SingleRotationElement::stiffness(
                n_nodes,
                n_q,
                &grad_N[std::size_t(c) * n_q * n_nodes],
                &JxW[std::size_t(c) * n_q],
                lame.first,
                lame.second,
                &single_rotation_K[std::size_t(k) * n_local * n_local]);
            }

          using VolumeTerm = BodyData::VolumeTerm;
          if (b->material != nullptr &&
              b->volume_term == VolumeTerm::element_average)
            {
              AssertThrow(cell_hyperelastic[c] != nullptr &&
                            b->bulk_modulus > 0,
                          ExcInternalError());
              mean_dilatation_kappa.resize(n_cells, 0.);
              mean_dilatation_kappa[c] = b->bulk_modulus;
            }
          if (b->material != nullptr &&
              b->volume_term == VolumeTerm::nodal_average)
            {
              AssertThrow(disc.degree == 1 && n_q == 1 && n_nodes == 4,
                          ExcMessage(
                            "Volumetric term = nodal average (material id " +
                            std::to_string(cell->material_id()) +
                            ") integrates the volume term at the vertices of "
                            "linear tetrahedra: it needs Discretization/"
                            "Polynomial degree = 1 (on P2 meshes use "
                            "Volumetric term = element average)"));
              AssertThrow(cell_hyperelastic[c] != nullptr, ExcInternalError());
              NodalPressure::Element e;
              e.body  = cell->material_id();
              e.V0    = fe_values.JxW(0);
              e.kappa = b->bulk_modulus;
              for (unsigned int k = 0; k < n_local; ++k)
                e.dofs[local_node[k] * 3 + local_component[k]] = dofs[k];
              for (unsigned int a = 0; a < 4; ++a)
                e.vertices[a] = cell->vertex_index(a);
              nodal_element[c] = nodal_elements.size();
              nodal_cells.push_back(c);
              nodal_elements.push_back(e);
            }

          if (!b->loaded)
            continue;
          local = 0.;
          if (b->density != 0. && loads.gravity.norm() > 0.)
            for (unsigned int q = 0; q < n_q; ++q)
              for (unsigned int k = 0; k < n_local; ++k)
                local[k] += b->density * loads.gravity[local_component[k]] *
                            fe_values.shape_value(k, q) * fe_values.JxW(q);
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const auto t =
                  loads.tractions.find(cell->face(f)->boundary_id());
                if (t == loads.tractions.end())
                  continue;
                fe_face_values.reinit(cell, f);
                for (unsigned int q = 0; q < disc.face_quadrature.size(); ++q)
                  for (unsigned int k = 0; k < n_local; ++k)
                    local[k] += t->second[local_component[k]] *
                                fe_face_values.shape_value(k, q) *
                                fe_face_values.JxW(q);
              }
          f_ext.add(dofs, local);
        }

      // the cells in the order of their lowest DoF where the DoFs are
      // numbered point by point in Cuthill-McKee order (Discretization):
      // cells that follow each other share rows of the tangent, and the
      // scatter below finds them in the cache; few cells then have unknowns
      // in two threads' ranges of rows (row_split(); doc/theory/02-weak-
      // form-and-linearization.md sec. 2.3)
      if (disc.points_renumbered)
        {
          std::vector<types::global_dof_index> lowest(n_cells);
          for (unsigned int c = 0; c < n_cells; ++c)
            lowest[c] = *std::min_element(&cell_dofs[c * n_local],
                                          &cell_dofs[c * n_local] + n_local);
          std::stable_sort(deformable_cells.begin(),
                           deformable_cells.end(),
                           [&](const unsigned int a, const unsigned int b) {
                             return lowest[a] < lowest[b];
                           });
        }
      for (const unsigned int c : deformable_cells)
        {
          double volume = 0.;
          for (unsigned int q = 0; q < n_q; ++q)
            volume += JxW[c * n_q + q];
          element_size += std::cbrt(volume);
        }
      if (!deformable_cells.empty())
        element_size /= deformable_cells.size();
      cell_dof_range.resize(n_cells);
      for (unsigned int c = 0; c < n_cells; ++c)
        {
          const auto range =
            std::minmax_element(&cell_dofs[c * n_local],
                                &cell_dofs[c * n_local] + n_local);
          cell_dof_range[c] = {{*range.first, *range.second}};
        }
      split = row_split(n_row_ranges());

      if (!nodal_elements.empty())
        {
          nodal = std::make_unique<NodalPressure>(std::move(nodal_elements));
          DynamicSparsityPattern dsp(disc.n_dofs());
          DoFTools::make_sparsity_pattern(disc.dof_handler, dsp);
          nodal->add_couplings(dsp);
          widened_pattern.copy_from(dsp);
        }
    }


    NodalPressure::State
    ElasticAssembler::nodal_state(const Vector<double> &u, bool &valid) const
    {
      std::vector<double> J(nodal_cells.size());
      for (unsigned int k = 0; k < nodal_cells.size(); ++k)
        {
          J[k] = determinant(deformation_gradient(nodal_cells[k], 0, u));
          if (!(J[k] > 0.))
            {
              valid = false;
              return {};
            }
        }
      return nodal->state(J);
    }


    std::vector<double>
    ElasticAssembler::vertex_pressure(const Vector<double> &u) const
    {
      const unsigned int n_vertices =
        disc.dof_handler.get_triangulation().n_vertices();
      if (!nodal)
        return {};
      bool       valid = true;
      const auto state = nodal_state(u, valid);
      return valid ? nodal->vertex_pressure(state, n_vertices) :
                     std::vector<double>(n_vertices, 0.);
    }


    double
    ElasticAssembler::mean_dilatation(const unsigned int    c,
                                      const Vector<double> &u,
                                      double               &V) const
    {
      double v = 0.;
      V        = 0.;
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const double J = determinant(deformation_gradient(c, q, u));
          if (!(J > 0.))
            return 0.;
          v += J * JxW[c * n_q + q];
          V += JxW[c * n_q + q];
        }
      return v / V;
    }


    const BodyData *
    ElasticAssembler::body(const types::material_id id) const
    {
      const auto it = bodies.find(id);
      Assert(it != bodies.end(),
             ExcMessage("no body data for material id " + std::to_string(id)));
      return &it->second;
    }


    Tensor<2, 3>
    ElasticAssembler::deformation_gradient(const unsigned int    c,
                                           const unsigned int    q,
                                           const Vector<double> &u) const
    {
      Tensor<2, 3>                   F    = unit_symmetric_tensor<3>();
      const Tensor<1, 3>            *g    = &grad_N[(c * n_q + q) * n_nodes];
      const types::global_dof_index *dofs = &cell_dofs[c * n_local];
      for (unsigned int k = 0; k < n_local; ++k)
        F[local_component[k]] += u[dofs[k]] * g[local_node[k]];
      return F;
    }


    SingleRotationElement
    ElasticAssembler::single_rotation_element(const unsigned int    c,
                                              const Vector<double> &u,
                                              Point<3>             *x) const
    {
      const unsigned int             k    = single_rotation_index[c];
      const Point<3>                *X    = &single_rotation_X[k * n_nodes];
      const types::global_dof_index *dofs = &cell_dofs[c * n_local];
      for (unsigned int I = 0; I < n_nodes; ++I)
        x[I] = X[I];
      for (unsigned int j = 0; j < n_local; ++j)
        x[local_node[j]][local_component[j]] += u[dofs[j]];
      return SingleRotationElement(
        n_nodes,
        &single_rotation_K[std::size_t(k) * n_local * n_local],
        X,
        &single_rotation_grad[4 * k]);
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
      bool valid = true;

      // the vertex pressures first: every element of such a body needs
      // the mean of its four (N3)
      NodalPressure::State                     vertex_state;
      std::vector<std::array<Tensor<1, 3>, 4>> dv; // dv_e/dx_b per element
      if (nodal)
        {
          vertex_state = nodal_state(u, valid);
          if (!valid)
            return false;
          if (K != nullptr)
            dv.resize(nodal->n_elements());
        }

      const bool by_position =
        K != nullptr && &K->get_sparsity_pattern() == positions_pattern &&
        K->n_nonzero_elements() == positions_entries;
      const auto worker = [&](
                            const std::vector<unsigned int>::const_iterator &it,
                            ScratchData                                     &s,
                            CopyData &copy) {
        const unsigned int c = *it;
        copy.cell            = c;
        copy.valid           = true;
        copy.r.reinit(n_local);
        const Materials::HyperelasticMaterial *hyper = cell_hyperelastic[c];
        const bool                             single_rotation =
          !single_rotation_index.empty() && single_rotation_index[c] >= 0;
        const double kappa_e =
          mean_dilatation_kappa.empty() ? 0. : mean_dilatation_kappa[c];
        // a hyperelastic cell without the mean dilatation's term writes
        // its node blocks (a, b), a <= b, once (below), and the copier
        // adds the lower ones as their mirrors' transposes: its matrix is
        // neither zeroed nor mirrored (the scatter of the rest needs both)
        copy.upper = by_position && hyper != nullptr && !single_rotation &&
                     !(kappa_e > 0.);
        if (copy.upper)
          copy.K.TableBase<2, double>::reinit(TableIndices<2>(n_local, n_local),
                                              true);
        else if (K != nullptr)
          copy.K.reinit(n_local, n_local);
        // the element matrix, row by row (local dof 3 a + i: node a,
        // component i)
        double *const Kc = K != nullptr ? &copy.K(0, 0) : nullptr;
        s.n.resize(n_nodes);
        s.cb.resize(n_nodes);
        s.tau_n.resize(n_nodes);

        const Materials::Material   *material = cell_material[c];
        Materials::MaterialResponse &m        = s.m;
        SymmetricTensor<2, 3>        tau;
        VoigtTangent                &CC = s.CC;

        if (single_rotation)
          {
            // one rotation per element (doc/theory/10, (SR4), (SR5));
            // inverted where det F <= 0 at a point, as the others
            std::array<Point<3>, 10>    x;
            std::array<double, 30>      r;
            std::array<double, 30 * 30> H;
            const SingleRotationElement e =
              single_rotation_element(c, u, x.data());
            for (unsigned int q = 0; q < n_q; ++q)
              if (!(determinant(deformation_gradient(c, q, u)) > 0.))
                copy.valid = false;
            if (!copy.valid || !e.gradient(x.data(),
                                           r.data(),
                                           K != nullptr ? H.data() : nullptr))
              {
                copy.valid = false;
                return;
              }
            for (unsigned int p = 0; p < n_local; ++p)
              {
                copy.r[p] = r[p];
                if (K != nullptr)
                  for (unsigned int q = 0; q < n_local; ++q)
                    copy.K(p, q) = H[p * n_local + q];
              }
            return;
          }

        // the mean dilatation's pressure and U''/V_e (doc/theory/09)
        double p_e = 0., ddU_V = 0.;
        if (kappa_e > 0.)
          {
            double       V0    = 0.;
            const double J_bar = mean_dilatation(c, u, V0);
            if (!(J_bar > 0.))
              {
                copy.valid = false;
                return;
              }
            const Materials::VolumetricEnergy U{kappa_e};
            p_e   = U.dU(J_bar);
            ddU_V = U.ddU(J_bar) / V0;
            s.dv.assign(n_nodes, Tensor<1, 3>());
          }

        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Tensor<2, 3> F = deformation_gradient(c, q, u);
            if (!(determinant(F) > 0.))
              {
                copy.valid = false;
                return;
              }
            const double        w = JxW[c * n_q + q];
            const Point<3>     &X = X_q[c * n_q + q];
            const Tensor<1, 3> *g = &grad_N[(c * n_q + q) * n_nodes];

            if (hyper != nullptr)
              {
                // the spatial form (doc/theory/02, (L5), (L6)): tau and
                // c of the material at F, the spatial gradients
                // n_a = F^-T grad N_a, R_a = tau n_a w
                hyper->stress_b(F, X, tau, K != nullptr ? &CC : nullptr);
                const double       J     = determinant(F);
                const Tensor<2, 3> F_inv = invert(F);
                for (unsigned int a = 0; a < n_nodes; ++a)
                  s.n[a] = g[a] * F_inv; // (F^-T g)_j = g_J F^-1_Jj
                if (kappa_e > 0.)
                  {
                    add_pressure(p_e * J, tau, K != nullptr ? &CC : nullptr);
                    if (K != nullptr)
                      // dv_e/dx_a += w cof(F) grad N_a = w J n_a   (D2)
                      for (unsigned int a = 0; a < n_nodes; ++a)
                        s.dv[a] += (w * J) * s.n[a];
                  }
                const int k = nodal ? nodal_element[c] : -1;
                if (k >= 0)
                  {
                    add_pressure(nodal->element_pressure(vertex_state, k) * J,
                                 tau,
                                 K != nullptr ? &CC : nullptr);
                    if (K != nullptr && s.primary)
                      // dv_e/dx_b = V0_e cof(F) grad N_b   (N2)
                      for (unsigned int a = 0; a < 4; ++a)
                        dv[k][a] = (w * J) * s.n[a];
                  }
                for (unsigned int a = 0; a < n_nodes; ++a)
                  {
                    s.tau_n[a] = tau * s.n[a];
                    for (unsigned int i = 0; i < 3; ++i)
                      copy.r[3 * a + i] += s.tau_n[a][i] * w;
                  }
              }
            else
              {
                if (K == nullptr)
                  m.P = material->first_piola_kirchhoff(F, X);
                else
                  material->evaluate(F, X, m);
                for (unsigned int k = 0; k < n_local; ++k)
                  copy.r[k] += (m.P[local_component[k]] * g[local_node[k]]) * w;
              }

            if (K == nullptr)
              continue;

            if (hyper != nullptr)
              {
                // K_ab = b_a^T c b_b + (n_a . tau n_b) I   (L6), b_a with
                // three nonzeros per column: n_a in the rows (0, 4, 5),
                // (1, 3, 5), (2, 3, 4) of columns 0, 1, 2
                const auto &D = CC.D;
                for (unsigned int a = 0; a < n_nodes; ++a)
                  {
                    const Tensor<1, 3> &na = s.n[a];
                    // the three columns of c b_a side by side
                    double *cb = s.cb[a].data();
                    for (unsigned int p = 0; p < 6; ++p)
                      {
                        cb[p * 3 + 0] =
                          D[p][0] * na[0] + D[p][5] * na[1] + D[p][4] * na[2];
                        cb[p * 3 + 1] =
                          D[p][5] * na[0] + D[p][1] * na[1] + D[p][3] * na[2];
                        cb[p * 3 + 2] =
                          D[p][4] * na[0] + D[p][3] * na[1] + D[p][2] * na[2];
                      }
                  }
                // row i of b_a^T picks the rows pick[i] of c b_b, with the
                // entries with[i] of n_a
                static constexpr unsigned int pick[3][3] = {{0, 4, 5},
                                                            {1, 3, 5},
                                                            {2, 3, 4}};
                static constexpr unsigned int with[3][3] = {{0, 2, 1},
                                                            {1, 2, 0},
                                                            {2, 1, 0}};
                for (unsigned int a = 0; a < n_nodes; ++a)
                  for (unsigned int b = a; b < n_nodes; ++b)
                    {
                      const Tensor<1, 3> &na  = s.n[a];
                      const double        geo = na * s.tau_n[b];
                      const double       *cbb = s.cb[b].data();
                      for (unsigned int i = 0; i < 3; ++i)
                        {
                          double *row = &Kc[(a * 3 + i) * n_local + b * 3];
                          double  v0  = (i == 0 ? geo : 0.),
                                 v1   = (i == 1 ? geo : 0.),
                                 v2   = (i == 2 ? geo : 0.);
                          for (unsigned int t = 0; t < 3; ++t)
                            {
                              const double  nt = na[with[i][t]];
                              const double *cr = cbb + pick[i][t] * 3;
                              v0 += nt * cr[0];
                              v1 += nt * cr[1];
                              v2 += nt * cr[2];
                            }
                          // the first point sets the block (it is not
                          // zeroed on the upper path), the others add
                          if (q == 0)
                            {
                              row[0] = v0 * w;
                              row[1] = v1 * w;
                              row[2] = v2 * w;
                            }
                          else
                            {
                              row[0] += v0 * w;
                              row[1] += v1 * w;
                              row[2] += v2 * w;
                            }
                        }
                    }
              }
            else
              {
                // generic two-point tangent: K_ab,ik = g_aJ A_iJkL g_bL
                for (unsigned int a = 0; a < n_nodes; ++a)
                  for (unsigned int b = a; b < n_nodes; ++b)
                    for (unsigned int i = 0; i < 3; ++i)
                      for (unsigned int k = 0; k < 3; ++k)
                        {
                          double v = 0.;
                          for (unsigned int J = 0; J < 3; ++J)
                            for (unsigned int L = 0; L < 3; ++L)
                              v += g[a][J] * m.A[i][J][k][L] * g[b][L];
                          copy.K(a * 3 + i, b * 3 + k) += v * w;
                        }
              }
          }
        if (K != nullptr && hyper != nullptr)
          // a diagonal block's two halves sum in different orders: the
          // upper one for both, so that K is symmetric to the last bit
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int k = i + 1; k < 3; ++k)
                copy.K(a * 3 + k, a * 3 + i) = copy.K(a * 3 + i, a * 3 + k);
        if (K != nullptr && !copy.upper)
          // node blocks were filled for a <= b: mirror into the lower part
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int b = a + 1; b < n_nodes; ++b)
              for (unsigned int i = 0; i < 3; ++i)
                for (unsigned int k = 0; k < 3; ++k)
                  copy.K(b * 3 + k, a * 3 + i) = copy.K(a * 3 + i, b * 3 + k);
        if (K != nullptr && kappa_e > 0.)
          // U''(J_bar) / V_e dv_e/dx_a (x) dv_e/dx_b   (D4)
          for (unsigned int a = 0; a < n_nodes; ++a)
            for (unsigned int i = 0; i < 3; ++i)
              {
                const double da = ddU_V * s.dv[a][i];
                for (unsigned int b = 0; b < n_nodes; ++b)
                  for (unsigned int k = 0; k < 3; ++k)
                    copy.K(a * 3 + i, b * 3 + k) += da * s.dv[b][k];
              }
      };

      double *const values = by_position ? value_array(*K) : nullptr;
      // add the rows lo .. hi - 1 of a cell's entries
      const auto copier = [&](const CopyData               &copy,
                              const types::global_dof_index lo,
                              const types::global_dof_index hi,
                              std::vector<double>          &row) {
        const types::global_dof_index *dofs = &cell_dofs[copy.cell * n_local];
        const auto                     mine = [&](const unsigned int k) {
          return dofs[k] >= lo && dofs[k] < hi;
        };
        for (unsigned int k = 0; k < n_local; ++k)
          if (mine(k))
            R[dofs[k]] += copy.r[k];
        if (by_position)
          {
            // the offsets are within the rows (use_matrix_pattern())
            const unsigned int *at =
              &positions[std::size_t(copy.cell) * n_local * n_local];
            const double *k      = &copy.K(0, 0);
            const auto    row_of = [&](const unsigned int i) {
              return values + positions_row_start[dofs[i]];
            };
            if (copy.upper && !node_positions.empty())
              {
                // node by node: a row's three columns of a node follow
                // each other in the values
                const unsigned int  per_row = n_nodes + 1;
                const unsigned int *np =
                  &node_positions[std::size_t(copy.cell) * n_local * per_row];
                for (unsigned int a = 0; a < n_nodes; ++a)
                  for (unsigned int i = 0; i < 3; ++i)
                    {
                      const unsigned int row = 3 * a + i;
                      if (!mine(row))
                        continue;
                      const unsigned int *P  = np + row * per_row;
                      const double       *kr = k + row * n_local;
                      double             *v  = row_of(row);
                      for (unsigned int b = 0; b < a; ++b)
                        for (unsigned int j = 0; j < 3; ++j)
                          v[P[b] + j] += k[(3 * b + j) * n_local + row];
                      v[P[n_nodes]] += kr[row];
                      for (unsigned int j = 0, offset = 0; j < 3; ++j)
                        if (j != i)
                          v[P[a] + offset++] += kr[3 * a + j];
                      for (unsigned int b = a + 1; b < n_nodes; ++b)
                        for (unsigned int j = 0; j < 3; ++j)
                          v[P[b] + j] += kr[3 * b + j];
                    }
              }
            else if (copy.upper)
              for (unsigned int a = 0; a < n_nodes; ++a)
                for (unsigned int i = 0; i < 3; ++i)
                  {
                    const unsigned int row = 3 * a + i;
                    if (!mine(row))
                      continue;
                    double *v = row_of(row);
                    for (unsigned int b = 0; b < a; ++b)
                      for (unsigned int j = 0; j < 3; ++j)
                        v[at[row * n_local + 3 * b + j]] +=
                          k[(3 * b + j) * n_local + row];
                    for (unsigned int col = 3 * a; col < n_local; ++col)
                      v[at[row * n_local + col]] += k[row * n_local + col];
                  }
            else
              for (unsigned int i = 0; i < n_local; ++i)
                if (mine(i))
                  {
                    double *v = row_of(i);
                    for (unsigned int j = 0; j < n_local; ++j)
                      v[at[i * n_local + j]] += k[i * n_local + j];
                  }
          }
        else if (K != nullptr)
          {
            const types::global_dof_index *columns =
              &sorted_dofs[copy.cell * n_local];
            const unsigned char *local = &sorted_local[copy.cell * n_local];
            for (unsigned int i = 0; i < n_local; ++i)
              {
                if (columns[i] < lo || columns[i] >= hi)
                  continue;
                for (unsigned int j = 0; j < n_local; ++j)
                  row[j] = copy.K(local[i], local[j]);
                K->add(columns[i], n_local, columns, row.data(), false, true);
              }
          }
      };

      const unsigned int n_parts = n_row_ranges();
      const RowSplit     other =
        split.n_parts == n_parts ? RowSplit() : row_split(n_parts);
      const RowSplit &parts = split.n_parts == n_parts ? split : other;
      if (parts.usable)
        {
          // each thread the cells with unknowns in its range of rows, in
          // the cells' order, adding only to its rows: every entry of R
          // and K receives the same additions in the same order as in the
          // serial loop, on any number of threads (row_ranges.h). A cell
          // with unknowns in two ranges is computed by both threads.
          std::vector<char> part_valid(n_parts, 1);
          parallel::apply_to_subranges(
            0u,
            n_parts,
            [&](const unsigned int part_begin, const unsigned int part_end) {
              ScratchData         s;
              CopyData            copy;
              std::vector<double> row(n_local);
              for (unsigned int part = part_begin; part < part_end; ++part)
                {
                  const types::global_dof_index lo = parts.bounds[part],
                                                hi = parts.bounds[part + 1];
                  for (unsigned int k = 0; k < deformable_cells.size(); ++k)
                    {
                      const auto &range = cell_dof_range[deformable_cells[k]];
                      if (range[1] < lo || range[0] >= hi)
                        continue;
                      s.primary = range[0] >= lo;
                      worker(deformable_cells.cbegin() + k, s, copy);
                      if (!copy.valid)
                        {
                          part_valid[part] = 0;
                          break;
                        }
                      copier(copy, lo, hi, row);
                    }
                }
            },
            1);
          valid = valid && std::find(part_valid.begin(), part_valid.end(), 0) ==
                             part_valid.end();
        }
      else
        {
          // the cells in batches: one WorkStream item (and one copier call)
          // per batch instead of per cell; the copier runs on one thread
          constexpr unsigned int    batch = 16;
          std::vector<unsigned int> batch_starts;
          for (unsigned int k = 0; k < deformable_cells.size(); k += batch)
            batch_starts.push_back(k);
          std::vector<double> row(n_local);
          WorkStream::run(
            batch_starts.begin(),
            batch_starts.end(),
            [&](const std::vector<unsigned int>::const_iterator &start,
                ScratchData                                     &s,
                std::vector<CopyData>                           &copies) {
              const unsigned int n =
                std::min<unsigned int>(batch, deformable_cells.size() - *start);
              copies.resize(n);
              for (unsigned int k = 0; k < n; ++k)
                worker(deformable_cells.cbegin() + *start + k, s, copies[k]);
            },
            [&](const std::vector<CopyData> &copies) {
              for (const CopyData &copy : copies)
                if (!copy.valid)
                  valid = false;
                else
                  copier(copy, 0, disc.n_dofs(), row);
            },
            ScratchData(),
            std::vector<CopyData>(),
            2 * MultithreadInfo::n_threads(),
            4);
        }
      if (valid && K != nullptr && nodal)
        nodal->add_tangent(vertex_state, dv, *K);
      if (valid)
        R.add(-load_factor, f_ext);
      return valid;
    }


    bool
    ElasticAssembler::splits_rows() const
    {
      const unsigned int n_parts = n_row_ranges();
      return n_parts > 1 &&
             (split.n_parts == n_parts ? split.usable :
                                         row_split(n_parts).usable);
    }


    ElasticAssembler::RowSplit
    ElasticAssembler::row_split(const unsigned int n_parts) const
    {
      RowSplit split;
      split.n_parts = n_parts;
      std::vector<std::size_t> work(disc.n_dofs() + 1, 0);
      for (const unsigned int c : deformable_cells)
        for (unsigned int k = 0; k < n_local; ++k)
          ++work[cell_dofs[c * n_local + k] + 1];
      std::partial_sum(work.begin(), work.end(), work.begin());
      split.bounds = balanced_row_ranges(work, n_parts);
      // the cells each part computes: those with an unknown in its rows
      std::size_t computed = 0;
      for (const unsigned int c : deformable_cells)
        for (unsigned int part = 0; part < n_parts; ++part)
          if (cell_dof_range[c][1] >= split.bounds[part] &&
              cell_dof_range[c][0] < split.bounds[part + 1])
            ++computed;
      split.usable = 4 * computed <= 5 * deformable_cells.size();
      return split;
    }


    void
    ElasticAssembler::use_matrix_pattern(const SparsityPattern &pattern)
    {
      AssertThrow(pattern.n_nonzero_elements() <
                    std::numeric_limits<unsigned int>::max(),
                  ExcNotImplemented());
      const unsigned int n_cells = cell_material.size();
      const unsigned int per_row = n_nodes + 1;
      // the rows of this pattern: their starts (a compressed pattern stores
      // its rows one after the other), their columns, and which rows have
      // the columns they had in the pattern of the last call. The offsets
      // within a row are stored, so the cells whose rows all kept their
      // columns keep theirs: a pattern build changes the rows of the contact
      // couplings only (the cells' positions found anew at every build were
      // 40 % of a build on the full knee; doc/theory/02 sec. 2.4)
      const auto               n_rows = pattern.n_rows();
      std::vector<std::size_t> row_start(n_rows + 1, 0);
      for (types::global_dof_index r = 0; r < n_rows; ++r)
        row_start[r + 1] = row_start[r] + pattern.row_length(r);
      std::vector<types::global_dof_index> columns(row_start[n_rows]);
      const bool                           have_rows =
        positions_row_start.size() == n_rows + 1 &&
        positions.size() == std::size_t(n_cells) * n_local * n_local;
      std::vector<unsigned char> same(n_rows, 0);
      parallel::apply_to_subranges(
        types::global_dof_index(0),
        n_rows,
        [&](const types::global_dof_index begin,
            const types::global_dof_index end) {
          for (types::global_dof_index r = begin; r < end; ++r)
            {
              const std::size_t length = row_start[r + 1] - row_start[r];
              for (std::size_t k = 0; k < length; ++k)
                columns[row_start[r] + k] = pattern.column_number(r, k);
              same[r] =
                have_rows &&
                positions_row_start[r + 1] - positions_row_start[r] == length &&
                std::equal(columns.begin() + row_start[r],
                           columns.begin() + row_start[r + 1],
                           positions_columns.begin() + positions_row_start[r]);
            }
        },
        512);
      // a cell's rows that changed (all of them at the first call) find
      // their offsets by one binary search per local entry, and their
      // node-wise ones; the others keep theirs (their node-wise ones are
      // found too if there were none). The cells in parallel, each writing
      // only its own
      const bool had_node_wise = have_rows && !node_positions.empty();
      positions.resize(std::size_t(n_cells) * n_local * n_local);
      node_positions.resize(std::size_t(n_cells) * n_local * per_row);
      std::atomic<bool> all_found{true}, node_wise{true};
      parallel::apply_to_subranges(
        0u,
        static_cast<unsigned int>(deformable_cells.size()),
        [&](const unsigned int begin, const unsigned int end) {
          // flags decided locally: a shared one written per entry cost more
          // than the whole rest (its cache line passed between threads)
          bool found = true, ok = true;
          for (unsigned int k = begin; k < end; ++k)
            {
              const unsigned int             c    = deformable_cells[k];
              const types::global_dof_index *dofs = &cell_dofs[c * n_local];
              unsigned int *at = &positions[std::size_t(c) * n_local * n_local];
              unsigned int *np =
                &node_positions[std::size_t(c) * n_local * per_row];
              bool checked = false;
              for (unsigned int r = 0; r < n_local; ++r)
                {
                  const bool changed = !have_rows || same[dofs[r]] == 0;
                  if (!changed && had_node_wise)
                    continue;
                  unsigned int *row = at + r * n_local;
                  if (changed)
                    for (unsigned int j = 0; j < n_local; ++j)
                      {
                        // compared before narrowing to the stored 32 bits,
                        // where invalid_entry would no longer read as
                        // itself
                        const std::size_t p = pattern(dofs[r], dofs[j]);
                        if (p == SparsityPattern::invalid_entry)
                          found = false;
                        else
                          row[j] = p - row_start[dofs[r]];
                      }
                  // per node: each node's three DoFs consecutive, and so
                  // its three columns in the row (the diagonal left out)
                  if (!checked)
                    for (unsigned int b = 0; b < n_nodes; ++b)
                      if (dofs[3 * b + 1] != dofs[3 * b] + 1 ||
                          dofs[3 * b + 2] != dofs[3 * b] + 2)
                        ok = false;
                  checked              = true;
                  const unsigned int a = r / 3, i = r % 3;
                  for (unsigned int b = 0; b < n_nodes; ++b)
                    {
                      unsigned int       offset = 0;
                      const unsigned int base =
                        row[3 * b + (b == a && i == 0 ? 1 : 0)];
                      for (unsigned int j = 0; j < 3; ++j)
                        if (b != a || j != i)
                          ok = ok && row[3 * b + j] == base + offset++;
                      np[r * per_row + b] = base;
                    }
                  np[r * per_row + n_nodes] = row[r];
                }
            }
          if (!found)
            all_found = false;
          if (!ok)
            node_wise = false;
        },
        256);
      AssertThrow(all_found, ExcInternalError());
      if (!node_wise)
        node_positions.clear();
      positions_pattern = &pattern;
      positions_entries = pattern.n_nonzero_elements();
      positions_row_start.swap(row_start);
      positions_columns.swap(columns);
    }


    double
    ElasticAssembler::energy(const Vector<double> &u,
                             const double          load_factor) const
    {
      double W = 0.;
      if (nodal)
        {
          bool       valid = true;
          const auto state = nodal_state(u, valid);
          if (!valid)
            return std::numeric_limits<double>::infinity();
          W += nodal->energy(state);
        }
      // each cell's terms computed on the threads, then added to W in the
      // cells' order, term by term, as a serial loop adds them (the same sum
      // to the last bit on any number of threads)
      const unsigned int         n_terms = n_q + 2;
      const std::size_t          n_cells = deformable_cells.size();
      std::vector<double>        terms(n_cells * n_terms);
      std::vector<unsigned char> n_used(n_cells, 0);
      std::vector<char>          cell_valid(n_cells, 1);
      parallel::apply_to_subranges(
        std::size_t(0),
        n_cells,
        [&](const std::size_t begin, const std::size_t end) {
          for (std::size_t i = begin; i < end; ++i)
            {
              const unsigned int c    = deformable_cells[i];
              double            *term = &terms[i * n_terms];
              unsigned int       t    = 0;
              const bool         single =
                !single_rotation_index.empty() && single_rotation_index[c] >= 0;
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  const Tensor<2, 3> F = deformation_gradient(c, q, u);
                  if (!(determinant(F) > 0.))
                    {
                      cell_valid[i] = 0;
                      break;
                    }
                  if (!single)
                    term[t++] = cell_material[c]->energy(F, X_q[c * n_q + q]) *
                                JxW[c * n_q + q];
                }
              if (!cell_valid[i])
                continue;
              if (single)
                {
                  // (SR1)
                  std::array<Point<3>, 10> x;
                  double                   W_e = 0.;
                  if (!single_rotation_element(c, u, x.data())
                         .energy(x.data(), W_e))
                    {
                      cell_valid[i] = 0;
                      continue;
                    }
                  term[t++] = W_e;
                }
              if (!mean_dilatation_kappa.empty() &&
                  mean_dilatation_kappa[c] > 0.)
                {
                  // V_e U(J_bar_e)   (D1)
                  double       V0    = 0.;
                  const double J_bar = mean_dilatation(c, u, V0);
                  term[t++] =
                    V0 *
                    Materials::VolumetricEnergy{mean_dilatation_kappa[c]}.U(
                      J_bar);
                }
              n_used[i] = t;
            }
        },
        256);
      for (std::size_t i = 0; i < n_cells; ++i)
        {
          if (!cell_valid[i])
            return std::numeric_limits<double>::infinity();
          for (unsigned int t = 0; t < n_used[i]; ++t)
            W += terms[i * n_terms + t];
        }
      return W - load_factor * (f_ext * u);
    }


    double
    ElasticAssembler::min_jacobian(const Vector<double> &u) const
    {
      double J_min = std::numeric_limits<double>::max();
      for (const unsigned int c : deformable_cells)
        for (unsigned int q = 0; q < n_q; ++q)
          J_min = std::min(J_min, determinant(deformation_gradient(c, q, u)));
      return J_min;
    }


    Vector<double>
    ElasticAssembler::quasi_viscosity_diagonal(const double eta) const
    {
      Vector<double> D(disc.n_dofs());
      for (const unsigned int c : deformable_cells)
        {
          double volume = 0.;
          for (unsigned int q = 0; q < n_q; ++q)
            volume += JxW[c * n_q + q];
          const double mu_e  = cell_material[c]->lame_equivalents().first;
          const double value = eta * mu_e * std::cbrt(volume) / n_nodes;
          for (unsigned int k = 0; k < n_local; ++k)
            D[cell_dofs[c * n_local + k]] += value;
        }
      return D;
    }


    CellQuantities
    ElasticAssembler::cell_quantities(const Vector<double> &u) const
    {
      const unsigned int n_cells = cell_material.size();
      CellQuantities     out;
      out.J.reinit(n_cells);
      out.strain_energy_density.reinit(n_cells);
      out.von_mises.reinit(n_cells);
      for (auto &v : out.cauchy_stress)
        v.reinit(n_cells);

      bool                 vertex_valid = true;
      NodalPressure::State vertex_state;
      if (nodal)
        vertex_state = nodal_state(u, vertex_valid);

      for (unsigned int c = 0; c < n_cells; ++c)
        {
          double       volume = 0., J = 0., psi = 0.;
          Tensor<2, 3> sigma;
          // a single-rotation element's rotation (doc/theory/10, (SR1'))
          Tensor<2, 3> R_e;
          bool         single =
            !single_rotation_index.empty() && single_rotation_index[c] >= 0;
          if (single)
            {
              std::array<Point<3>, 10> x;
              const Tensor<2, 3> F_c = single_rotation_element(c, u, x.data())
                                         .corner_deformation_gradient(x.data());
              single = determinant(F_c) > 0.;
              if (single)
                R_e = PolarRotation(F_c).R();
            }
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Tensor<2, 3> F  = deformation_gradient(c, q, u);
              const double       Jq = determinant(F);
              const double       w  = JxW[c * n_q + q];
              volume += w;
              J += Jq * w;
              if (single && Jq > 0.)
                {
                  // linear elasticity of eps = sym(R^T F) - I, P = R T
                  const auto [mu, lambda] =
                    cell_material[c]->lame_equivalents();
                  const SymmetricTensor<2, 3> eps =
                    symmetrize(transpose(R_e) * F) - unit_symmetric_tensor<3>();
                  psi +=
                    (mu * eps * eps + 0.5 * lambda * trace(eps) * trace(eps)) *
                    w;
                  const SymmetricTensor<2, 3> T =
                    2. * mu * eps +
                    lambda * trace(eps) * unit_symmetric_tensor<3>();
                  sigma += R_e * static_cast<Tensor<2, 3>>(T) * transpose(F) *
                           (w / Jq);
                }
              else if (cell_material[c] != nullptr && Jq > 0.)
                {
                  const Point<3> &X = X_q[c * n_q + q];
                  psi += cell_material[c]->energy(F, X) * w;
                  sigma += cell_material[c]->first_piola_kirchhoff(F, X) *
                           transpose(F) * (w / Jq);
                }
            }
          if (!mean_dilatation_kappa.empty() && mean_dilatation_kappa[c] > 0. &&
              J > 0.)
            {
              // the element's volume term and pressure (doc/theory/09)
              const Materials::VolumetricEnergy U{mean_dilatation_kappa[c]};
              psi += U.U(J / volume) * volume;
              sigma += U.dU(J / volume) * volume *
                       Tensor<2, 3>(unit_symmetric_tensor<3>());
            }
          if (nodal && nodal_element[c] >= 0 && vertex_valid)
            {
              // the vertex term's share (doc/theory/08, sec. 8.4)
              const unsigned int k = nodal_element[c];
              psi += nodal->element_energy_density(vertex_state, k) * volume;
              sigma += nodal->element_pressure(vertex_state, k) * volume *
                       Tensor<2, 3>(unit_symmetric_tensor<3>());
            }
          out.J[c]                     = J / volume;
          out.strain_energy_density[c] = psi / volume;
          sigma /= volume;
          for (unsigned int i = 0; i < 6; ++i)
            out.cauchy_stress[i][c] =
              sigma[VoigtTangent::index[i][0]][VoigtTangent::index[i][1]];
          const Tensor<2, 3> dev =
            sigma - trace(sigma) / 3. * unit_symmetric_tensor<3>();
          out.von_mises[c] = std::sqrt(1.5 * scalar_product(dev, dev));
        }
      return out;
    }
  } // namespace Elasticity
} // namespace TissueContact
