#include <tissue_contact/contact/contact_assembler.h>

namespace TissueContact
{
  namespace Contact
  {
    ContactAssembler::ContactAssembler(
      const Elasticity::Discretization   &disc,
      const std::set<types::boundary_id> &contact_surfaces,
      const std::vector<ObstacleContact> &obstacles)
      : obstacles(obstacles)
    {
      const auto &tria = disc.dof_handler.get_triangulation();
      X                = tria.get_vertices();
      vertex_dofs.resize(X.size());
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < 3; ++c)
              vertex_dofs[cell->vertex_index(v)][c] =
                cell->vertex_dof_index(v, c);
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() &&
                contact_surfaces.count(face->boundary_id()) > 0)
              {
                triangles.push_back({face->vertex_index(0),
                                     face->vertex_index(1),
                                     face->vertex_index(2)});
                triangle_body.push_back(cell->material_id());
              }
        }
    }


    Point<3>
    ContactAssembler::position(const unsigned int    v,
                               const Vector<double> &u) const
    {
      return Point<3>(X[v][0] + u[vertex_dofs[v][0]],
                      X[v][1] + u[vertex_dofs[v][1]],
                      X[v][2] + u[vertex_dofs[v][2]]);
    }


    template <typename F>
    void
    ContactAssembler::for_each_obstacle_contact(const Vector<double> &u,
                                                const F              &f) const
    {
      for (unsigned int t = 0; t < triangles.size(); ++t)
        {
          const std::array<Point<3>, 3> tri = {position(triangles[t][0], u),
                                               position(triangles[t][1], u),
                                               position(triangles[t][2], u)};
          for (const auto &o : obstacles)
            {
              if (!o.bodies.empty() && o.bodies.count(triangle_body[t]) == 0)
                continue;
              bool penetrates = false;
              for (const auto &p : tri)
                penetrates = penetrates || o.obstacle.penetration(p) > 0.;
              if (penetrates)
                f(t,
                  tri,
                  o,
                  obstacle_derivatives_ad(o.obstacle, tri, o.penalty));
            }
        }
    }


    void
    ContactAssembler::assemble(const Vector<double> &u,
                               Vector<double>       &R,
                               SparseMatrix<double> *K) const
    {
      for_each_obstacle_contact(u,
                                [&](const unsigned int t,
                                    const std::array<Point<3>, 3> &,
                                    const ObstacleContact &,
                                    const PairDerivatives &d) {
                                  std::array<types::global_dof_index, 9> dofs;
                                  for (unsigned int a = 0; a < 3; ++a)
                                    for (unsigned int c = 0; c < 3; ++c)
                                      dofs[3 * a + c] =
                                        vertex_dofs[triangles[t][a]][c];
                                  for (unsigned int i = 0; i < 9; ++i)
                                    {
                                      R[dofs[i]] += d.gradient[i];
                                      if (K != nullptr)
                                        for (unsigned int j = 0; j < 9; ++j)
                                          K->add(dofs[i],
                                                 dofs[j],
                                                 d.hessian(i, j));
                                    }
                                });
    }


    double
    ContactAssembler::energy(const Vector<double> &u) const
    {
      double W = 0.;
      for (unsigned int t = 0; t < triangles.size(); ++t)
        {
          const std::array<Point<3>, 3> tri = {position(triangles[t][0], u),
                                               position(triangles[t][1], u),
                                               position(triangles[t][2], u)};
          for (const auto &o : obstacles)
            if (o.bodies.empty() || o.bodies.count(triangle_body[t]) > 0)
              W += obstacle_energy<double>(o.obstacle, tri, o.penalty);
        }
      return W;
    }


    Tensor<1, 3>
    ContactAssembler::obstacle_force(const Vector<double> &u) const
    {
      Tensor<1, 3> force;
      for_each_obstacle_contact(u,
                                [&](const unsigned int,
                                    const std::array<Point<3>, 3> &,
                                    const ObstacleContact &,
                                    const PairDerivatives &d) {
                                  for (unsigned int a = 0; a < 3; ++a)
                                    for (unsigned int c = 0; c < 3; ++c)
                                      force[c] -= d.gradient[3 * a + c];
                                });
      return force;
    }


    double
    ContactAssembler::max_obstacle_penetration(const Vector<double> &u) const
    {
      double d = 0.;
      for (unsigned int t = 0; t < triangles.size(); ++t)
        for (const auto &o : obstacles)
          if (o.bodies.empty() || o.bodies.count(triangle_body[t]) > 0)
            for (const unsigned int v : triangles[t])
              d = std::max(d, o.obstacle.penetration(position(v, u)));
      return d;
    }
  } // namespace Contact
} // namespace TissueContact
