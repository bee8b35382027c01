#include <tissue_contact/base/parameter_tools.h>
#include <tissue_contact/contact/contact_parameters.h>

#include <deal.II/base/exceptions.h>

namespace TissueContact
{
  namespace Contact
  {
    void
    ObstacleContact::declare_parameters(ParameterHandler &prm)
    {
      add_selection<AnalyticObstacle::Type>(
        prm,
        "Type",
        obstacle.type,
        {{"plane", AnalyticObstacle::Type::plane},
         {"sphere", AnalyticObstacle::Type::sphere}},
        "A rigid plane (the bodies stay on the side its Normal points to) "
        "or sphere (the bodies stay outside).");
      prm.add_parameter("Point",
                        obstacle.point,
                        "A point of the plane, in length units" +
                          vector_pattern_doc,
                        vector_pattern());
      prm.add_parameter("Normal",
                        obstacle.normal,
                        "Normal of the plane, pointing out of the obstacle; "
                        "any nonzero length (normalized when read)" +
                          vector_pattern_doc,
                        vector_pattern());
      prm.add_parameter("Center",
                        obstacle.center,
                        "Center of the sphere, in length units" +
                          vector_pattern_doc,
                        vector_pattern());
      prm.add_parameter("Radius",
                        obstacle.radius,
                        "Radius of the sphere, in length units; > 0.",
                        Patterns::Double(0.));
      prm.add_parameter(
        "Penalty factor",
        penalty,
        "eps_p in W = eps_p/2 int d^2 da over the penetrating part of each "
        "contact triangle (d: penetration depth); the penetration falls as "
        "1/eps_p. Units: stress per length (consistent units); >= 0 (0: the "
        "obstacle pushes nothing, with a warning).",
        Patterns::Double(0.));
      prm.add_parameter("Bodies",
                        bodies,
                        "Material ids (0..255) of the bodies the obstacle "
                        "pushes (empty: all bodies with contact surfaces).",
                        Patterns::List(Patterns::Integer(0, 255)));
    }


    void
    ObstacleContact::parse_parameters(ParameterHandler &)
    {
      AssertThrow(obstacle.normal.norm() > 0.,
                  ExcMessage("Obstacle: the Normal must not be zero"));
      obstacle.normal /= obstacle.normal.norm();
    }


    void
    BodyContact::declare_parameters(ParameterHandler &prm)
    {
      prm.add_parameter("Surface body",
                        surface_body,
                        "Material id (0..255) of the body whose contact "
                        "triangles are pushed out of the other body (for a "
                        "body of several materials: their Contact body).",
                        Patterns::Integer(0, 255));
      prm.add_parameter("Volume body",
                        volume_body,
                        "Material id (0..255) of the body whose tetrahedra "
                        "and material depth push; equal to Surface body for "
                        "self-contact. Declare both directions for two "
                        "bodies.",
                        Patterns::Integer(0, 255));
      prm.add_parameter(
        "Penalty factor",
        penalty,
        "eps_p in W = eps_p/2 int g^2 da over every triangle-tetrahedron "
        "intersection (g: the material depth of the volume body). Units: "
        "stress per length (consistent units); >= 0 (0: the pair pushes "
        "nothing, a baseline without contact, with a warning).",
        Patterns::Double(0.));
      add_selection<bool>(
        prm,
        "Method",
        point_collocation,
        {{"area integration", false}, {"point collocation", true}},
        "area integration: the penalty integrated exactly over every "
        "triangle-tetrahedron intersection (continuous forces); point "
        "collocation: sampled at the triangle vertices only (dissertation "
        "5.3.5, the baseline that chatters).");
    }


