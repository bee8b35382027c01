#pragma once

#include <deal.II/base/point.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace TissueContact
{
  namespace Output
  {
    using namespace dealii;

    /** A connected unstructured mesh as VTK stores it: shared points and
     * the point indices of every cell, in VTK's node order. */
    struct VtuMesh
    {
      std::vector<Point<3>>      points;
      std::vector<std::uint32_t> connectivity;
      /** Nodes per cell: 4 (VTK_TETRA), 10 (VTK_QUADRATIC_TETRA), 3
       * (VTK_TRIANGLE) or 6 (VTK_QUADRATIC_TRIANGLE). */
      unsigned int nodes_per_cell = 4;

      std::size_t
      n_cells() const
      {
        return connectivity.size() / nodes_per_cell;
      }
    };

    /** One data array: @p n_components values per point or per cell,
     * interleaved. ParaView reads 3 components as a vector and 6 as a
     * symmetric tensor (xx, yy, zz, xy, yz, xz). */
    struct VtuField
    {
      std::string         name;
      unsigned int        n_components = 1;
      std::vector<double> values;
      /** Written as the array's "units" attribute when not empty. */
      std::string units;
      /** Written as Int32 instead of floating point. */
      bool integer = false;
    };

    /**
     * Write @p mesh with its point and cell fields as a VTK XML
     * unstructured grid (.vtu): appended binary arrays, each compressed by
     * zlib at its fastest level, floating point in Float64 if
     * @p double_precision else Float32, the time as field data
     * "TimeValue". The file is written under a temporary name and renamed
     * when complete, so @p path is either the old file or the whole new
     * one; a write that fails (full disk, no permission) throws naming
     * @p path and the cause.
     */
    void
    write_vtu(const std::string           &path,
              const VtuMesh               &mesh,
              const std::vector<VtuField> &point_fields,
              const std::vector<VtuField> &cell_fields,
              const double                 time,
              const bool                   double_precision);

    /**
     * Write the ParaView series @p path (.pvd) listing @p records (time,
     * file name relative to the series), atomically as write_vtu(). The
     * file holds nothing but the list (no date), so equal series give
     * equal files.
     */
    void
    write_pvd(const std::string                                 &path,
              const std::vector<std::pair<double, std::string>> &records);

    /**
     * Write @p contents to @p path through a temporary file in the same
     * folder and a rename: readers see the old or the new file, never a
     * partial one. Throws naming @p path and the cause on failure.
     */
    void
    write_file_atomically(const std::string &path, const std::string &contents);
  } // namespace Output
} // namespace TissueContact
