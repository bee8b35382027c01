// Material depth and the bounding-volume tree:
//  - the point-triangle distance behind the depth, in each of its seven
//    regions (interior, three edges, three vertices), against an
//    independent evaluation: the distance to the plane where the projection
//    falls inside, else the least distance to the three edge segments;
//  - the depth of a box mesh equals the analytic distance to its faces at
//    every vertex (exact: the faces are planar), also with only some faces
//    declared contact surfaces;
//  - the depth of a ball mesh approaches 1 - |x| at second order in h (the
//    facets of the discrete sphere sag by O(h^2));
//  - the tree's nearest query equals brute force;
//  - the broad phase: the candidate pairs (boundary triangle, tetrahedron)
//    of the tree equal a brute-force box test, before and after the mesh
//    moves and the tree is refitted, and after a rebuild (with the trees'
//    surface-area cost);
//  - the rejection before the clipping (pair_rejected()) against the
//    clipping itself, on random pairs sharing no vertex, one or two, and
//    on triangles just outside a face: no rejected pair has an
//    intersection of positive area or positive energy beyond roundoff.

#include "../tests.h"

#include <tissue_contact/contact/bounding_volume_tree.h>
#include <tissue_contact/contact/material_depth.h>
#include <tissue_contact/contact/pair_rejection.h>
#include <tissue_contact/contact/penalty_energy.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <array>
#include <set>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  void
  box_depth(const std::set<types::boundary_id> &contact,
            const std::string                  &name)
  {
    Triangulation<3> tria;
    const Point<3>   lo(0, 0, 0), hi(1, 0.5, 0.25);
    GridGenerator::subdivided_hyper_rectangle_with_simplices(tria,
                                                             {8, 4, 2},
                                                             lo,
                                                             hi);
    GridTools::distort_random(0.2, tria, true, 5);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          for (unsigned int d = 0; d < 3; ++d)
            {
              if (std::abs(face->center()[d] - lo[d]) < 1e-12)
                face->set_boundary_id(2 * d);
              if (std::abs(face->center()[d] - hi[d]) < 1e-12)
                face->set_boundary_id(2 * d + 1);
            }
    const std::vector<double> g =
      Contact::compute_material_depth(tria, contact);
    double error = 0., g_max = 0.;
    for (unsigned int i = 0; i < g.size(); ++i)
      {
        const Point<3> &p     = tria.get_vertices()[i];
        double          exact = 1e300;
        for (unsigned int d = 0; d < 3; ++d)
          {
            if (contact.count(2 * d))
              exact = std::min(exact, p[d] - lo[d]);
            if (contact.count(2 * d + 1))
              exact = std::min(exact, hi[d] - p[d]);
          }
        error = std::max(error, std::abs(g[i] - exact));
        g_max = std::max(g_max, g[i]);
      }
    deallog << "box, contact faces " << name << ": max depth " << g_max
            << ", max |g - analytic| " << error_bound(error, -14) << std::endl;
  }

  double
  ball_depth_error(const unsigned int refinements)
  {
    Triangulation<3> hex, tria;
    GridGenerator::hyper_ball(hex);
    hex.refine_global(refinements);
    GridGenerator::convert_hypercube_to_simplex_mesh(hex, tria);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(0);
    const std::vector<double> g = Contact::compute_material_depth(tria, {0});
    double                    error = 0.;
    for (unsigned int i = 0; i < g.size(); ++i)
      if (tria.get_used_vertices()[i])
        error = std::max(error,
                         std::abs(g[i] - (1. - tria.get_vertices()[i].norm())));
    return error;
  }

  void
  tree_queries()
  {
    // random boxes: nearest distance and overlap queries against brute force
    std::vector<BoundingBox<3>> boxes;
    std::vector<Point<3>>       centers;
    for (unsigned int i = 0; i < 500; ++i)
      {
        const Point<3> c(random_value(0, 1),
                         random_value(0, 1),
                         random_value(0, 1));
        const Point<3> h(random_value(0, 0.05),
                         random_value(0, 0.05),
                         random_value(0, 0.05));
        boxes.emplace_back(std::make_pair(Point<3>(c - h), Point<3>(c + h)));
        centers.push_back(c);
      }
    Contact::BoundingVolumeTree tree(boxes);
    unsigned int                nearest_mismatch = 0, overlap_mismatch = 0;
    unsigned long               checks = 0, brute = 0;
    for (unsigned int q = 0; q < 200; ++q)
      {
        const Point<3> p(random_value(-0.2, 1.2),
                         random_value(-0.2, 1.2),
                         random_value(-0.2, 1.2));
        double         best = 1e300;
        for (unsigned int i = 0; i < centers.size(); ++i)
          best = std::min(best, p.distance(centers[i]));
        const double found = tree.nearest(p, [&](unsigned int i, double) {
          ++checks;
          return p.distance(centers[i]);
        });
        nearest_mismatch += (found != best);
        brute += centers.size();

        const BoundingBox<3> query(
          std::make_pair(Point<3>(p - Point<3>(0.1, 0.1, 0.1)),
                         Point<3>(p + Point<3>(0.1, 0.1, 0.1))));
        std::set<unsigned int> a, b;
        tree.for_each_overlap(query, [&](unsigned int i) { a.insert(i); });
        for (unsigned int i = 0; i < boxes.size(); ++i)
          if (boxes[i].get_neighbor_type(query) != NeighborType::not_neighbors)
            b.insert(i);
        overlap_mismatch += (a != b);
      }
    deallog << "tree of 500 boxes: nearest mismatches " << nearest_mismatch
            << ", overlap mismatches " << overlap_mismatch
            << ", distance evaluations below 20 % of brute force: "
            << (checks < 0.2 * brute) << std::endl;
  }

  void
  broad_phase()
  {
    Triangulation<3> tria;
    GridGenerator::subdivided_hyper_rectangle_with_simplices(tria,
                                                             {4, 4, 4},
                                                             Point<3>(0, 0, 0),
                                                             Point<3>(1, 1, 1));
    const auto boxes_of = [&](const std::vector<Point<3>> &x) {
      std::vector<BoundingBox<3>> boxes;
      for (const auto &cell : tria.active_cell_iterators())
        {
          std::vector<Point<3>> v;
          for (const unsigned int i : cell->vertex_indices())
            v.push_back(x[cell->vertex_index(i)]);
          boxes.emplace_back(v);
        }
      return boxes;
    };
    std::vector<std::array<unsigned int, 3>> triangles;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          triangles.push_back({face->vertex_index(0),
                               face->vertex_index(1),
                               face->vertex_index(2)});

    std::vector<Point<3>>       x = tria.get_vertices();
    Contact::BoundingVolumeTree tree(boxes_of(x));
    const double                cost_at_build = tree.cost();
    for (unsigned int step = 0; step < 3; ++step)
      {
        if (step == 1)
          {
            // fold the cube (bend the upper half over the lower one) and
            // slide its top layer far along y: nodes that held neighbours
            // now span the gap
            for (auto &p : x)
              p = Point<3>(p[0] + 0.3 * std::sin(3. * p[2]) +
                             0.02 * random_value(-1, 1),
                           p[1] + 0.02 * random_value(-1, 1) +
                             (p[2] > 0.7 ? 3. : 0.),
                           p[2] - 0.4 * p[2] * p[2]);
            tree.refit(boxes_of(x));
          }
        if (step == 2)
          tree = Contact::BoundingVolumeTree(boxes_of(x));
        const auto    boxes  = boxes_of(x);
        unsigned long n_tree = 0, n_brute = 0;
        bool          equal = true;
        for (const auto &t : triangles)
          {
            const BoundingBox<3> tb(
              std::vector<Point<3>>{x[t[0]], x[t[1]], x[t[2]]});
            std::set<unsigned int> a, b;
            tree.for_each_overlap(tb, [&](unsigned int i) { a.insert(i); });
            for (unsigned int i = 0; i < boxes.size(); ++i)
              if (boxes[i].get_neighbor_type(tb) != NeighborType::not_neighbors)
                b.insert(i);
            n_tree += a.size();
            n_brute += b.size();
            equal = equal && (a == b);
          }
        static const char *names[] = {"reference mesh",
                                      "moved mesh, refitted tree",
                                      "moved mesh, rebuilt tree"};
        deallog << names[step] << ": " << triangles.size()
                << " boundary triangles x " << boxes.size()
                << " tetrahedra, candidate pairs " << n_tree
                << ", equal to brute force: " << equal
                << "; tree cost / cost at the first build "
                << std::setprecision(3) << tree.cost() / cost_at_build
                << std::setprecision(6) << std::endl;
      }
  }


  /** Distance from p to the segment [a, b]. */
  double
  segment_distance(const Point<3> &p, const Point<3> &a, const Point<3> &b)
  {
    const Tensor<1, 3> d = b - a;
    const double       t = std::clamp(((p - a) * d) / (d * d), 0., 1.);
    return p.distance(a + t * d);
  }

  void
  triangle_distance_regions()
  {
    const Point<3>     a(0., 0., 0.), b(1., 0.2, 0.1), c(0.3, 0.9, -0.2);
    const Tensor<1, 3> n = cross_product_3d(b - a, c - a);
    // region of the nearest point: 0 interior, 1-3 edges ab, bc, ca, 4-6
    // vertices a, b, c
    std::array<unsigned int, 7> count{};
    std::array<double, 7>       error{};
    for (unsigned int i = 0; i < 20000; ++i)
      {
        const Point<3> p(random_value(-1., 2.),
                         random_value(-1., 2.),
                         random_value(-1., 1.));
        // barycentric coordinates of the projection onto the plane
        const Point<3> q   = p - ((p - a) * n) / (n * n) * n;
        const double   A   = n * n;
        const double   l_a = cross_product_3d(b - q, c - q) * n / A,
                     l_b   = cross_product_3d(c - q, a - q) * n / A,
                     l_c   = 1. - l_a - l_b;
        double       reference;
        unsigned int region;
        if (l_a >= 0. && l_b >= 0. && l_c >= 0.)
          {
            reference = std::abs((p - a) * n) / std::sqrt(A);
            region    = 0;
          }
        else
          {
            const std::array<double, 3> e = {segment_distance(p, a, b),
                                             segment_distance(p, b, c),
                                             segment_distance(p, c, a)};
            const unsigned int          k =
              std::min_element(e.begin(), e.end()) - e.begin();
            reference = e[k];
            // an edge's end point is a vertex region
            const std::array<Point<3>, 3> v  = {a, b, c};
            const Point<3>               &s0 = v[k], &s1 = v[(k + 1) % 3];
            const Tensor<1, 3>            d = s1 - s0;
            const double                  t = ((p - s0) * d) / (d * d);
            region = t <= 0. ? 4 + k : (t >= 1. ? 4 + (k + 1) % 3 : 1 + k);
          }
        const double distance = Contact::point_triangle_distance(p, a, b, c);
        ++count[region];
        error[region] = std::max(error[region], std::abs(distance - reference));
      }
    const char *names[] = {"interior",
                           "edge ab",
                           "edge bc",
                           "edge ca",
                           "vertex a",
                           "vertex b",
                           "vertex c"};
    deallog << "point-triangle distance against the independent evaluation:"
            << std::endl;
    for (unsigned int r = 0; r < 7; ++r)
      deallog << "  " << names[r] << ": " << count[r] << " points, max error "
              << error_bound(error[r], -15) << std::endl;
  }

  /** The point with barycentric coordinates @p lambda in @p tet. */
  Point<3>
  from_barycentric(const std::array<Point<3>, 4> &tet,
                   const std::array<double, 4>   &lambda)
  {
    Point<3> p;
    for (unsigned int j = 0; j < 4; ++j)
      p += lambda[j] * tet[j];
    return p;
  }

  void
  rejection_against_clipping()
  {
    deallog << "rejection before the clipping against the clipping:"
            << std::endl;
    const std::array<std::string, 5> names = {
      {"no shared vertex",
       "one shared vertex",
       "two shared vertices (an edge)",
       "outside a face by 1e-8 to 1e-7",
       "outside a face by 1e-5 to 1e-3"}};
    for (unsigned int kind = 0; kind < 5; ++kind)
      {
        unsigned int n_rejected = 0, n_kept_cut = 0;
        // the largest area (relative to the triangle's) and energy of a
        // rejected pair: exactly zero, or the roundoff of a polygon that
        // degenerates to the shared edge, whose depth is zero
        double largest_area = 0., largest_W = 0.;
        for (unsigned int r = 0; r < 4000; ++r)
          {
            std::array<Point<3>, 4> tet = {{Point<3>(0, 0, 0),
                                            Point<3>(1, 0, 0),
                                            Point<3>(0, 1, 0),
                                            Point<3>(0, 0, 1)}};
            for (auto &v : tet)
              for (unsigned int d = 0; d < 3; ++d)
                v[d] += 0.25 * random_value(-1., 1.);
            std::array<Point<3>, 3>      tri;
            std::array<unsigned char, 3> shared = {{4, 4, 4}};
            std::array<double, 4>        g;
            for (auto &gj : g)
              gj = random_value(0., 0.2);
            const unsigned int n_shared = kind < 3 ? kind : 0;
            // the face the near-face triangles lie outside of
            const unsigned int face = r % 4;
            for (unsigned int a = 0; a < 3; ++a)
              if (a < n_shared)
                {
                  // a surface vertex: depth zero
                  tri[a]    = tet[a];
                  shared[a] = a;
                  g[a]      = 0.;
                }
              else if (kind < 3)
                tri[a] = Point<3>(random_value(-0.6, 1.3),
                                  random_value(-0.6, 1.3),
                                  random_value(-0.6, 1.3));
              else
                {
                  std::array<double, 4> lambda;
                  const double          delta = kind == 3 ?
                                                  random_value(1e-8, 1e-7) :
                                                  std::pow(10., random_value(-5., -3.));
                  double                sum   = 0.;
                  for (unsigned int j = 0; j < 4; ++j)
                    sum += (lambda[j] = j == face ? 0. : random_value(0., 1.));
                  for (unsigned int j = 0; j < 4; ++j)
                    lambda[j] =
                      j == face ? -delta : lambda[j] * (1. + delta) / sum;
                  tri[a] = from_barycentric(tet, lambda);
                }
            const bool rejected =
              Contact::pair_rejected(shared,
                                     Contact::TetrahedronFrame(tet),
                                     Contact::TriangleFrame(tri),
                                     tri);
            const double area = Contact::intersection_area(tet, tri);
            const double W    = Contact::penalty_energy_value(tet, tri, g, 1.);
            n_rejected += rejected;
            n_kept_cut += !rejected && W > 0.;
            if (rejected)
              {
                largest_area =
                  std::max(largest_area,
                           area / (0.5 * cross_product_3d(tri[1] - tri[0],
                                                          tri[2] - tri[0])
                                           .norm()));
                largest_W = std::max(largest_W, W);
              }
          }
        deallog << "  " << names[kind] << ": 4000 pairs, " << n_rejected
                << " rejected (largest area / triangle's "
                << error_bound(largest_area, -13) << ", largest energy "
                << error_bound(largest_W, -40) << "), kept with energy "
                << n_kept_cut << std::endl;
      }
  }
} // namespace

int
main()
{
  initlog();
  box_depth({0, 1, 2, 3, 4, 5}, "all");
  box_depth({4, 5}, "z- and z+");
  box_depth({1}, "x+");
  const double e1 = ball_depth_error(1), e2 = ball_depth_error(2),
               e3 = ball_depth_error(3);
  deallog << "ball: max |g - (1 - |x|)| " << std::setprecision(3) << e1 << ", "
          << e2 << ", " << e3 << " on three meshes (h halved), ratios "
          << std::fixed << std::setprecision(1) << e1 / e2 << ", " << e2 / e3
          << " (second order: 4)" << std::defaultfloat << std::setprecision(6)
          << std::endl;
  tree_queries();
  broad_phase();
  // last: they draw from the shared random generator
  triangle_distance_regions();
  rejection_against_clipping();
}
