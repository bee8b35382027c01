#pragma once

#include <tissue_contact/base/discretization.h>
#include <tissue_contact/elasticity/elastic_assembler.h>
#include <tissue_contact/output/vtu_file.h>

#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <future>
#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  namespace Output
  {
    using namespace dealii;

    /** A field given at every vertex of the mesh (@p n_components values
     * per vertex, interleaved), such as the material depth or the contact
     * traction. */
    struct VertexField
    {
      std::string         name;
      unsigned int        n_components = 1;
      std::vector<double> values;
      /** "length" or "stress" (the units of Options), or empty. */
      std::string quantity;
    };

    /**
     * The ParaView series of a run (doc/users/output.md): per written state
     * <base>-NNNN.vtu, the connected mesh (shared points: the vertices, and
     * for P2 the edge midpoints of quadratic tetrahedra) in the reference
     * configuration with the displacement as point data (apply "Warp By
     * Vector"), the per-cell quantities as cell data (material id, J, the
     * Cauchy stress as a symmetric tensor, von Mises stress, strain-energy
     * density) and the vertex fields given; when contact surfaces are set,
     * also <base>-surface-NNNN.vtu, their triangles with the displacement
     * and the vertex fields. <base>.pvd (and <base>-surface.pvd) list the
     * states written, with the load factor or time as "timestep". Every
     * file is written under a temporary name and renamed, so a run that
     * stops at any moment leaves complete files and a series that lists
     * only them.
     */
    class VtuSeriesWriter
    {
    public:
      struct Options
      {
        /** Values in Float64 instead of Float32. */
        bool double_precision = false;
        /** Units written beside the fields (empty: none). */
        std::string length_unit, stress_unit;
      };

      VtuSeriesWriter(const Discretization &disc,
                      const std::string    &directory,
                      const std::string    &base_name,
                      const Options        &options);

      /** Also write the surface files, of these triangles (mesh vertex
       * indices) with their body numbers. */
      void
      set_surface(const std::vector<std::array<unsigned int, 3>> &triangles,
                  const std::vector<types::material_id>          &body);

      /** Waits for the last state's files (finish()); an error in writing
       * them is printed, not thrown. */
      ~VtuSeriesWriter();

      /** Write the state @p u at load factor (or time) @p time; returns the
       * volume file's name. The fields are computed here; the files are
       * compressed and written on a thread of their own while the caller
       * goes on (the next call and finish() wait for them), so
       * a serial linear solve that follows runs beside the writing. */
      std::string
      write(const Elasticity::ElasticAssembler &assembler,
            const Vector<double>               &u,
            const double                        time,
            const std::vector<VertexField>     &vertex_fields = {});

      /** Path of the PVD file. */
      std::string
      pvd_file() const;

      /** Wait until the files of the last write() are complete; rethrows
       * the error that stopped them. */
      void
      finish() const;

      /** The series written so far: (time, file name) of each state. */
      using Records = std::vector<std::pair<double, std::string>>;

      /** Run @p task on the writing thread once the files of the last
       * write() are complete, with the volume and surface records that
       * list them (a checkpoint that refers to them; not run if they
       * failed: finish() then rethrows that error). */
      void
      then(std::function<void(const Records &, const Records &)> task);

      /** Continue a series of which @p volume and @p surface were written
       * (a restarted run): the next state gets the next number. */
      void
      continue_series(const Records &volume, const Records &surface)
      {
        finish();
        records         = volume;
        surface_records = surface;
      }

    private:
      const Discretization &disc;
      const std::string     directory, base_name;
      const Options         options;
      VtuMesh               volume, surface;
      /** The three DoFs of each point of the volume mesh. */
      std::vector<std::array<types::global_dof_index, 3>> point_dofs;
      /** Each point's two mesh vertices (equal for a vertex point). */
      std::vector<std::array<unsigned int, 2>> point_vertices;
      /** The mesh vertex of each point of the surface mesh. */
      std::vector<unsigned int> surface_vertices;
      std::vector<double>       surface_body;
      /** Appended by the writing thread once a state's files are complete;
       * read there too (then()), or after finish(). */
      Records records, surface_records;
      /** The writing of the last state's files. */
      mutable std::future<void> pending;

      std::string
      units(const std::string &quantity) const;
    };
  } // namespace Output
} // namespace TissueContact
