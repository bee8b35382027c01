#include <tissue_contact/contact/bounding_volume_tree.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace TissueContact
{
  namespace Contact
  {
    double
    distance(const Point<3> &p, const BoundingBox<3> &b)
    {
      double d2 = 0.;
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double lo = b.get_boundary_points().first[d];
          const double hi = b.get_boundary_points().second[d];
          const double e = p[d] < lo ? lo - p[d] : (p[d] > hi ? p[d] - hi : 0.);
          d2 += e * e;
        }
      return std::sqrt(d2);
    }


    BoundingVolumeTree::BoundingVolumeTree(
      const std::vector<BoundingBox<3>> &boxes)
    {
      if (boxes.empty())
        return;
      nodes.reserve(2 * boxes.size() - 1);
      std::vector<unsigned int> objects(boxes.size());
      for (unsigned int i = 0; i < objects.size(); ++i)
        objects[i] = i;
      build(objects, 0, objects.size(), boxes);
    }


    int
    BoundingVolumeTree::build(std::vector<unsigned int>         &objects,
                              const unsigned int                 begin,
                              const unsigned int                 end,
                              const std::vector<BoundingBox<3>> &boxes)
    {
      const int index = nodes.size();
      nodes.emplace_back();
      BoundingBox<3> box = boxes[objects[begin]];
      for (unsigned int i = begin + 1; i < end; ++i)
        box.merge_with(boxes[objects[i]]);
      nodes[index].box = box;
      if (end - begin == 1)
        {
          nodes[index].object = objects[begin];
          return index;
        }
      // split at the median of the box centers along the largest extent
      unsigned int axis   = 0;
      double       extent = -1.;
      for (unsigned int d = 0; d < 3; ++d)
        if (box.side_length(d) > extent)
          {
            extent = box.side_length(d);
            axis   = d;
          }
      const unsigned int middle = (begin + end) / 2;
      std::nth_element(objects.begin() + begin,
                       objects.begin() + middle,
                       objects.begin() + end,
                       [&](const unsigned int a, const unsigned int b) {
                         return boxes[a].center()[axis] <
                                boxes[b].center()[axis];
                       });
      const int left     = build(objects, begin, middle, boxes);
      const int right    = build(objects, middle, end, boxes);
      nodes[index].left  = left;
      nodes[index].right = right;
      return index;
    }


    double
    BoundingVolumeTree::cost() const
    {
      const auto area = [](const BoundingBox<3> &b) {
        const Tensor<1, 3> e =
          b.get_boundary_points().second - b.get_boundary_points().first;
        return 2. * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
      };
      double inner = 0., leaves = 0.;
      for (const Node &n : nodes)
        (n.left >= 0 ? inner : leaves) += area(n.box);
      return leaves > 0. ? inner / leaves : 0.;
    }


    void
    BoundingVolumeTree::refit(const std::vector<BoundingBox<3>> &boxes)
    {
      if (!nodes.empty())
        refit(0, boxes);
    }


    void
    BoundingVolumeTree::refit(const int                          node,
                              const std::vector<BoundingBox<3>> &boxes)
    {
      Node &n = nodes[node];
      if (n.left < 0)
        {
          n.box = boxes[n.object];
          return;
        }
      refit(n.left, boxes);
      refit(n.right, boxes);
      n.box = nodes[n.left].box;
      n.box.merge_with(nodes[n.right].box);
    }


    double
    BoundingVolumeTree::nearest(
      const Point<3>                                    &p,
      const std::function<double(unsigned int, double)> &dist) const
    {
      double best = std::numeric_limits<double>::infinity();
      if (nodes.empty())
        return best;
      std::vector<std::pair<double, int>> stack{{distance(p, nodes[0].box), 0}};
      while (!stack.empty())
        {
          const auto [d_box, index] = stack.back();
          stack.pop_back();
          if (d_box >= best)
            continue;
          const Node &n = nodes[index];
          if (n.left < 0)
            {
              best = std::min(best, dist(n.object, best));
              continue;
            }
          const double dl = distance(p, nodes[n.left].box);
          const double dr = distance(p, nodes[n.right].box);
          // visit the nearer child first (it is pushed last)
          if (dl < dr)
            {
              stack.emplace_back(dr, n.right);
              stack.emplace_back(dl, n.left);
            }
          else
            {
              stack.emplace_back(dl, n.left);
              stack.emplace_back(dr, n.right);
            }
        }
      return best;
    }
  } // namespace Contact
} // namespace TissueContact
