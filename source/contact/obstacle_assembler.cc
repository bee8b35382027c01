#include <tissue_contact/contact/obstacle_assembler.h>

#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>

namespace TissueContact
{
  namespace Contact
  {
    ObstacleAssembler::ObstacleAssembler(
      const ContactSurface               &surface,
      const std::vector<ObstacleContact> &obstacles)
      : surface(surface)
      , obstacles(obstacles)
      , multipliers(obstacles.size() * surface.X.size(), 0.)
      , pushed_vertices(obstacles.size())
    {
      for (unsigned int o = 0; o < obstacles.size(); ++o)
        {
          for (unsigned int t = 0; t < surface.n_triangles(); ++t)
            if (pushes(this->obstacles[o], t))
              for (const unsigned int v : surface.triangles[t])
                pushed_vertices[o].push_back(v);
          auto &p = pushed_vertices[o];
          std::sort(p.begin(), p.end());
          p.erase(std::unique(p.begin(), p.end()), p.end());
        }
    }


    double
    ObstacleAssembler::multiplier(const unsigned int o,
                                  const unsigned int v) const
    {
      return multipliers[o * surface.X.size() + v];
    }


    bool
    ObstacleAssembler::has_multiplier(const unsigned int o,
                                      const unsigned int t) const
    {
      for (const unsigned int v : surface.triangles[t])
        if (multiplier(o, v) > 0.)
          return true;
      return false;
    }


    template <typename Number>
    Number
    ObstacleAssembler::triangle_energy(
      const unsigned int                     o,
      const unsigned int                     t,
      const std::array<Point<3, Number>, 3> &tri) const
    {
      const ObstacleContact &c = obstacles[o];
      if (!has_multiplier(o, t))
        return obstacle_energy(c.obstacle, tri, c.penalty);
      const auto &v = surface.triangles[t];
      return augmented_obstacle_energy(
        c.obstacle,
        tri,
        c.penalty,
        {{multiplier(o, v[0]), multiplier(o, v[1]), multiplier(o, v[2])}});
    }


    double
    ObstacleAssembler::contact_area(const unsigned int             o,
                                    const unsigned int             t,
                                    const std::array<Point<3>, 3> &tri) const
    {
      if (!has_multiplier(o, t))
        return obstacle_contact_area(obstacles[o].obstacle, tri);
      // with multipliers the pressure lambda + eps d acts where phi > 0
      std::array<double, 3> phi;
      for (unsigned int k = 0; k < 3; ++k)
        phi[k] = obstacles[o].obstacle.penetration(tri[k]) +
                 multiplier(o, surface.triangles[t][k]) / obstacles[o].penalty;
      std::array<Point<3>, 4> x;
      std::array<double, 4>   d;
      return polygon_area(x, non_negative_part(tri, phi, x, d));
    }


    bool
    ObstacleAssembler::pushes(const ObstacleContact &o,
                              const unsigned int     t) const
    {
      return o.bodies.empty() || o.bodies.count(surface.triangle_body[t]) > 0;
    }


    template <typename F>
    void
    ObstacleAssembler::for_each_contact(const Vector<double> &u,
                                        const bool            with_hessian,
                                        const F              &f) const
    {
      for (unsigned int t = 0; t < surface.n_triangles(); ++t)
        {
          const std::array<Point<3>, 3> tri = surface.triangle(t, u);
          for (unsigned int i = 0; i < obstacles.size(); ++i)
            {
              const ObstacleContact &o = obstacles[i];
              if (!pushes(o, t))
                continue;
              bool penetrates = has_multiplier(i, t);
              for (const auto &p : tri)
                penetrates = penetrates || o.obstacle.penetration(p) > 0.;
              if (penetrates)
                f(t,
                  i,
                  ad_derivatives(
                    [&](const auto &T) { return triangle_energy(i, t, T); },
                    with_hessian,
                    tri));
            }
        }
    }


