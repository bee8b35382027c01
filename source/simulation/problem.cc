#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/pattern_rows.h>
#include <tissue_contact/base/timing.h>
#include <tissue_contact/simulation/problem.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <set>

namespace TissueContact
{
  Problem::Problem(const Scene::SceneParameters &parameters)
    : scene(parameters)
    , disc(scene.triangulation,
           parameters.degree,
           parameters.stiffness_quadrature == "reduced",
           parameters.dof_numbering == "Cuthill-McKee")
    , assembler(disc, scene.body_data(), scene.dead_loads())
    , prescribed(scene.prescribed_dofs(disc))
    , coupling_margin(0.5 *
                      GridTools::minimal_cell_diameter(scene.triangulation))
  {
    // contact only where the scene asks for it: no obstacle and no pair,
    // no contact search
    if (parameters.contact.enabled())
      contact =
        std::make_unique<Contact::ContactAssembler>(disc, parameters.contact);
    // a body whose material depth is zero everywhere cannot be entered: the
    // penalty of its pairs would do nothing, silently
    if (contact && !parameters.contact.pairs.empty())
      {
        const std::vector<double>           &depth = contact->vertex_depth();
        std::map<types::material_id, double> largest;
        for (const auto &cell : scene.triangulation.active_cell_iterators())
          {
            const auto body =
              Contact::body_of_material(parameters.contact.body_of_material,
                                        cell->material_id());
            for (const unsigned int v : cell->vertex_indices())
              largest[body] =
                std::max(largest[body], depth[cell->vertex_index(v)]);
          }
        for (unsigned int i = 0; i < parameters.contact.pairs.size(); ++i)
          {
            const auto  id   = parameters.contact.pairs[i].volume_body;
            std::string name = "material id " + std::to_string(id);
            for (const auto &b : parameters.bodies)
              if (b.id == id)
                name =
                  "'" + b.name + "' (material id " + std::to_string(id) + ")";
            AssertThrow(largest[id] > 0.,
                        ExcMessage(
                          "Contact pair " + std::to_string(i) + ": body " +
                          name +
                          " has material depth zero everywhere (every vertex "
                          "lies on a contact surface), so nothing can "
                          "penetrate it and the pair would push nothing; "
                          "refine it so that it has vertices inside, or list "
                          "fewer of its boundary ids as Contact surfaces"));
          }
      }
    const auto free_bodies = scene.free_rigid_bodies(disc);
    if (!free_bodies.empty())
      {
        rigid =
          std::make_unique<Rigid::FreeRigidBodies>(disc.n_dofs(), free_bodies);
        for (const auto &p : prescribed)
          AssertThrow(!rigid->is_slave(p.dof),
                      ExcMessage(
                        "a node of a free rigid body is also prescribed (by a "
                        "Dirichlet condition or a body with a prescribed "
                        "motion) at " +
                        Utilities::to_string(p.X[0]) + ", " +
                        Utilities::to_string(p.X[1]) + ", " +
                        Utilities::to_string(p.X[2]) +
                        "; a free body's motion is unknown: prescribe none "
                        "of its boundary, or make it a prescribed rigid "
                        "body"));
      }
    rebuild_sparsity_pattern(Vector<double>(n_dofs()));
  }


  const Vector<double> &
  Problem::fe_displacement(const Vector<double> &u) const
  {
    if (!rigid)
      return u;
    rigid->expand(u, u_fe);
    return u_fe;
  }


  Vector<double>
  Problem::displacement(const Vector<double> &u) const
  {
    if (!rigid)
      return u;
    Vector<double> result;
    rigid->expand(u, result);
    return result;
  }


  const std::vector<double> *
  Problem::depth_field() const
  {
    return contact && !scene.parameters.contact.pairs.empty() ?
             &contact->vertex_depth() :
             nullptr;
  }


