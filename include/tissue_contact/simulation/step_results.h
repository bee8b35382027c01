#pragma once

#include <tissue_contact/contact/contact_assembler.h>
#include <tissue_contact/simulation/problem.h>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  /**
   * What a converged state of a Problem transmits, as the run summary, the
   * statistics file and the output's contact fields show it: the strain
   * energy and the contact energy, the result of every declared contact
   * interaction (force on its surface side, contact area, largest
   * penetration, energy; doc/theory/05-contact.md, sec. 9) with the
   * contact traction, pressure and penetration at every vertex, and the
   * reaction force and moment of every support (Problem::reactions()).
   * Computed only where the scene has what it needs: no contact, no
   * contact search.
   */
  struct StepResults
  {
    /** The results at the state @p u and load factor @p load_factor. */
    StepResults(const Problem        &problem,
                const Vector<double> &u,
                const double          load_factor);

    double strain_energy  = 0.;
    double contact_energy = 0.;
    /** Column-name stem of every interaction, in the order of
     * contact.interactions: "pair<i>_<surface>_in_<volume>" for the body
     * pairs, "obstacle<i>_<plane|sphere>" for the obstacles. */
    std::vector<std::string>                interaction_names;
    Contact::ContactAssembler::SurfaceState contact;
    std::vector<Problem::Reaction>          reactions;

    /** The statistics columns: strain_energy, contact_energy, then per
     * interaction <name>_Fx, _Fy, _Fz, _area, _max_penetration, then per
     * support <name>_Fx, _Fy, _Fz, _Mx, _My, _Mz. */
    std::vector<std::pair<std::string, double>>
    columns() const;

    /** The same as lines of the run summary. */
    void
    print(std::ostream &out) const;
  };
} // namespace TissueContact