    void
    ObstacleAssembler::assemble(const Vector<double> &u,
                                Vector<double>       &R,
                                SparseMatrix<double> *K) const
    {
      for_each_contact(u,
                       K != nullptr,
                       [&](const unsigned int t,
                           const unsigned int,
                           const PairDerivatives &d) {
                         std::array<types::global_dof_index, 9> dofs;
                         for (unsigned int a = 0; a < 3; ++a)
                           for (unsigned int c = 0; c < 3; ++c)
                             dofs[3 * a + c] =
                               surface.vertex_dofs[surface.triangles[t][a]][c];
                         for (unsigned int i = 0; i < 9; ++i)
                           {
                             R[dofs[i]] += d.gradient[i];
                             if (K != nullptr)
                               for (unsigned int j = 0; j < 9; ++j)
                                 K->add(dofs[i], dofs[j], d.hessian(i, j));
                           }
                       });
    }


    std::vector<double>
    ObstacleAssembler::energies(const Vector<double> &u) const
    {
      std::vector<double> W(obstacles.size(), 0.);
      for (unsigned int t = 0; t < surface.n_triangles(); ++t)
        {
          const std::array<Point<3>, 3> tri = surface.triangle(t, u);
          for (unsigned int i = 0; i < obstacles.size(); ++i)
            if (pushes(obstacles[i], t))
              W[i] += triangle_energy<double>(i, t, tri);
        }
      return W;
    }


    Tensor<1, 3>
    ObstacleAssembler::force(const Vector<double> &u) const
    {
      Tensor<1, 3> force;
      for_each_contact(u,
                       false,
                       [&](const unsigned int,
                           const unsigned int,
                           const PairDerivatives &d) {
                         for (unsigned int a = 0; a < 3; ++a)
                           for (unsigned int c = 0; c < 3; ++c)
                             force[c] -= d.gradient[3 * a + c];
                       });
      return force;
    }


    std::vector<ContactResult>
    ObstacleAssembler::results(const Vector<double>      &u,
                               std::vector<Tensor<1, 3>> &surface_force,
                               std::vector<double>       &penetration) const
    {
      const std::vector<double> d = vertex_penetrations(u);
      for (unsigned int v = 0; v < d.size(); ++v)
        penetration[v] = std::max(penetration[v], d[v]);
      std::vector<ContactResult> result(obstacles.size());
      for_each_contact(u,
                       false,
                       [&](const unsigned int     t,
                           const unsigned int     o,
                           const PairDerivatives &d) {
                         ContactResult &r = result[o];
                         for (unsigned int a = 0; a < 3; ++a)
                           for (unsigned int c = 0; c < 3; ++c)
                             {
                               r.force[c] -= d.gradient[3 * a + c];
                               surface_force[surface.triangles[t][a]][c] -=
                                 d.gradient[3 * a + c];
                             }
                         r.area += contact_area(o, t, surface.triangle(t, u));
                         r.energy += d.energy;
                         for (const unsigned int v : surface.triangles[t])
                           r.max_penetration =
                             std::max(r.max_penetration,
                                      obstacles[o].obstacle.penetration(
                                        surface.position(v, u)));
                       });
      return result;
    }


    std::vector<double>
    ObstacleAssembler::vertex_penetrations(const Vector<double> &u) const
    {
      std::vector<double> d(surface.X.size(), 0.);
      for (unsigned int t = 0; t < surface.n_triangles(); ++t)
        for (const auto &o : obstacles)
          if (pushes(o, t))
            for (const unsigned int v : surface.triangles[t])
              d[v] =
                std::max(d[v], o.obstacle.penetration(surface.position(v, u)));
      return d;
    }


