#include <tissue_contact/scene/prescribed_motion.h>

#include <deal.II/physics/transformations.h>

#include <algorithm>
#include <cmath>

namespace TissueContact
{
  namespace Scene
  {
    Tensor<1, 3>
    PrescribedMotion::translation_at(const double load_factor) const
    {
      if (path.empty())
        return load_factor * translation;
      if (path.size() == 1)
        return path[0];
      const unsigned int n = path.size() - 1;
      const double       s = n * load_factor;
      const unsigned int k =
        static_cast<unsigned int>(std::clamp(std::floor(s), 0., n - 1.));
      return path[k] + (s - k) * (path[k + 1] - path[k]);
    }


    Tensor<1, 3>
    PrescribedMotion::displacement(const Point<3> &X,
                                   const double    load_factor) const
    {
      Tensor<1, 3> u = translation_at(load_factor);
      if (angle != 0.)
        {
          const Tensor<2, 3> R =
            Physics::Transformations::Rotations::rotation_matrix_3d(
              axis / axis.norm(), load_factor * angle);
          const Tensor<1, 3> r = X - center;
          u += R * r - r;
        }
      return u;
    }
  } // namespace Scene
} // namespace TissueContact
