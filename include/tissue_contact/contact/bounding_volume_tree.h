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
     * box centers along the node's largest extent, down to leaves of at most
     * leaf_size objects; refitted bottom-up when the objects move (the
     * topology is kept, only the boxes grow or shrink), which is cheaper than
     * a rebuild and exact, though the tree may degrade when the motion is
     * large (objects that were neighbours drift apart); cost() measures it.
     * The contact assembler rebuilds the tree when a vertex has moved
     * farther than the mean tetrahedron size since the last build.
     *
     * The walk is limited by memory traffic, not arithmetic (doc/theory/
     * 05-contact.md, sec. 2): the nodes hold single-precision boxes rounded
     * outward (32 bytes a node, two to a cache line), supersets of the
     * double-precision boxes of their objects, and a leaf's objects are
     * tested with their own double-precision boxes. The objects found and
     * their order are those of a tree of one object per leaf built by the
     * same median splits.
     */
    class BoundingVolumeTree
    {
    public:
      /** The most objects in a leaf. */
      static constexpr unsigned int leaf_size = 4;

      /** Build over @p boxes; object i has box boxes[i]. */
      explicit BoundingVolumeTree(const std::vector<BoundingBox<3>> &boxes);

      /** New boxes for the same objects: recompute every node's box. */
      void
      refit(const std::vector<BoundingBox<3>> &boxes);

      /** Call @p f(i) for every object whose box intersects @p box
       * (overlap()), depth first, the right subtree before the left (within
       * a leaf, the order of a right-first walk of its median splits). */
      template <typename F>
      void
      for_each_overlap(const BoundingBox<3> &box, const F &f) const
      {
        if (nodes.empty())
          return;
        const Node query = outward(box, 2);
        // a median split halves the objects at each level: the depth is
        // at most log2(n) + 1, and the stack holds at most one node per
        // level and the root
        std::array<unsigned int, 66> stack;
        unsigned int                 top = 0;
        stack[top++]                     = 0;
        while (top > 0)
          {
            const unsigned int index = stack[--top];
            const Node        &n     = nodes[index];
            if (!overlaps(n, query))
              continue;
            if (n.count > 0)
              {
                for (unsigned int i = n.first; i < n.first + n.count; ++i)
                  if (overlap(leaf_boxes[i], box))
                    f(objects[i]);
              }
            else
              {
                AssertIndexRange(top + 1, stack.size());
                stack[top++] = index + 1; // the left child follows its parent
                stack[top++] = n.first;   // the right child
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

      /** The summed surface area of the nodes' boxes (the expected work of
       * a query is proportional to it: the surface area heuristic) divided
       * by that of the objects' boxes, so that a uniform stretch of the
       * objects leaves it unchanged. */
      double
      cost() const;

      /** Number of tree nodes (inner nodes and leaves). */
      unsigned int
      n_nodes() const
      {
        return nodes.size();
      }

    private:
      /** A box in single precision; an inner node's left child is the
       * node after it, its right child nodes[first]; a leaf (count > 0)
       * holds objects[first] .. objects[first + count - 1]. */
      struct Node
      {
        std::array<float, 3> lo, hi;
        unsigned int         first = 0, count = 0;
      };
      std::vector<Node> nodes;
      /** The objects in the leaves' order, and their boxes. */
      std::vector<unsigned int>   objects;
      std::vector<BoundingBox<3>> leaf_boxes;

      /** Single-precision box containing @p box, widened by @p ulps units
       * in the last place of a float on each side. */
      static Node
      outward(const BoundingBox<3> &box, const unsigned int ulps = 0);

      /** Whether the boxes overlap (touching counts; a NaN bound
       * overlaps, as with overlap() of two BoundingBox). */
      static bool
      overlaps(const Node &a, const Node &b)
      {
        for (unsigned int d = 0; d < 3; ++d)
          if (a.lo[d] > b.hi[d] || b.lo[d] > a.hi[d])
            return false;
        return true;
      }

      void
      build(std::vector<unsigned int>         &order,
            const unsigned int                 begin,
            const unsigned int                 end,
            const std::vector<BoundingBox<3>> &boxes);
      /** Append order[begin, end) to objects in the order a tree of one
       * object per leaf, split as build() splits, would visit them. */
      void
      append_leaf_objects(std::vector<unsigned int>         &order,
                          const unsigned int                 begin,
                          const unsigned int                 end,
                          const std::vector<BoundingBox<3>> &boxes);
      /** Recompute the nodes' boxes from leaf_boxes. */
      void
      fit_nodes();
    };

    /** Euclidean distance from @p p to the box @p b (0 inside). */
    double
    distance(const Point<3> &p, const BoundingBox<3> &b);
  } // namespace Contact
} // namespace TissueContact