    void
    Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.add_parameter("Contact surfaces",
                        surfaces,
                        "Boundary ids (0..255) whose faces are contact "
                        "surfaces (a cut plane with a Dirichlet condition is "
                        "not). Empty: no contact, and no contact search at "
                        "all.",
                        Patterns::List(Patterns::Integer(0, 255)));
      // the counts' defaults (the file sets them; the subsections declared
      // below are as many as the vectors hold)
      n_obstacles = 0;
      n_pairs     = 0;
      prm.add_parameter("Number of obstacles",
                        n_obstacles,
                        "How many subsections 'Obstacle 0', ... follow "
                        "(0..64).",
                        Patterns::Integer(0, 64));
      prm.add_parameter("Number of pairs",
                        n_pairs,
                        "How many subsections 'Pair 0', ... follow (0..64).",
                        Patterns::Integer(0, 64));
      prm.add_parameter(
        "Augmented Lagrangian",
        augmented_lagrangian,
        "Static runs: after each converged load increment update every "
        "contact vertex's multiplier lambda (the pressure it carries) to "
        "max(0, lambda + eps_p d), accelerated (Anderson), and solve the "
        "increment again, until the contact holds within 'Penetration "
        "tolerance': no vertex penetrates an obstacle by more, and no "
        "multiplier pushes a vertex that lifted off by more "
        "(doc/theory/05-contact.md sec. 6.1). The penetration then no longer "
        "depends on the Penalty factor, which can be moderate. Obstacles "
        "only: body pairs keep the plain penalty.",
        Patterns::Bool());
      prm.add_parameter("Penetration tolerance",
                        penetration_tolerance,
                        "Largest violation of the obstacle contact (length "
                        "units: a penetration, or the gap of a vertex whose "
                        "multiplier still pushes) the augmented-Lagrangian "
                        "loop accepts; > 0.",
                        Patterns::Double(0.));
      prm.add_parameter("Maximum multiplier updates",
                        max_multiplier_updates,
                        "Augmented-Lagrangian updates per load increment "
                        "(1..1000); past them the increment is kept with a "
                        "warning in the log.",
                        Patterns::Integer(1, 1000));
      for (unsigned int i = 0; i < obstacles.size(); ++i)
        {
          prm.enter_subsection("Obstacle " + std::to_string(i));
          obstacles[i].declare_parameters(prm);
          prm.leave_subsection();
        }
      for (unsigned int i = 0; i < pairs.size(); ++i)
        {
          prm.enter_subsection("Pair " + std::to_string(i));
          pairs[i].declare_parameters(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }


    void
    Parameters::parse_parameters(ParameterHandler &prm)
    {
      for (auto &o : obstacles)
        o.parse_parameters(prm);
      for (unsigned int i = 0; i < obstacles.size(); ++i)
        {
          const std::string name = "Contact/Obstacle " + std::to_string(i);
          AssertThrow(obstacles[i].penalty < 1e100,
                      ExcMessage(name + ": Penalty factor " +
                                 Utilities::to_string(obstacles[i].penalty) +
                                 " is out of range: it must be below 1e100"));
          AssertThrow(
            obstacles[i].obstacle.type != AnalyticObstacle::Type::sphere ||
              (obstacles[i].obstacle.radius > 0. &&
               obstacles[i].obstacle.radius < 1e100),
            ExcMessage(name +
                       ": a sphere needs a Radius > 0 (and "
                       "below 1e100), not " +
                       Utilities::to_string(obstacles[i].obstacle.radius)));
        }
      for (unsigned int i = 0; i < pairs.size(); ++i)
        AssertThrow(pairs[i].penalty < 1e100,
                    ExcMessage("Contact/Pair " + std::to_string(i) +
                               ": Penalty factor " +
                               Utilities::to_string(pairs[i].penalty) +
                               " is out of range: it must be below 1e100"));
      if (augmented_lagrangian)
        {
          AssertThrow(!obstacles.empty(),
                      ExcMessage("Contact: Augmented Lagrangian = true acts "
                                 "on obstacles, and none is declared (body "
                                 "pairs keep the plain penalty)"));
          AssertThrow(penetration_tolerance > 0.,
                      ExcMessage("Contact: the augmented-Lagrangian loop "
                                 "needs a Penetration tolerance > 0"));
          for (unsigned int i = 0; i < obstacles.size(); ++i)
            AssertThrow(obstacles[i].penalty > 0.,
                        ExcMessage("Contact/Obstacle " + std::to_string(i) +
                                   ": the augmented-Lagrangian loop needs a "
                                   "Penalty factor > 0 (its multipliers "
                                   "grow by Penalty factor x penetration)"));
        }
      AssertThrow(!enabled() || !surfaces.empty(),
                  ExcMessage("Contact: obstacles or pairs are declared but no "
                             "Contact surfaces; list the boundary ids that "
                             "can touch"));
    }
  } // namespace Contact
} // namespace TissueContact
