// tissue-contact: run the scene described by a parameter file.
//
//   tissue-contact                     the built-in default scene
//   tissue-contact scene.prm           a scene file (see prm/)
//   tissue-contact --print-parameters  every parameter, documented (also
//                                      =json and =markdown)

#include <tissue_contact/base/exceptions.h>
#include <tissue_contact/base/interrupt.h>
#include <tissue_contact/simulation/dynamic_simulation.h>
#include <tissue_contact/simulation/static_simulation.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>

namespace
{
  // A small beam of Mooney-Rivlin tissue, clamped at x = 0, whose far end
  // is twisted by 90 degrees about the beam axis: large rotations, a few
  // increments, about a second.
  const char *default_scene = R"(
subsection Mesh
  set Source           = box
  set Box lower corner = 0, 0, 0
  set Box upper corner = 1, 0.2, 0.2
  set Box subdivisions = 10, 2, 2
end
subsection Bodies
  set Number of bodies = 1
  subsection Body 0
    set Name        = beam
    set Material id = 0
    set Model       = Mooney-Rivlin
    set C1          = 5
    set C2          = 1
    set a           = 50
  end
end
subsection Boundary conditions
  set Number of Dirichlet conditions = 2
  subsection Dirichlet 0
    set Boundary id = 0
  end
  subsection Dirichlet 1
    set Boundary id     = 1
    set Rotation axis   = 1, 0, 0
    set Rotation center = 0, 0.1, 0.1
    set Rotation angle  = 90
  end
end
subsection Output
  set Directory = output
  set Base name = default-scene
end
)";

  void
  print_usage(std::ostream &out)
  {
    out << "Usage: tissue-contact [FILE.prm]\n"
           "       tissue-contact --restart DIR FILE.prm\n"
           "       tissue-contact --print-parameters[=prm|json|markdown]\n"
           "Without a file, runs a small built-in scene (a twisted beam) and "
           "writes output/default-scene.pvd.\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  using namespace TissueContact;
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(
        argc, argv, dealii::numbers::invalid_unsigned_int);

      if (argc == 4 && std::string(argv[1]) == "--restart")
        {
          // continue the run whose output folder is argv[2]
          Scene::SceneParameters parameters =
            Scene::SceneParameters::from_file(argv[3]);
          parameters.output.directory = argv[2];
          const Checkpoint checkpoint =
            Checkpoint::read(checkpoint_file(parameters.output.directory,
                                             parameters.output.base_name));
          check_same_parameters(checkpoint, parameters.effective_parameters);
          install_interrupt_handlers();
          if (parameters.time_integration.dynamic)
            DynamicSimulation(parameters, std::cout).run({}, &checkpoint);
          else
            StaticSimulation(parameters, std::cout).run(&checkpoint);
          return 0;
        }
      if (argc > 2)
        {
          std::cerr << "tissue-contact: error: one parameter file expected, "
                       "got "
                    << argc - 1 << " arguments\n";
          print_usage(std::cerr);
          return 1;
        }
      const std::string arg = argc == 2 ? argv[1] : "";
      if (arg == "-h" || arg == "--help")
        {
          print_usage(std::cout);
          return 0;
        }
      if (arg == "--print-parameters")
        {
          Scene::SceneParameters::print_reference(std::cout);
          return 0;
        }
      const std::string print_option = "--print-parameters=";
      if (arg.rfind(print_option, 0) == 0)
        {
          Scene::SceneParameters::print_reference(
            std::cout, arg.substr(print_option.size()));
          return 0;
        }
      if (!arg.empty() && arg[0] == '-')
        {
          std::cerr << "tissue-contact: error: unknown option '" << arg
                    << "'\n";
          print_usage(std::cerr);
          return 1;
        }

      const Scene::SceneParameters parameters =
        arg.empty() ? Scene::SceneParameters::from_string(default_scene) :
                      Scene::SceneParameters::from_file(arg);
      if (arg.empty())
        std::cout << "No parameter file given: running the built-in default "
                     "scene (tissue-contact --help)\n";
      install_interrupt_handlers();
      if (parameters.time_integration.dynamic)
        DynamicSimulation(parameters, std::cout).run();
      else
        StaticSimulation(parameters, std::cout).run();
    }
  catch (const std::bad_alloc &)
    {
      std::cout.flush();
      std::cerr << "tissue-contact: error: out of memory: the scene needs "
                   "more memory than this machine has (a mesh too fine, or "
                   "a corrupt element count?)"
                << std::endl;
      return 1;
    }
  catch (const Interrupted &e)
    {
      std::cout.flush();
      std::cerr << "tissue-contact: " << e.what() << std::endl;
      return 128 + e.signal;
    }
  catch (const std::exception &e)
    {
      std::cout.flush();
      std::cerr << "tissue-contact: error: " << error_message(e) << std::endl;
      return 1;
    }
  return 0;
}
