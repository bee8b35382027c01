#pragma once

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>

#include <array>
#include <functional>
#include <limits>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    using namespace dealii;

    /**
     * Whether the boxes @p a and @p b overlap: the comparisons of deal.II's
     * BoundingBox::get_neighbor_type() (each lower bound shrunk by one
     * relative unit roundoff before it is compared with the other box's
     * upper bound), so the same pairs pass, but inline and without that
     * function's classification of the kind of neighbour (which allocates
     * two vectors per call: 10 % of a profile of the full knee).
     */
    inline bool
    overlap(const BoundingBox<3> &a, const BoundingBox<3> &b)
    {
      constexpr double shrink  = 1. - std::numeric_limits<double>::epsilon();
      const auto &[a_lo, a_hi] = a.get_boundary_points();
      const auto &[b_lo, b_hi] = b.get_boundary_points();
      for (unsigned int d = 0; d < 3; ++d)
        if (a_lo[d] * shrink > b_hi[d] || b_lo[d] * shrink > a_hi[d])
          return false;
      return true;
    }

    /**
     * A binary tree of axis-aligned bounding boxes over a set of objects
     * (tetrahedra, triangles), the broad phase of dissertation sec. 5.4.5:
     * built top-down by splitting each node's objects at the median of their
     * box centers along the node's largest extent; refitted bottom-up when
     * the objects move (the topology is kept, only the boxes grow or
     * shrink), which is cheaper than a rebuild and exact, though the tree
     * may degrade when the motion is large (objects that were neighbours
     * drift apart); cost() measures it. The contact assembler rebuilds the
     * tree when a vertex has moved farther than the mean tetrahedron size
     * since the last build.
     */
    class BoundingVolumeTree
    {
    public:
      /** Build over @p boxes; object i has box boxes[i]. */
      explicit BoundingVolumeTree(const std::vector<BoundingBox<3>> &boxes);

      /** New boxes for the same objects: recompute every node's box. */
      void
      refit(const std::vector<BoundingBox<3>> &boxes);

      /** Call @p f(i) for every object whose box intersects @p box
       * (overlap()), depth first, the right subtree before the left. */
      template <typename F>
      void
      for_each_overlap(const BoundingBox<3> &box, const F &f) const
      {
        if (nodes.empty())
          return;
        // a median split halves the objects at each level: the depth is
        // at most log2(n) + 1, and the stack holds at most one node per
        // level and the root
        std::array<int, 66> stack;
        unsigned int        top = 0;
        stack[top++]            = 0;
        while (top > 0)
          {
            const Node &n = nodes[stack[--top]];
            if (!overlap(n.box, box))
              continue;
            if (n.left < 0)
              f(n.object);
            else
              {
                AssertIndexRange(top + 1, stack.size());
                stack[top++] = n.left;
                stack[top++] = n.right;
              }
          }
      }

      /**
       * The smallest value of @p distance(i, cutoff) over all objects, by
       * branch and bound: subtrees whose box is farther from @p p than the
       * best value so far are skipped. @p distance must return the exact
       * distance from @p p to object i (it may return any value >= cutoff
       * if that distance is >= cutoff).
       */
      double
      nearest(
        const Point<3>                                    &p,
        const std::function<double(unsigned int, double)> &distance) const;

      /** The summed surface area of the inner nodes' boxes (the expected
       * work of a query is proportional to it: the surface area heuristic)
       * divided by that of the objects' boxes, so that a uniform stretch
       * of the objects leaves it unchanged. */
      double
      cost() const;

      /** Number of tree nodes (2 n_objects - 1). */
      unsigned int
      n_nodes() const
      {
        return nodes.size();
      }

    private:
      struct Node
      {
        BoundingBox<3> box;
        int            left = -1, right = -1; // children, -1 for a leaf
        unsigned int   object = 0;            // the object of a leaf
      };
      std::vector<Node> nodes;

      int
      build(std::vector<unsigned int>         &objects,
            const unsigned int                 begin,
            const unsigned int                 end,
            const std::vector<BoundingBox<3>> &boxes);
      void
      refit(const int node, const std::vector<BoundingBox<3>> &boxes);
    };

    /** Euclidean distance from @p p to the box @p b (0 inside). */
    double
    distance(const Point<3> &p, const BoundingBox<3> &b);
  } // namespace Contact
} // namespace TissueContact
