#include <tissue_contact/scene/prescribed_motion.h>

#include <deal.II/physics/transformations.h>

namespace TissueContact
{
  namespace Scene
  {
    Tensor<1, 3>
    PrescribedMotion::displacement(const Point<3> &X,
                                   const double    load_factor) const
    {
      Tensor<1, 3> u = load_factor * translation;
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
