#pragma once

// The distorted box of tetrahedra that several test programs build their
// bodies on (kept out of tests.h, which every test includes).

#include <deal.II/base/point.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <limits>

namespace TissueContactTests
{
  using namespace dealii;

  /** The box from the origin to @p upper in @p n subdivisions per
   * direction, each a cube cut into tetrahedra; its interior vertices moved
   * at random by @p distortion of the local cell size (a fixed @p seed, the
   * boundary kept); material 1 for the cells whose centre lies beyond
   * x = @p split_x, 0 for the others (all 0 by default). */
  inline void
  distorted_box(Triangulation<3>                  &tria,
                const std::array<unsigned int, 3> &n,
                const Point<3>                    &upper,
                const double                       distortion,
                const unsigned int                 seed,
                const double split_x = std::numeric_limits<double>::max())
  {
    GridGenerator::subdivided_hyper_rectangle_with_simplices(tria,
                                                             {n[0], n[1], n[2]},
                                                             Point<3>(0, 0, 0),
                                                             upper);
    GridTools::distort_random(distortion, tria, true, seed);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(cell->center()[0] > split_x ? 1 : 0);
  }
} // namespace TissueContactTests
