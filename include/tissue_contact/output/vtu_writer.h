#pragma once

#include <tissue_contact/base/discretization.h>
#include <tissue_contact/elasticity/elastic_assembler.h>

#include <deal.II/lac/vector.h>

#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  namespace Output
  {
    using namespace dealii;

    /**
     * Writes one VTU file per converged state, <base>-NNNN.vtu, and rewrites
     * the ParaView series <base>.pvd after each, so a run that stops keeps
     * a readable series. Fields: displacement (point data, P2 written with
     * subdivided cells), material id, J, Cauchy stress (6 components), von
     * Mises stress and strain-energy density (cell averages), and, when
     * given, the material depth of contact (per vertex, linear). The PVD
     * "timestep" is the load factor.
     */
    class VtuSeriesWriter
    {
    public:
      VtuSeriesWriter(const std::string &directory,
                      const std::string &base_name);

      /** Write the state @p u at load factor (or time) @p time; returns the
       * file name written. */
      std::string
      write(const Discretization               &disc,
            const Elasticity::ElasticAssembler &assembler,
            const Vector<double>               &u,
            const double                        time,
            const std::vector<double>          *vertex_depth = nullptr);

      /** Path of the PVD file. */
      std::string
      pvd_file() const;

    private:
      const std::string                           directory, base_name;
      std::vector<std::pair<double, std::string>> records;
    };
  } // namespace Output
} // namespace TissueContact
