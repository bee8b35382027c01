#include <tissue_contact/materials/corotated.h>
#include <tissue_contact/materials/fiber_reinforcement.h>
#include <tissue_contact/materials/linear_elastic.h>
#include <tissue_contact/materials/material_factory.h>
#include <tissue_contact/materials/mooney_rivlin.h>
#include <tissue_contact/materials/neo_hookean.h>
#include <tissue_contact/materials/saint_venant_kirchhoff.h>
#include <tissue_contact/materials/uncoupled_material.h>
#include <tissue_contact/materials/veronda.h>

#include <deal.II/base/function_parser.h>

#include <cmath>

namespace TissueContact
{
  namespace Materials
  {
    void
    MaterialParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.add_parameter(
        "Model",
        model,
        "Material model (doc/theory/03-materials.md). neo-Hookean, Saint "
        "Venant-Kirchhoff, corotated (linear elasticity in the stretch U of "
        "F = RU), linear: Mu, Lambda. Mooney-Rivlin: C1, C2, a. "
        "Veronda: Alpha, Beta, a. rigid: the body follows 'Rigid motion'.",
        Patterns::Selection("neo-Hookean|Mooney-Rivlin|Veronda|"
                            "Saint Venant-Kirchhoff|corotated|linear|rigid"));
      prm.add_parameter("Mu",
                        mu,
                        "Lame shear modulus mu (stress units) of the "
                        "neo-Hookean, Saint Venant-Kirchhoff, corotated and "
                        "linear models; > 0 for a stable material.",
                        Patterns::Double());
      prm.add_parameter("Lambda",
                        lambda,
                        "Lame constant lambda (stress units) of the same "
                        "models; bulk modulus lambda + 2 mu / 3 > 0.",
                        Patterns::Double());
      prm.add_parameter("C1",
                        C1,
                        "Mooney-Rivlin C1 (stress units) in W = C1 (I1 - 3) "
                        "+ C2 (I2 - 3) + ...; small-strain shear modulus "
                        "2 (C1 + C2) > 0.",
                        Patterns::Double());
      prm.add_parameter("C2",
                        C2,
                        "Mooney-Rivlin C2 (stress units); 0 gives a "
                        "neo-Hookean-like model.",
                        Patterns::Double());
      prm.add_parameter("a",
                        a,
                        "Compressibility a (stress units) of Mooney-Rivlin "
                        "and Veronda, in their volume terms a (I3 - 1) - k ln "
                        "I3 (doc/theory/03-materials.md sec. 3.3); larger is "
                        "less compressible.",
                        Patterns::Double());
      prm.add_parameter("Alpha",
                        alpha,
                        "Veronda alpha (stress units) in W = alpha (exp(beta "
                        "(I1 - 3)) - 1) - alpha beta / 2 (I2 - 3) + ...; "
                        "small-strain shear modulus alpha beta.",
                        Patterns::Double());
      prm.add_parameter("Beta",
                        beta,
                        "Veronda beta (dimensionless), the exponential "
                        "stiffening rate.",
                        Patterns::Double());
      prm.add_parameter(
        "Formulation",
        formulation,
        "For neo-Hookean, Mooney-Rivlin and Veronda: coupled (the forms "
        "above, the volume term in a or Lambda) or uncoupled (their energy "
        "in the isochoric invariants of J^(-1/3) F plus kappa/4 (J^2 - 1 - "
        "2 ln J), so that the shear parameters and the Bulk modulus kappa "
        "are set apart; doc/theory/03-materials.md sec. 3.7). Lambda and a "
        "are then unused.",
        Patterns::Selection("coupled|uncoupled"));
      prm.add_parameter("Bulk modulus",
                        bulk_modulus,
                        "For Formulation = uncoupled: the small-strain bulk "
                        "modulus kappa (stress units, > 0); Poisson's ratio "
                        "is (3 kappa - 2 mu) / (2 (3 kappa + mu)), 0.4999 at "
                        "kappa = 5000 mu.",
                        Patterns::Double());
      prm.add_parameter(
        "Volumetric term",
        volumetric_term,
        "For Formulation = uncoupled: where the volume term U(J) is "
        "integrated. pointwise: at the quadrature points, the "
        "displacement-only element, which locks on P1 meshes as Poisson's "
        "ratio approaches 1/2 (stiff by tens of percent at 0.49); nodal "
        "average: at the vertices, with the volume ratio of each vertex's "
        "share of its elements (Bonet and Burton's average nodal pressure "
        "tetrahedron, a mixed u-p formulation whose pressure is eliminated "
        "vertex by vertex; doc/theory/08-nodal-pressure.md), which does "
        "not lock. P1 only; it widens the tangent's sparsity pattern. "
        "element average: U of each element's mean volume ratio (the mean "
        "dilatation, a P2-P0 mixed u-p formulation whose pressure is "
        "eliminated element by element; doc/theory/09-mean-dilatation.md), "
        "for P2 meshes at Poisson's ratios from about 0.49 on, with at "
        "least two elements across the thinnest part (it is too soft on "
        "coarser meshes and for compressible tissue); on P1 meshes it is the "
        "same as pointwise.",
        Patterns::Selection("pointwise|nodal average|element average"));
      prm.add_parameter(
        "Rotation",
        rotation,
        "For Model = corotated: where the rotation R of F = RU is taken. "
        "pointwise: at every quadrature point (the corotated material, "
        "doc/theory/03-materials.md sec. 3.6). element: once per element, "
        "from the deformation of its four corner vertices, with linear "
        "elasticity in the frame it defines and the element's stiffness "
        "matrix computed once (the single-rotation element, tet10SR on P2 "
        "meshes; doc/theory/10-single-rotation.md): a third of the assembly "
        "cost on P2 and as accurate on the beams measured in "
        "doc/users/choosing.md, but 7.2 kB per element and more Newton "
        "iterations in large twists; on P1 meshes both are the same "
        "(pointwise is twice as fast there).",
        Patterns::Selection("pointwise|element"));
      prm.enter_subsection("Fiber");
      prm.add_parameter("Enabled",
                        fiber,
                        "Add fiber reinforcement to the ground material "
                        "(not for linear and rigid).",
                        Patterns::Bool());
      prm.add_parameter("Alpha",
                        fiber_alpha,
                        "Fiber alpha (stress units), the scale of the fiber "
                        "energy (doc/theory/03-materials.md).",
                        Patterns::Double());
      prm.add_parameter("Beta",
                        fiber_beta,
                        "Fiber beta (dimensionless), the fiber's "
                        "exponential stiffening rate.",
                        Patterns::Double());
      prm.add_parameter("Direction",
                        fiber_direction,
                        "Fiber direction in the reference configuration: "
                        "three expressions in x, y, z separated by ';' "
                        "(normalized where evaluated).",
                        Patterns::Anything());
      prm.leave_subsection();
    }


