#include <tissue_contact/contact/obstacle_assembler.h>

#include <algorithm>

namespace TissueContact
{
  namespace Contact
  {
    ObstacleAssembler::ObstacleAssembler(
      const ContactSurface               &surface,
      const std::vector<ObstacleContact> &obstacles)
      : surface(surface)
      , obstacles(obstacles)
    {}


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
              bool penetrates = false;
              for (const auto &p : tri)
                penetrates = penetrates || o.obstacle.penetration(p) > 0.;
              if (penetrates)
                f(t,
                  i,
                  ad_derivatives(
                    [&](const auto &T) {
                      return obstacle_energy(o.obstacle, T, o.penalty);
                    },
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
              W[i] += obstacle_energy<double>(obstacles[i].obstacle,
                                              tri,
                                              obstacles[i].penalty);
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
                         r.area +=
                           obstacle_contact_area(obstacles[o].obstacle,
                                                 surface.triangle(t, u));
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
    ObstacleAssembler::max_penetration(const Vector<double> &u) const
    {
      const std::vector<double> d = vertex_penetrations(u);
      return d.empty() ? 0. : *std::max_element(d.begin(), d.end());
    }
  } // namespace Contact
} // namespace TissueContact