    double
    ObstacleAssembler::uzawa_map(const Vector<double> &u,
                                 std::vector<double>  &G) const
    {
      // G(lambda)_a = max(0, lambda_a + eps d_a) for each vertex an
      // obstacle pushes; G - lambda moves lambda_a / eps by the
      // constraint's violation there: the penetration where the vertex
      // carries pressure, the gap where its multiplier still pushes
      G                            = multipliers;
      double             violation = 0.;
      const unsigned int n_v       = surface.X.size();
      for (unsigned int o = 0; o < obstacles.size(); ++o)
        {
          const double eps = obstacles[o].penalty;
          for (const unsigned int v : pushed_vertices[o])
            {
              const double d =
                obstacles[o].obstacle.penetration(surface.position(v, u));
              const double lambda = multipliers[o * n_v + v];
              G[o * n_v + v]      = std::max(0., lambda + eps * d);
              violation =
                std::max(violation, std::abs(G[o * n_v + v] - lambda) / eps);
            }
        }
      return violation;
    }


    double
    ObstacleAssembler::violation(const Vector<double> &u) const
    {
      std::vector<double> G;
      return uzawa_map(u, G);
    }


    double
    ObstacleAssembler::update_multipliers(const Vector<double> &u,
                                          const double          tolerance,
                                          const bool            first)
    {
      std::vector<double> G;
      const double        violation = uzawa_map(u, G);
      if (first)
        history.clear();
      if (!(violation > tolerance))
        return violation;
      std::vector<double> f(G.size());
      for (unsigned int i = 0; i < f.size(); ++i)
        f[i] = G[i] - multipliers[i];
      // Anderson acceleration of the fixed-point iteration (memory
      // max_history): lambda_new = G_k - dG gamma, gamma minimizing
      // |f_k - dF gamma| over the differences of the last iterates; plain
      // Uzawa (lambda_new = G_k) at the first update of an increment. The
      // projection onto lambda >= 0 follows.
      std::vector<double> next = G;
      const unsigned int  m    = history.size();
      if (m > 0)
        {
          FullMatrix<double>               A(m, m);
          Vector<double>                   b(m), gamma(m);
          std::vector<std::vector<double>> dF(m, std::vector<double>(f.size())),
            dG(m, std::vector<double>(f.size()));
          for (unsigned int j = 0; j < m; ++j)
            for (unsigned int i = 0; i < f.size(); ++i)
              {
                dF[j][i] = f[i] - history[j].f[i];
                dG[j][i] = G[i] - history[j].G[i];
              }
          double trace = 0.;
          for (unsigned int j = 0; j < m; ++j)
            {
              for (unsigned int l = 0; l < m; ++l)
                for (unsigned int i = 0; i < f.size(); ++i)
                  A(j, l) += dF[j][i] * dF[l][i];
              for (unsigned int i = 0; i < f.size(); ++i)
                b[j] += dF[j][i] * f[i];
              trace += A(j, j);
            }
          for (unsigned int j = 0; j < m; ++j)
            A(j, j) += 1e-12 * trace + 1e-300;
          A.gauss_jordan();
          A.vmult(gamma, b);
          for (unsigned int j = 0; j < m; ++j)
            for (unsigned int i = 0; i < f.size(); ++i)
              next[i] -= gamma[j] * dG[j][i];
          for (double &x : next)
            x = std::max(0., x);
        }
      history.push_front({G, f});
      if (history.size() > max_history)
        history.pop_back();
      multipliers.swap(next);
      return violation;
    }


    const std::vector<double> &
    ObstacleAssembler::multiplier_values() const
    {
      return multipliers;
    }


    void
    ObstacleAssembler::set_multiplier_values(const std::vector<double> &values)
    {
      AssertThrow(values.size() == multipliers.size(),
                  ExcMessage("the contact multipliers read do not fit the "
                             "obstacles and the mesh"));
      multipliers = values;
    }


    double
    ObstacleAssembler::max_penetration(const Vector<double> &u) const
    {
      const std::vector<double> d = vertex_penetrations(u);
      return d.empty() ? 0. : *std::max_element(d.begin(), d.end());
    }
  } // namespace Contact
} // namespace TissueContact
