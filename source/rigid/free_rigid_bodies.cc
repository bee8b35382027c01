#include <tissue_contact/rigid/free_rigid_bodies.h>
#include <tissue_contact/rigid/rotation.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parallel.h>

#include <algorithm>

namespace TissueContact
{
  namespace Rigid
  {
    FreeRigidBodies::FreeRigidBodies(const types::global_dof_index n_fe,
                                     const std::vector<Body>      &bodies)
      : n_fe(n_fe)
      , bodies(bodies)
      , owner(n_fe, -1)
      , slave_index(n_fe, 0)
    {
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const Body &body = bodies[b];
          AssertThrow(!body.dofs.empty(),
                      ExcMessage("the free rigid body '" + body.name +
                                 "' has no cells in the mesh"));
          // c: the mean of the support points (each point has three DoFs)
          Point<3> c;
          for (const Point<3> &X : body.X)
            c += X;
          centers.push_back(c / double(body.X.size()));
          for (unsigned int k = 0; k < body.dofs.size(); ++k)
            {
              const auto i = body.dofs[k];
              AssertThrow(owner[i] < 0 || owner[i] == int(b),
                          ExcMessage("the free rigid bodies '" +
                                     bodies[owner[i]].name + "' and '" +
                                     body.name +
                                     "' share nodes; attach them through an "
                                     "elastic body or make them one body"));
              owner[i]       = b;
              slave_index[i] = k;
            }
        }
      slaves.resize(bodies.size());
      for (types::global_dof_index i = 0; i < n_fe; ++i)
        if (owner[i] >= 0)
          slaves[owner[i]].push_back(i);
    }


    Tensor<1, 3>
    FreeRigidBodies::translation(const Vector<double> &u,
                                 const unsigned int    b) const
    {
      Tensor<1, 3> t;
      for (unsigned int i = 0; i < 3; ++i)
        t[i] = u[first_unknown(b) + i];
      return t;
    }


    Tensor<1, 3>
    FreeRigidBodies::rotation_vector(const Vector<double> &u,
                                     const unsigned int    b) const
    {
      Tensor<1, 3> theta;
      for (unsigned int i = 0; i < 3; ++i)
        theta[i] = u[first_unknown(b) + 3 + i];
      return theta;
    }