    std::unique_ptr<Material>
    create_material(const MaterialParameters &b)
    {
      const bool uncoupled = b.formulation == "uncoupled";
      AssertThrow(!uncoupled || b.model == "neo-Hookean" ||
                    b.model == "Mooney-Rivlin" || b.model == "Veronda",
                  ExcMessage("Formulation = uncoupled exists for neo-Hookean, "
                             "Mooney-Rivlin and Veronda, not for the model '" +
                             b.model + "'"));
      AssertThrow(b.volumetric_term == "pointwise" || uncoupled,
                  ExcMessage("Volumetric term = " + b.volumetric_term +
                             " needs Formulation = uncoupled (it moves the "
                             "volume term U(J) of the uncoupled forms out of "
                             "the quadrature points); the model '" +
                             b.model +
                             "' is in Formulation = " + b.formulation));
      AssertThrow(b.rotation == "pointwise" ||
                    (b.model == "corotated" && !b.fiber),
                  ExcMessage("Rotation = element is a form of the corotated "
                             "model without fibers; the model is '" +
                             b.model + "'" + (b.fiber ? " with fibers" : "")));
      if (b.model == "rigid")
        return nullptr;
      const bool pointwise = b.volumetric_term == "pointwise";
      // magnitudes that overflow the energy (exp(beta (I1 - 3)), squares
      // of moduli) are refused by name, not met later as an inverted
      // element or a failed line search
      for (const auto &[name, value] :
           std::vector<std::pair<std::string, double>>{
             {"Mu", b.mu},
             {"Lambda", b.lambda},
             {"C1", b.C1},
             {"C2", b.C2},
             {"a", b.a},
             {"Alpha", b.alpha},
             {"Beta", b.beta},
             {"Bulk modulus", b.bulk_modulus},
             {"Fiber/Alpha", b.fiber_alpha},
             {"Fiber/Beta", b.fiber_beta}})
        AssertThrow(std::isfinite(value) &&
                      std::abs(value) <=
                        (name.find("Beta") != std::string::npos ? 1e3 : 1e100),
                    ExcMessage("the value of " + name + " (" +
                               Utilities::to_string(value) +
                               ") is out of range: moduli must stay below "
                               "1e100 and the exponents Beta below 1e3 "
                               "(exp(Beta) overflows at 709)"));
      if (b.model == "linear")
        {
          AssertThrow(!b.fiber,
                      ExcMessage("fibers cannot be added to the linear "
                                 "model; use a hyperelastic one"));
          return std::make_unique<LinearElastic>(b.mu, b.lambda);
        }
      std::unique_ptr<HyperelasticMaterial> ground;
      if (uncoupled && b.model == "neo-Hookean")
        ground = std::make_unique<UncoupledNeoHookean>(b.mu,
                                                       b.bulk_modulus,
                                                       pointwise);
      else if (uncoupled && b.model == "Mooney-Rivlin")
        ground = std::make_unique<UncoupledMooneyRivlin>(b.C1,
                                                         b.C2,
                                                         b.bulk_modulus,
                                                         pointwise);
      else if (uncoupled && b.model == "Veronda")
        ground = std::make_unique<UncoupledVeronda>(b.alpha,
                                                    b.beta,
                                                    b.bulk_modulus,
                                                    pointwise);
      else if (b.model == "neo-Hookean")
        ground = std::make_unique<NeoHookean>(b.mu, b.lambda);
      else if (b.model == "Mooney-Rivlin")
        ground = std::make_unique<MooneyRivlin>(b.C1, b.C2, b.a);
      else if (b.model == "Veronda")
        ground = std::make_unique<Veronda>(b.alpha, b.beta, b.a);
      else if (b.model == "Saint Venant-Kirchhoff")
        ground = std::make_unique<SaintVenantKirchhoff>(b.mu, b.lambda);
      else if (b.model == "corotated")
        ground = std::make_unique<Corotated>(b.mu, b.lambda);
      else
        AssertThrow(false,
                    ExcMessage("unknown material model '" + b.model + "'"));
      if (!b.fiber)
        return ground;
      auto direction = std::make_shared<FunctionParser<3>>(3);
      try
        {
          direction->initialize("x,y,z",
                                b.fiber_direction,
                                std::map<std::string, double>());
        }
      catch (...)
        {
          AssertThrow(false,
                      ExcMessage("cannot parse the fiber Direction '" +
                                 b.fiber_direction +
                                 "': give three expressions in x, y, z "
                                 "separated by ';'"));
        }
      return std::make_unique<FiberReinforcement>(std::move(ground),
                                                  b.fiber_alpha,
                                                  b.fiber_beta,
                                                  direction);
    }
  } // namespace Materials
} // namespace TissueContact
