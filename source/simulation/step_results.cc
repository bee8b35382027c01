#include <tissue_contact/simulation/step_results.h>

#include <numeric>

namespace TissueContact
{
  namespace
  {
    std::string
    body_name(const Scene::SceneParameters &p, const types::material_id id)
    {
      for (const auto &b : p.bodies)
        if (b.id == id)
          return b.name;
      return "body" + std::to_string(int(id));
    }
  } // namespace


  StepResults::StepResults(const Problem        &problem,
                           const Vector<double> &u,
                           const double          load_factor)
    : strain_energy(problem.strain_energy(u))
    , reactions(problem.reactions(u, load_factor))
  {
    const auto *assembler = problem.contact_assembler();
    if (assembler == nullptr)
      return;
    const auto &p = problem.get_scene().parameters;
    contact       = assembler->surface_state(problem.displacement(u));
    for (const auto &r : contact.interactions)
      contact_energy += r.energy;
    for (unsigned int i = 0; i < p.contact.pairs.size(); ++i)
      interaction_names.push_back(
        "pair" + std::to_string(i) + "_" +
        body_name(p, p.contact.pairs[i].surface_body) + "_in_" +
        body_name(p, p.contact.pairs[i].volume_body));
    for (unsigned int i = 0; i < p.contact.obstacles.size(); ++i)
      interaction_names.push_back("obstacle" + std::to_string(i) + "_" +
                                  (p.contact.obstacles[i].obstacle.type ==
                                       Contact::AnalyticObstacle::Type::plane ?
                                     "plane" :
                                     "sphere"));
  }


  std::vector<std::pair<std::string, double>>
  StepResults::columns() const
  {
    std::vector<std::pair<std::string, double>> c = {
      {"strain_energy", strain_energy}, {"contact_energy", contact_energy}};
    const char *xyz[3] = {"x", "y", "z"};
    for (unsigned int i = 0; i < contact.interactions.size(); ++i)
      {
        const auto        &r = contact.interactions[i];
        const std::string &n = interaction_names[i];
        for (unsigned int d = 0; d < 3; ++d)
          c.emplace_back(n + "_F" + xyz[d], r.force[d]);
        c.emplace_back(n + "_area", r.area);
        c.emplace_back(n + "_max_penetration", r.max_penetration);
      }
    for (const auto &r : reactions)
      {
        for (unsigned int d = 0; d < 3; ++d)
          c.emplace_back(r.name + "_F" + xyz[d], r.force[d]);
        for (unsigned int d = 0; d < 3; ++d)
          c.emplace_back(r.name + "_M" + xyz[d], r.moment[d]);
      }
    return c;
  }


  void
  StepResults::print(std::ostream &out) const
  {
    out << "  strain energy " << strain_energy;
    if (!contact.interactions.empty())
      out << ", contact energy " << contact_energy;
    out << "\n";
    for (unsigned int i = 0; i < contact.interactions.size(); ++i)
      {
        const auto &r = contact.interactions[i];
        out << "  contact " << interaction_names[i] << ": force on the surface "
            << "side (" << r.force << "), area " << r.area
            << ", largest penetration " << r.max_penetration << "\n";
      }
    for (const auto &r : reactions)
      out << "  reaction " << r.name << ": force (" << r.force << "), moment ("
          << r.moment << ") about (" << r.centroid << ")\n";
  }
} // namespace TissueContact
