#include <tissue_contact/contact/contact_assembler.h>

#include <numeric>

namespace TissueContact
{
  namespace Contact
  {
    ContactAssembler::ContactAssembler(const Discretization &disc,
                                       const Parameters     &parameters)
      : surface(disc, parameters.surfaces, parameters.body_of_material)
    {
      if (!parameters.pairs.empty())
        {
          bodies = std::make_unique<BodyContactAssembler>(
            surface,
            disc.dof_handler.get_triangulation(),
            parameters.surfaces,
            parameters.pairs,
            parameters.body_of_material);
          interactions.push_back(bodies.get());
        }
      if (!parameters.obstacles.empty())
        {
          obstacles =
            std::make_unique<ObstacleAssembler>(surface, parameters.obstacles);
          interactions.push_back(obstacles.get());
        }
    }


    void
    ContactAssembler::assemble(const Vector<double> &u,
                               Vector<double>       &R,
                               SparseMatrix<double> *K) const
    {
      // obstacles first: the order of the sums before the split
      for (auto it = interactions.rbegin(); it != interactions.rend(); ++it)
        (*it)->assemble(u, R, K);
    }


    std::vector<double>
    ContactAssembler::energies(const Vector<double> &u) const
    {
      std::vector<double> W;
      for (const auto *i : interactions)
        {
          const std::vector<double> w = i->energies(u);
          W.insert(W.end(), w.begin(), w.end());
        }
      return W;
    }


    std::vector<ContactResult>
    ContactAssembler::results(const Vector<double>      &u,
                              std::vector<Tensor<1, 3>> &surface_force,
                              std::vector<double>       &penetration) const
    {
      std::vector<ContactResult> result;
      for (const auto *i : interactions)
        {
          const std::vector<ContactResult> r =
            i->results(u, surface_force, penetration);
          result.insert(result.end(), r.begin(), r.end());
        }
      return result;
    }


    ContactAssembler::SurfaceState
    ContactAssembler::surface_state(const Vector<double> &u) const
    {
      SurfaceState              s;
      std::vector<Tensor<1, 3>> f(surface.X.size()), n;
      s.penetration.assign(f.size(), 0.);
      s.interactions = results(u, f, s.penetration);
      surface.vertex_areas_and_normals(u, s.area, n);
      s.traction.assign(f.size(), Tensor<1, 3>());
      s.pressure.assign(f.size(), 0.);
      for (unsigned int v = 0; v < f.size(); ++v)
        if (s.area[v] > 0.)
          {
            s.traction[v] = f[v] / s.area[v];
            s.pressure[v] = -s.traction[v] * n[v];
          }
      return s;
    }


    double
    ContactAssembler::energy(const Vector<double> &u) const
    {
      const std::vector<double> W = energies(u);
      return std::accumulate(W.begin(), W.end(), 0.);
    }


    void
    ContactAssembler::add_couplings(const Vector<double> &u,
                                    const double          margin,
                                    PatternRows          &rows,
                                    const bool            where_missing) const
    {
      for (const auto *i : interactions)
        i->add_couplings(u, margin, rows, where_missing);
    }


    bool
    ContactAssembler::has_couplings(const Vector<double>  &u,
                                    const SparsityPattern &pattern) const
    {
      for (const auto *i : interactions)
        if (!i->has_couplings(u, pattern))
          return false;
      return true;
    }


    unsigned int
    ContactAssembler::n_tree_rebuilds() const
    {
      return bodies ? bodies->n_tree_rebuilds() : 0;
    }


    const std::vector<double> &
    ContactAssembler::vertex_depth() const
    {
      static const std::vector<double> none;
      return bodies ? bodies->vertex_depth() : none;
    }


    double
    ContactAssembler::max_body_penetration(const Vector<double> &u) const
    {
      return bodies ? bodies->max_penetration(u) : 0.;
    }


    std::vector<double>
    ContactAssembler::pair_penetrations(const Vector<double> &u) const
    {
      return bodies ? bodies->pair_penetrations(u) : std::vector<double>();
    }


    std::vector<std::pair<unsigned int, double>>
    ContactAssembler::body_penetrations(const Vector<double> &u) const
    {
      return bodies ? bodies->penetrations(u) :
                      std::vector<std::pair<unsigned int, double>>();
    }


    Tensor<1, 3>
    ContactAssembler::obstacle_force(const Vector<double> &u) const
    {
      return obstacles ? obstacles->force(u) : Tensor<1, 3>();
    }


    double
    ContactAssembler::max_obstacle_penetration(const Vector<double> &u) const
    {
      return obstacles ? obstacles->max_penetration(u) : 0.;
    }


    void
    ContactAssembler::set_timer(TimerOutput *timer)
    {
      this->timer = timer;
      if (bodies)
        bodies->set_timer(timer);
    }
  } // namespace Contact
} // namespace TissueContact
