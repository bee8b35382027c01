#pragma once

#include <deal.II/grid/tria.h>

namespace TissueContact
{
  using namespace dealii;

  /**
   * Number the vertices of the coarse mesh @p triangulation in the
   * Cuthill-McKee order of their graph (two vertices joined where a cell
   * holds both) and its cells in the order of their lowest new vertex
   * (ties in their old order), and build it anew in that numbering. A mesh
   * generator writes its tetrahedra in no spatial order; afterwards cells
   * that follow each other are neighbours, and so are their entries in
   * every array indexed by cell or vertex and the unknowns that deal.II
   * distributes cell by cell (doc/theory/02-weak-form-and-linearization.md
   * sec. 2.3). The vertices' positions, each cell's vertices in their
   * local order, and the material, manifold and boundary ids are kept.
   * The triangulation must not be refined.
   */
  void
  order_mesh_by_cuthill_mckee(Triangulation<3> &triangulation);
} // namespace TissueContact