    void
    FreeRigidBodies::expand(const Vector<double> &u, Vector<double> &u_fe) const
    {
      AssertDimension(u.size(), n_dofs());
      u_fe.reinit(n_fe, true);
      for (types::global_dof_index i = 0; i < n_fe; ++i)
        u_fe[i] = u[i];
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const Tensor<1, 3> t    = translation(u, b);
          const Tensor<2, 3> R    = rotation(rotation_vector(u, b)).R;
          const Body        &body = bodies[b];
          for (unsigned int k = 0; k < body.dofs.size(); ++k)
            {
              // u_s = (R (X - c) + c + t - X)_i
              const Tensor<1, 3> r = body.X[k] - centers[b];
              const unsigned int i = body.components[k];
              u_fe[body.dofs[k]]   = (R * r)[i] - r[i] + t[i];
            }
        }
    }


    void
    FreeRigidBodies::complete(Vector<double> &u) const
    {
      Vector<double> u_fe;
      expand(u, u_fe);
      for (types::global_dof_index i = 0; i < n_fe; ++i)
        u[i] = u_fe[i];
    }


    std::vector<std::array<double, 6>>
    FreeRigidBodies::jacobian(const unsigned int         b,
                              const RotationDerivatives &rot) const
    {
      const Body                        &body = bodies[b];
      std::vector<std::array<double, 6>> J(body.dofs.size());
      for (unsigned int k = 0; k < body.dofs.size(); ++k)
        {
          const Tensor<1, 3> r = body.X[k] - centers[b];
          const unsigned int i = body.components[k];
          for (unsigned int m = 0; m < 3; ++m)
            {
              J[k][m]     = (m == i ? 1. : 0.);
              J[k][3 + m] = (rot.dR[m] * r)[i];
            }
        }
      return J;
    }


    void
    FreeRigidBodies::condense(const Vector<double> &u,
                              const Vector<double> &R_fe,
                              Vector<double>       &R,
                              SparseMatrix<double> *K) const
    {
      AssertDimension(R_fe.size(), n_fe);
      R.reinit(n_dofs());
      for (types::global_dof_index i = 0; i < n_fe; ++i)
        R[i] = R_fe[i];

      std::vector<std::vector<std::array<double, 6>>> J(bodies.size());
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const RotationDerivatives rot = rotation(rotation_vector(u, b));
          J[b]                          = jacobian(b, rot);
          const Body &body              = bodies[b];
          const auto  q                 = first_unknown(b);

          // R_q = sum_s J_s^T R_s; the slaves' rows become u_s - u_s(q) = 0
          Tensor<2, 3> M; // sum_s R_s e_i (X - c)^T, for the geometric term
          for (unsigned int k = 0; k < body.dofs.size(); ++k)
            {
              const double Rs = R_fe[body.dofs[k]];
              for (unsigned int m = 0; m < 6; ++m)
                R[q + m] += J[b][k][m] * Rs;
              R[body.dofs[k]]      = 0.;
              const Tensor<1, 3> r = body.X[k] - centers[b];
              for (unsigned int j = 0; j < 3; ++j)
                M[body.components[k]][j] += Rs * r[j];
            }
          if (K == nullptr)
            continue;
          // sum_s R_s d2u_s/dtheta_k dtheta_l = d2R_kl : M
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              K->add(q + 3 + k, q + 3 + l, scalar_product(rot.d2R[k][l], M));
        }
      if (K == nullptr)
        return;

      // K T: every slave column s moves to its body's columns, times J_s;
      // each row changes only itself: the rows in parallel. Only the rows
      // with a slave column change, and the pattern is symmetric (the
      // elements', the contact pairs' and add_couplings()' are), so they
      // are the columns of the slaves' rows: on the full knee 3 150 of 29 706
      // rows (a sampling profile of its first 8 increments: condense() 3.1 %
      // of the samples with the pass over all rows, 1.6 % without). The
      // rows are read and written in place: a square SparseMatrix stores
      // row i's values from its diagonal on, in the pattern's order (its
      // diagonal first, the other columns ascending), and each entry gets
      // the additions SparseMatrix::add() would make, in the same order
      // (zeros skipped, as add() skips them)
      const SparsityPattern &pattern    = K->get_sparsity_pattern();
      const auto             row_values = [&](const types::global_dof_index i) {
        return &K->diag_element(i);
      };
      // the place of column j in row i, counted from the row's first
      // (diagonal) entry; invalid if not stored
      constexpr unsigned int missing  = numbers::invalid_unsigned_int;
      const auto             place_of = [&](const types::global_dof_index i,
                                const types::global_dof_index j) {
        const auto at = pattern(i, j);
        return at == SparsityPattern::invalid_entry ?
                             missing :
                             static_cast<unsigned int>(at - pattern(i, i));
      };
      std::vector<bool> has_slave_column(K->m(), false);
      for (const auto &body_slaves : slaves)
        for (const auto s : body_slaves)
          for (unsigned int k = 0; k < pattern.row_length(s); ++k)
            has_slave_column[pattern.column_number(s, k)] = true;
      std::vector<types::global_dof_index> coupled_rows;
      for (types::global_dof_index i = 0; i < K->m(); ++i)
        if (has_slave_column[i])
          coupled_rows.push_back(i);
      Assert(
        [&]() {
          for (types::global_dof_index i = 0; i < K->m(); ++i)
            if (!has_slave_column[i])
              for (auto e = K->begin(i); e != K->end(i); ++e)
                if (e->column() < n_fe && owner[e->column()] >= 0)
                  return false;
          return true;
        }(),
        ExcMessage("the pattern of K is not symmetric in the slaves' rows"));
      parallel::apply_to_subranges(
        std::size_t(0),
        coupled_rows.size(),
        [&](const std::size_t begin, const std::size_t end) {
          // the places of each body's six columns in the row, found once
          std::vector<std::array<unsigned int, 6>> body_places(bodies.size());
          std::vector<bool>                        have_places(bodies.size());
          for (std::size_t r = begin; r < end; ++r)
            {
              const types::global_dof_index i      = coupled_rows[r];
              double                       *values = row_values(i);
              const unsigned int            length = pattern.row_length(i);
              std::fill(have_places.begin(), have_places.end(), false);
              for (unsigned int k = 0; k < length; ++k)
                {
                  const auto j = pattern.column_number(i, k);
                  if (j >= n_fe || owner[j] < 0 || values[k] == 0.)
                    continue;
                  const double v = values[k];
                  values[k]      = 0.;
                  const auto &Js = J[owner[j]][slave_index[j]];
                  auto       &at = body_places[owner[j]];
                  if (!have_places[owner[j]])
                    {
                      const auto q = first_unknown(owner[j]);
                      for (unsigned int m = 0; m < 6; ++m)
                        at[m] = place_of(i, q + m);
                      have_places[owner[j]] = true;
                    }
                  for (unsigned int m = 0; m < 6; ++m)
                    if (Js[m] != 0.)
                      {
                        const double a = v * Js[m];
                        AssertThrow(a == 0. || at[m] != missing,
                                    ExcMessage(
                                      "a rigid body's coupling is not in the "
                                      "matrix's pattern"));
                        if (a != 0.)
                          values[at[m]] += a;
                      }
                }
            }
        },
        64);
      // T^T (K T): every slave row moves to its body's rows, then becomes
      // the identity's. Each of a body's six rows gathers from all its
      // slaves' rows, in the slaves' order (the sums as if done one after
      // the other), each column's place in the body's row read from a map
      // of the row: the bodies' rows in parallel, then the slaves' rows
      // cleared
      const unsigned int n_rows = 6 * bodies.size();
      parallel::apply_to_subranges(
        0u,
        n_rows,
        [&](const unsigned int begin, const unsigned int end) {
          std::vector<unsigned int> place(K->n(), missing);
          for (unsigned int bm = begin; bm < end; ++bm)
            {
              const unsigned int b = bm / 6, m = bm % 6;
              const auto         q   = first_unknown(b);
              const auto         row = q + m;
              for (unsigned int k = 0; k < pattern.row_length(row); ++k)
                place[pattern.column_number(row, k)] = k;
              double *body_values = row_values(row);
              for (const auto s : slaves[b])
                {
                  const double Jm = J[b][slave_index[s]][m];
                  if (Jm == 0.)
                    continue;
                  const double *values = row_values(s);
                  for (unsigned int k = 0; k < pattern.row_length(s); ++k)
                    if (values[k] != 0.)
                      {
                        const double a = Jm * values[k];
                        if (a == 0.)
                          continue;
                        const unsigned int at =
                          place[pattern.column_number(s, k)];
                        AssertThrow(at != missing,
                                    ExcMessage(
                                      "a rigid body's coupling is not in the "
                                      "matrix's pattern"));
                        body_values[at] += a;
                      }
                }
              for (unsigned int k = 0; k < pattern.row_length(row); ++k)
                place[pattern.column_number(row, k)] = missing;
            }
        },
        1);
      for (unsigned int b = 0; b < bodies.size(); ++b)
        for (const auto s : slaves[b])
          {
            double *values = row_values(s);
            std::fill(values, values + pattern.row_length(s), 0.);
            values[0] = 1.;
          }
    }


    void
    FreeRigidBodies::add_couplings(PatternRows &rows) const
    {
      AssertDimension(rows.size(), n_fe);
      // row i gets the six unknowns of the body of every slave among its
      // columns; they are numbered after all finite element DoFs and in
      // the order of the bodies, so appended they keep the row sorted. The
      // rows in parallel
      parallel::apply_to_subranges(
        types::global_dof_index(0),
        n_fe,
        [&](const types::global_dof_index begin,
            const types::global_dof_index end) {
          std::vector<bool> coupled(bodies.size());
          for (types::global_dof_index i = begin; i < end; ++i)
            {
              std::fill(coupled.begin(), coupled.end(), false);
              bool any = false;
              for (const auto j : rows[i])
                if (owner[j] >= 0)
                  any = coupled[owner[j]] = true;
              if (any)
                for (unsigned int b = 0; b < bodies.size(); ++b)
                  if (coupled[b])
                    for (unsigned int m = 0; m < 6; ++m)
                      rows[i].push_back(first_unknown(b) + m);
            }
        },
        512);
      // a body's six rows: the union of its slaves' rows (so far) and its
      // own unknowns, marked in a flag per column and read off in order
      std::vector<bool> marked(n_dofs());
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          std::fill(marked.begin(), marked.end(), false);
          for (const auto s : slaves[b])
            for (const auto j : rows[s])
              marked[j] = true;
          for (unsigned int m = 0; m < 6; ++m)
            marked[first_unknown(b) + m] = true;
          std::vector<types::global_dof_index> row;
          for (types::global_dof_index j = 0; j < marked.size(); ++j)
            if (marked[j])
              row.push_back(j);
          for (unsigned int m = 0; m < 6; ++m)
            rows.push_back(row);
        }
    }


    Vector<double>
    FreeRigidBodies::condense_diagonal(const Vector<double> &D_fe) const
    {
      Vector<double> D(n_dofs());
      for (types::global_dof_index i = 0; i < n_fe; ++i)
        D[i] = owner[i] >= 0 ? 0. : D_fe[i];
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const auto J = jacobian(b, rotation(Tensor<1, 3>()));
          for (unsigned int k = 0; k < J.size(); ++k)
            for (unsigned int m = 0; m < 6; ++m)
              D[first_unknown(b) + m] +=
                J[k][m] * J[k][m] * D_fe[bodies[b].dofs[k]];
        }
      return D;
    }
  } // namespace Rigid
} // namespace TissueContact
