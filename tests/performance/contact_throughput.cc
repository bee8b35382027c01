// Benchmark (not a test): the contact pipeline at three mesh sizes — tree
// build and refit time, candidate (triangle, tetrahedron) pairs, and the
// narrow-phase throughput of the pair kernel: energy only over all
// candidates; the hand-derived kernel (energy + gradient, and energy +
// gradient + Hessian) over the candidates, as the assembler calls it, and
// over the cutting pairs alone; the automatic-differentiation reference
// (energy + gradient + Hessian) over the cutting pairs.
//
//   cmake --build build --target performance
//   build/tests/performance/contact_throughput

#include <tissue_contact/contact/ad_reference.h>
#include <tissue_contact/contact/bounding_volume_tree.h>
#include <tissue_contact/contact/material_depth.h>
#include <tissue_contact/contact/penalty_energy.h>
#include <tissue_contact/contact/penalty_kernel.h>

#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <iomanip>
#include <iostream>
#include <limits>

using namespace dealii;
using namespace TissueContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << "Contact pipeline: a cube folded onto itself (self-contact "
               "candidates), 1 thread\n\n"
            << std::left << std::setw(10) << "tets" << std::setw(12)
            << "triangles" << std::setw(12) << "build ms" << std::setw(12)
            << "refit ms" << std::setw(12) << "candidates" << std::setw(12)
            << "cutting" << std::setw(12) << "W /s" << std::setw(12)
            << "cand. g /s" << std::setw(12) << "cand. gH /s" << std::setw(12)
            << "cut g /s" << std::setw(12) << "cut gH /s" << std::setw(12)
            << "AD gH /s"
            << "\n";
  for (const unsigned int n : {6u, 12u, 20u})
    {
      Triangulation<3> tria;
      GridGenerator::subdivided_hyper_rectangle_with_simplices(
        tria, {n, n, n}, Point<3>(0, 0, 0), Point<3>(1, 1, 1));
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            face->set_boundary_id(0);
      const std::vector<double> depth =
        Contact::compute_material_depth(tria, {0});

      // fold: move the vertices so that the boundary passes through the
      // interior (many intersecting pairs)
      std::vector<Point<3>> x = tria.get_vertices();
      for (auto &p : x)
        p = Point<3>(p[0] + 0.3 * std::sin(3. * p[2]),
                     p[1],
                     p[2] - 0.5 * p[2] * p[2] + 0.1 * std::sin(5. * p[0]));

      std::vector<std::array<unsigned int, 4>> tets;
      for (const auto &cell : tria.active_cell_iterators())
        tets.push_back({cell->vertex_index(0),
                        cell->vertex_index(1),
                        cell->vertex_index(2),
                        cell->vertex_index(3)});
      std::vector<std::array<unsigned int, 3>> triangles;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            triangles.push_back({face->vertex_index(0),
                                 face->vertex_index(1),
                                 face->vertex_index(2)});
      const auto boxes_of = [&](const std::vector<Point<3>> &y) {
        std::vector<BoundingBox<3>> boxes;
        for (const auto &t : tets)
          boxes.emplace_back(
            std::vector<Point<3>>{y[t[0]], y[t[1]], y[t[2]], y[t[3]]});
        return boxes;
      };

      Timer                       timer;
      Contact::BoundingVolumeTree tree(boxes_of(tria.get_vertices()));
      const double                t_build = timer.wall_time();
      timer.restart();
      const auto boxes = boxes_of(x);
      tree.refit(boxes);
      const double t_refit = timer.wall_time();

      std::vector<std::pair<unsigned int, unsigned int>> candidates;
      for (unsigned int t = 0; t < triangles.size(); ++t)
        {
          const auto    &tv = triangles[t];
          BoundingBox<3> b(std::vector<Point<3>>{x[tv[0]], x[tv[1]], x[tv[2]]});
          tree.for_each_overlap(b, [&](unsigned int k) {
            unsigned int shared = 0;
            for (const unsigned int a : tv)
              shared += std::count(tets[k].begin(), tets[k].end(), a);
            if (shared < 3)
              candidates.emplace_back(t, k);
          });
        }
      const auto pair = [&](const std::pair<unsigned int, unsigned int> &c) {
        const auto &tv = triangles[c.first];
        const auto &kv = tets[c.second];
        return std::make_tuple(
          std::array<Point<3>, 4>{x[kv[0]], x[kv[1]], x[kv[2]], x[kv[3]]},
          std::array<Point<3>, 3>{x[tv[0]], x[tv[1]], x[tv[2]]},
          std::array<double, 4>{
            depth[kv[0]], depth[kv[1]], depth[kv[2]], depth[kv[3]]});
      };
      std::vector<std::pair<unsigned int, unsigned int>> cutting;
      timer.restart();
      for (const auto &c : candidates)
        {
          const auto [tet, tri, g] = pair(c);
          if (Contact::penalty_energy_value(tet, tri, g, 1.) > 0.)
            cutting.push_back(c);
        }
      const double        t_energy = timer.wall_time();
      double              sink     = 0.;
      Contact::PairKernel kernel;
      // pairs per second of the hand-derived kernel over a list of pairs
      const auto rate =
        [&](const std::vector<std::pair<unsigned int, unsigned int>> &list,
            const bool with_hessian) {
          // the best of 7 passes: robust to other jobs on the machine
          double best = std::numeric_limits<double>::max();
          for (unsigned int pass = 0; pass < 7; ++pass)
            {
              timer.restart();
              for (const auto &c : list)
                {
                  const auto [tet, tri, g] = pair(c);
                  if (Contact::penalty_kernel(
                        tet, tri, g, 1., with_hessian, kernel))
                    sink += kernel.gradient[0];
                }
              best = std::min(best, timer.wall_time());
            }
          return list.size() / best;
        };
      const double candidates_g  = rate(candidates, false);
      const double candidates_gH = rate(candidates, true);
      const double cutting_g     = rate(cutting, false);
      const double cutting_gH    = rate(cutting, true);
      // the AD reference on (up to) 2000 cutting pairs
      const unsigned int n_ad = std::min<std::size_t>(cutting.size(), 2000);
      timer.restart();
      for (unsigned int i = 0; i < n_ad; ++i)
        {
          const auto [tet, tri, g] = pair(cutting[i]);
          sink += Contact::ad_derivatives(
                    [&](const auto &K, const auto &T) {
                      return Contact::penalty_energy(K, T, g, 1.);
                    },
                    true,
                    tet,
                    tri)
                    .hessian(0, 0);
        }
      const double ad_gH = n_ad / timer.wall_time();
      std::cout << std::setw(10) << tria.n_active_cells() << std::setw(12)
                << triangles.size() << std::fixed << std::setprecision(2)
                << std::setw(12) << 1e3 * t_build << std::setw(12)
                << 1e3 * t_refit << std::setw(12) << candidates.size()
                << std::setw(12) << cutting.size() << std::setprecision(0)
                << std::setw(12) << candidates.size() / t_energy
                << std::setw(12) << candidates_g << std::setw(12)
                << candidates_gH << std::setw(12) << cutting_g << std::setw(12)
                << cutting_gH << std::setw(12) << ad_gH << std::defaultfloat
                << "\n";
      if (sink == 12345.)
        std::cout << "";
    }
}