  double
  Problem::max_relative_penetration(const Vector<double> &u) const
  {
    if (!contact || scene.parameters.contact.pairs.empty())
      return 0.;
    std::vector<double> h(scene.triangulation.n_vertices(),
                          std::numeric_limits<double>::max());
    for (const auto &cell : scene.triangulation.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        h[cell->vertex_index(v)] =
          std::min(h[cell->vertex_index(v)], cell->diameter());
    double ratio = 0.;
    for (const auto &[v, d] : contact->body_penetrations(fe_displacement(u)))
      ratio = std::max(ratio, d / h[v]);
    return ratio;
  }


  void
  Problem::rebuild_sparsity_pattern(const Vector<double> &u,
                                    const bool            keep_couplings)
  {
    const auto scope = time_section(timer, "contact: pattern build");
    ++n_pattern_builds;
    const bool body_contact =
      contact && !scene.parameters.contact.pairs.empty();
    if (!body_contact && !rigid)
      sparsity.copy_from(assembler.sparsity_pattern());
    else
      {
        // the finite element pattern's rows copied from the one the
        // discretization built once (a fraction of the time of building it
        // again from the cells: the full knee rebuilds its pattern some 400
        // times as its contact zones move), the contact couplings merged
        // into them, the rigid bodies' rows added, and the rows written
        // into the pattern at once
        PatternRows rows =
          rows_of(keep_couplings ? sparsity : assembler.sparsity_pattern());
        if (keep_couplings && rigid)
          {
            // the finite element rows as they were before the bodies'
            // couplings were added: those are numbered after all finite
            // element DoFs, at the end of each row, and in rows of their own
            rows.resize(assembler.sparsity_pattern().n_rows());
            for (auto &row : rows)
              while (!row.empty() && row.back() >= rows.size())
                row.pop_back();
          }
        // the rows kept hold the couplings found at the builds before, and
        // only those near the ones found missing are searched for
        if (body_contact)
          contact->add_couplings(fe_displacement(u),
                                 coupling_margin,
                                 rows,
                                 keep_couplings);
        if (rigid)
          rigid->add_couplings(rows);
        to_pattern(rows, sparsity);
      }
    assembler.use_matrix_pattern(sparsity);
  }


  bool
  Problem::update_multipliers(const Vector<double> &u, const unsigned int k)
  {
    const auto &c = scene.parameters.contact;
    if (!c.augmented_lagrangian || !contact ||
        contact->obstacle_assembler() == nullptr)
      return false;
    const double tolerance = c.penetration_tolerance;
    auto        *obstacles = contact->obstacle_assembler();
    if (k >= c.max_multiplier_updates)
      {
        const double violation = obstacles->violation(fe_displacement(u));
        if (violation > tolerance)
          multiplier_warning_lines.push_back(
            "after " + std::to_string(k) +
            " multiplier updates the obstacle contact is violated by " +
            Utilities::to_string(violation) + " (Penetration tolerance " +
            Utilities::to_string(tolerance) +
            "); the increment is kept. More Maximum multiplier updates or a "
            "larger Penalty factor converge faster");
        return false;
      }
    return obstacles->update_multipliers(fe_displacement(u),
                                         tolerance,
                                         k == 0) > tolerance;
  }


  std::vector<double>
  Problem::multipliers() const
  {
    return contact && contact->obstacle_assembler() != nullptr &&
               scene.parameters.contact.augmented_lagrangian ?
             contact->obstacle_assembler()->multiplier_values() :
             std::vector<double>();
  }


  void
  Problem::set_multipliers(const std::vector<double> &values)
  {
    if (!values.empty())
      contact->obstacle_assembler()->set_multiplier_values(values);
  }


  std::vector<std::string>
  Problem::warnings() const
  {
    const auto              &c = scene.parameters.contact;
    std::vector<std::string> result;
    for (unsigned int i = 0; i < c.pairs.size(); ++i)
      if (c.pairs[i].penalty == 0.)
        result.push_back("Contact/Pair " + std::to_string(i) +
                         " has Penalty factor 0: it pushes nothing and the "
                         "bodies pass through each other (a baseline "
                         "without contact; else give it a penalty > 0)");
    if (c.augmented_lagrangian && !c.pairs.empty())
      result.push_back("Contact/Augmented Lagrangian acts on the obstacles "
                       "only: the body pairs keep the plain penalty and its "
                       "penetration");
    for (unsigned int i = 0; i < c.obstacles.size(); ++i)
      if (c.obstacles[i].penalty == 0.)
        result.push_back("Contact/Obstacle " + std::to_string(i) +
                         " has Penalty factor 0: it pushes nothing and the "
                         "bodies pass through it (give it a penalty > 0)");
    return result;
  }


  std::vector<Problem::Reaction>
  Problem::reactions(const Vector<double> &u, const double load_factor) const
  {
    const auto                                       &p = scene.parameters;
    std::vector<Reaction>                             result;
    std::map<const Scene::PrescribedMotion *, size_t> group_of;
    for (unsigned int i = 0; i < p.dirichlet.size(); ++i)
      {
        group_of[&p.dirichlet[i].motion] = result.size();
        result.push_back({"dirichlet" + std::to_string(i) + "_boundary" +
                            std::to_string(int(p.dirichlet[i].boundary_id)),
                          {},
                          {},
                          {}});
      }
    for (const auto &b : p.bodies)
      if (b.prescribed_rigid())
        {
          group_of[&b.rigid_motion] = result.size();
          result.push_back({"body_" + b.name, {}, {}, {}});
        }
    if (result.empty())
      return result;

    const Vector<double> &x = fe_displacement(u);
    Vector<double>        R(disc.n_dofs());
    AssertThrow(assembler.assemble(x, load_factor, R, nullptr),
                ExcMessage("the reactions were asked for at a state with an "
                           "inverted element"));
    if (contact)
      contact->assemble(x, R, nullptr);

    // each DoF once, in the group of its first condition
    std::vector<std::pair<const Scene::PrescribedDof *, size_t>> dofs;
    std::set<types::global_dof_index>                            seen;
    for (const auto &d : prescribed)
      if (seen.insert(d.dof).second)
        dofs.emplace_back(&d, group_of.at(d.motion));
    const auto point_dofs = disc.support_point_dofs();
    const auto position   = [&](const Scene::PrescribedDof &d) {
      const std::array<types::global_dof_index, 3> &own = point_dofs[d.dof];
      return Point<3>(d.X[0] + x[own[0]],
                      d.X[1] + x[own[1]],
                      d.X[2] + x[own[2]]);
    };
    std::vector<unsigned int> n(result.size(), 0);
    for (const auto &[d, g] : dofs)
      {
        result[g].centroid += position(*d);
        ++n[g];
      }
    for (unsigned int g = 0; g < result.size(); ++g)
      if (n[g] > 0)
        result[g].centroid /= n[g];
    for (const auto &[d, g] : dofs)
      {
        Tensor<1, 3> f;
        f[d->component] = R[d->dof];
        result[g].force += f;
        result[g].moment +=
          cross_product_3d(position(*d) - result[g].centroid, f);
      }
    return result;
  }


  bool
  Problem::update_sparsity_pattern(const Vector<double> &u,
                                   const bool            keep_couplings)
  {
    if (!contact || scene.parameters.contact.pairs.empty())
      return false;
    if (!keep_couplings)
      next_build_fresh = true;
    if (contact->has_couplings(fe_displacement(u), sparsity))
      return false;
    rebuild_sparsity_pattern(u, keep_couplings && !next_build_fresh);
    next_build_fresh = false;
    return true;
  }


  bool
  Problem::assemble(const Vector<double> &u,
                    const double          load_factor,
                    Vector<double>       &R,
                    SparseMatrix<double> *K)
  {
    // with free rigid bodies: assemble at the finite element displacement,
    // then condense onto the bodies' unknowns (doc/theory/07)
    const Vector<double> &x = fe_displacement(u);
    Vector<double>       &r = rigid ? R_fe : R;
    if (!assembler.assemble(x, load_factor, r, K))
      return false;
    if (contact)
      {
        const auto scope = time_section(timer, "assembly: contact part");
        contact->assemble(x, r, K);
      }
    if (rigid)
      rigid->condense(u, R_fe, R, K);
    return true;
  }


  double
  Problem::energy(const Vector<double> &u, const double load_factor) const
  {
    const Vector<double> &x = fe_displacement(u);
    const double          W = assembler.energy(x, load_factor);
    return contact ? W + contact->energy(x) : W;
  }


  double
  Problem::energy(const Vector<double> &u,
                  const double          load_factor,
                  std::vector<double>  &contact_energies) const
  {
    const Vector<double> &x = fe_displacement(u);
    contact_energies = contact ? contact->energies(x) : std::vector<double>();
    return std::accumulate(contact_energies.begin(),
                           contact_energies.end(),
                           assembler.energy(x, load_factor));
  }


  std::map<types::global_dof_index, double>
  Problem::prescribed_values(const double load_factor) const
  {
    std::map<types::global_dof_index, double> values;
    for (const auto &p : prescribed)
      values[p.dof] = p.motion->displacement(p.X, load_factor)[p.component];
    return values;
  }


  double
  Problem::external_force_norm(const double load_factor) const
  {
    return load_factor * assembler.external_force().l2_norm();
  }


  Vector<double>
  Problem::quasi_viscosity_diagonal(const double eta) const
  {
    const Vector<double> D = assembler.quasi_viscosity_diagonal(eta);
    return rigid ? rigid->condense_diagonal(D) : D;
  }


  std::vector<Vector<double>>
  Problem::near_null_space() const
  {
    std::vector<Vector<double>> modes = disc.rigid_body_modes();
    if (!rigid)
      return modes;
    // the rotations' axes pass through the mean support point
    const Point<3> mean = disc.mean_support_point();
    for (unsigned int k = 0; k < 6; ++k)
      {
        Vector<double> &v = modes[k];
        for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
          if (rigid->is_slave(i))
            v[i] = 0.;
        Vector<double> full(n_dofs());
        for (types::global_dof_index i = 0; i < disc.n_dofs(); ++i)
          full[i] = v[i];
        for (unsigned int b = 0; b < rigid->n_bodies(); ++b)
          {
            const auto   q = rigid->first_unknown(b);
            Tensor<1, 3> t, theta;
            if (k < 3)
              t[k] = 1.;
            else
              {
                theta[k - 3] = 1.;
                t            = cross_product_3d(theta, rigid->center(b) - mean);
              }
            for (unsigned int j = 0; j < 3; ++j)
              {
                full[q + j]     = t[j];
                full[q + 3 + j] = theta[j];
              }
          }
        v = full;
      }
    return modes;
  }
} // namespace TissueContact
