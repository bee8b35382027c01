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


    BoundingVolumeTree::Node
    BoundingVolumeTree::outward(const BoundingBox<3> &box,
                                const unsigned int    ulps)
    {
      constexpr float inf = std::numeric_limits<float>::infinity();
      Node            n;
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double lo = box.get_boundary_points().first[d];
          const double hi = box.get_boundary_points().second[d];
          n.lo[d]         = static_cast<float>(lo);
          n.hi[d]         = static_cast<float>(hi);
          // rounded to nearest: step outward where that went inward
          if (n.lo[d] > lo)
            n.lo[d] = std::nextafter(n.lo[d], -inf);
          if (n.hi[d] < hi)
            n.hi[d] = std::nextafter(n.hi[d], inf);
          for (unsigned int u = 0; u < ulps; ++u)
            {
              n.lo[d] = std::nextafter(n.lo[d], -inf);
              n.hi[d] = std::nextafter(n.hi[d], inf);
            }
        }
      return n;
    }


    BoundingVolumeTree::BoundingVolumeTree(
      const std::vector<BoundingBox<3>> &boxes)
    {
      if (boxes.empty())
        return;
      std::vector<unsigned int> order(boxes.size());
      for (unsigned int i = 0; i < order.size(); ++i)
        order[i] = i;
      build(order, 0, order.size(), boxes);
      leaf_boxes.reserve(objects.size());
      for (const unsigned int i : objects)
        leaf_boxes.push_back(boxes[i]);
      fit_nodes();
    }


    namespace
    {
      /** The box of boxes[order[begin]] .. boxes[order[end - 1]], and the
       * median split of that range along its largest extent: the objects
       * of the left half at order[begin, middle), ordered as
       * std::nth_element leaves them. Returns middle. */
      unsigned int
      median_split(std::vector<unsigned int>         &order,
                   const unsigned int                 begin,
                   const unsigned int                 end,
                   const std::vector<BoundingBox<3>> &boxes)
      {
        BoundingBox<3> box = boxes[order[begin]];
        for (unsigned int i = begin + 1; i < end; ++i)
          box.merge_with(boxes[order[i]]);
        unsigned int axis   = 0;
        double       extent = -1.;
        for (unsigned int d = 0; d < 3; ++d)
          if (box.side_length(d) > extent)
            {
              extent = box.side_length(d);
              axis   = d;
            }
        const unsigned int middle = (begin + end) / 2;
        std::nth_element(order.begin() + begin,
                         order.begin() + middle,
                         order.begin() + end,
                         [&](const unsigned int a, const unsigned int b) {
                           return boxes[a].center()[axis] <
                                  boxes[b].center()[axis];
                         });
        return middle;
      }
    } // namespace


    void
    BoundingVolumeTree::build(std::vector<unsigned int>         &order,
                              const unsigned int                 begin,
                              const unsigned int                 end,
                              const std::vector<BoundingBox<3>> &boxes)
    {
      const unsigned int index = nodes.size();
      nodes.emplace_back();
      if (end - begin <= leaf_size)
        {
          nodes[index].first = objects.size();
          nodes[index].count = end - begin;
          append_leaf_objects(order, begin, end, boxes);
          return;
        }
      const unsigned int middle = median_split(order, begin, end, boxes);
      build(order, begin, middle, boxes); // the left child: index + 1
      nodes[index].first = nodes.size();
      build(order, middle, end, boxes);
    }


    void
    BoundingVolumeTree::append_leaf_objects(
      std::vector<unsigned int>         &order,
      const unsigned int                 begin,
      const unsigned int                 end,
      const std::vector<BoundingBox<3>> &boxes)
    {
      if (end - begin == 1)
        {
          objects.push_back(order[begin]);
          return;
        }
      // the walk visits the right half first
      const unsigned int middle = median_split(order, begin, end, boxes);
      append_leaf_objects(order, middle, end, boxes);
      append_leaf_objects(order, begin, middle, boxes);
    }


    void
    BoundingVolumeTree::fit_nodes()
    {
      // children follow their parent: a backward pass sees them first
      for (unsigned int index = nodes.size(); index-- > 0;)
        {
          Node &n = nodes[index];
          if (n.count > 0)
            {
              BoundingBox<3> box = leaf_boxes[n.first];
              for (unsigned int i = n.first + 1; i < n.first + n.count; ++i)
                box.merge_with(leaf_boxes[i]);
              const Node fitted = outward(box);
              n.lo              = fitted.lo;
              n.hi              = fitted.hi;
            }
          else
            {
              const Node &left = nodes[index + 1], &right = nodes[n.first];
              for (unsigned int d = 0; d < 3; ++d)
                {
                  n.lo[d] = std::min(left.lo[d], right.lo[d]);
                  n.hi[d] = std::max(left.hi[d], right.hi[d]);
                }
            }
        }
    }


    double
    BoundingVolumeTree::cost() const
    {
      const auto area = [](const Tensor<1, 3> &e) {
        return 2. * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
      };
      double tree = 0., objects_area = 0.;
      for (const Node &n : nodes)
        {
          Tensor<1, 3> e;
          for (unsigned int d = 0; d < 3; ++d)
            e[d] = double(n.hi[d]) - double(n.lo[d]);
          tree += area(e);
        }
      for (const auto &b : leaf_boxes)
        objects_area +=
          area(b.get_boundary_points().second - b.get_boundary_points().first);
      return objects_area > 0. ? tree / objects_area : 0.;
    }


    void
    BoundingVolumeTree::refit(const std::vector<BoundingBox<3>> &boxes)
    {
      AssertDimension(boxes.size(), objects.size());
      for (unsigned int i = 0; i < objects.size(); ++i)
        leaf_boxes[i] = boxes[objects[i]];
      fit_nodes();
    }


    double
    BoundingVolumeTree::nearest(
      const Point<3>                                    &p,
      const std::function<double(unsigned int, double)> &dist) const
    {
      double best = std::numeric_limits<double>::infinity();
      if (nodes.empty())
        return best;
      // the distance to a node's single-precision box, a superset of its
      // objects' boxes: never more than the distance to any of them
      const auto node_distance = [&](const Node &n) {
        double d2 = 0.;
        for (unsigned int d = 0; d < 3; ++d)
          {
            const double lo = n.lo[d], hi = n.hi[d];
            const double e =
              p[d] < lo ? lo - p[d] : (p[d] > hi ? p[d] - hi : 0.);
            d2 += e * e;
          }
        return std::sqrt(d2);
      };
      std::vector<std::pair<double, unsigned int>> stack{
        {node_distance(nodes[0]), 0}};
      while (!stack.empty())
        {
          const auto [d_box, index] = stack.back();
          stack.pop_back();
          if (d_box >= best)
            continue;
          const Node &n = nodes[index];
          if (n.count > 0)
            {
              for (unsigned int i = n.first; i < n.first + n.count; ++i)
                if (distance(p, leaf_boxes[i]) < best)
                  best = std::min(best, dist(objects[i], best));
              continue;
            }
          const double dl = node_distance(nodes[index + 1]);
          const double dr = node_distance(nodes[n.first]);
          // visit the nearer child first (it is pushed last)
          if (dl < dr)
            {
              stack.emplace_back(dr, n.first);
              stack.emplace_back(dl, index + 1);
            }
          else
            {
              stack.emplace_back(dl, index + 1);
              stack.emplace_back(dr, n.first);
            }
        }
      return best;
    }
  } // namespace Contact
} // namespace TissueContact
