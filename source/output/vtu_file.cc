#include <tissue_contact/output/vtu_file.h>

#include <deal.II/base/exceptions.h>

#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace TissueContact
{
  namespace Output
  {
    namespace
    {
      /** One appended array: vtkZLibDataCompressor's layout with a single
       * block, UInt64 header (number of blocks, block size, last block
       * size, compressed size), then the compressed bytes. */
      template <typename T>
      std::string
      compressed_block(const std::vector<T> &data)
      {
        const uLong raw_size = data.size() * sizeof(T);
        uLongf      size     = compressBound(raw_size);
        std::string bytes(size, '\0');
        const int   status =
          compress2(reinterpret_cast<Bytef *>(&bytes[0]),
                    &size,
                    reinterpret_cast<const Bytef *>(data.data()),
                    raw_size,
                    Z_BEST_SPEED);
        AssertThrow(status == Z_OK,
                    ExcMessage("zlib could not compress an output array"));
        bytes.resize(size);
        const std::uint64_t header[4] = {1, raw_size, raw_size, size};
        return std::string(reinterpret_cast<const char *>(header),
                           sizeof(header)) +
               bytes;
      }

      /** Appends the arrays and writes their XML tags. */
      class Appender
      {
      public:
        Appender(std::ostringstream &xml, const bool double_precision)
          : xml(xml)
          , double_precision(double_precision)
        {}

        template <typename T>
        void
        add(const std::string    &type,
            const std::string    &name,
            const unsigned int    n_components,
            const std::vector<T> &data,
            const std::string    &units = "")
        {
          xml << "        <DataArray type=\"" << type << "\" Name=\"" << name
              << "\" NumberOfComponents=\"" << n_components
              << "\" NumberOfTuples=\"" << data.size() / n_components
              << "\" format=\"appended\" offset=\"" << appended.size() << "\""
              << (units.empty() ? "" : " units=\"" + units + "\"") << "/>\n";
          appended += compressed_block(data);
        }

        void
        add_field(const VtuField &f)
        {
          if (f.integer)
            add("Int32",
                f.name,
                f.n_components,
                std::vector<std::int32_t>(f.values.begin(), f.values.end()),
                f.units);
          else if (double_precision)
            add("Float64", f.name, f.n_components, f.values, f.units);
          else
            add("Float32",
                f.name,
                f.n_components,
                std::vector<float>(f.values.begin(), f.values.end()),
                f.units);
        }

        std::string appended;

      private:
        std::ostringstream &xml;
        const bool          double_precision;
      };

      std::uint8_t
      vtk_cell_type(const unsigned int nodes_per_cell)
      {
        switch (nodes_per_cell)
          {
            case 3:
              return 5; // VTK_TRIANGLE
            case 4:
              return 10; // VTK_TETRA
            case 6:
              return 22; // VTK_QUADRATIC_TRIANGLE
            case 10:
              return 24; // VTK_QUADRATIC_TETRA
            default:
              AssertThrow(false, ExcInternalError());
              return 0;
          }
      }
    } // namespace


    void
    write_file_atomically(const std::string &path, const std::string &contents)
    {
      const std::string temporary = path + ".partial";
      {
        std::ofstream out(temporary, std::ios::binary);
        AssertThrow(out.good(),
                    ExcMessage("cannot write the output file '" + path +
                               "': " + std::strerror(errno) +
                               " (check that the output folder exists and "
                               "is writable)"));
        out.write(contents.data(), contents.size());
        out.close();
        if (!out.good())
          {
            const std::string cause = std::strerror(errno);
            std::remove(temporary.c_str());
            AssertThrow(false,
                        ExcMessage("writing the output file '" + path +
                                   "' failed: " + cause +
                                   " (is the disk full?); the files "
                                   "written before it are kept"));
          }
      }
      AssertThrow(std::rename(temporary.c_str(), path.c_str()) == 0,
                  ExcMessage("cannot rename '" + temporary + "' to '" + path +
                             "': " + std::strerror(errno)));
    }


    void
    write_pvd(const std::string                                 &path,
              const std::vector<std::pair<double, std::string>> &records)
    {
      std::ostringstream xml;
      xml.precision(17);
      xml << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"Collection\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n"
          << "  <Collection>\n";
      for (const auto &[time, file] : records)
        xml << "    <DataSet timestep=\"" << time
            << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
      xml << "  </Collection>\n"
          << "</VTKFile>\n";
      write_file_atomically(path, xml.str());
    }


    void
    write_vtu(const std::string           &path,
              const VtuMesh               &mesh,
              const std::vector<VtuField> &point_fields,
              const std::vector<VtuField> &cell_fields,
              const double                 time,
              const bool                   double_precision)
    {
      std::ostringstream xml;
      xml.precision(17);
      Appender data(xml, double_precision);
      xml << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
             "byte_order=\"LittleEndian\" header_type=\"UInt64\" "
             "compressor=\"vtkZLibDataCompressor\">\n"
          << "  <UnstructuredGrid>\n"
          << "    <FieldData>\n";
      data.add("Float64", "TimeValue", 1, std::vector<double>{time});
      xml << "    </FieldData>\n"
          << "    <Piece NumberOfPoints=\"" << mesh.points.size()
          << "\" NumberOfCells=\"" << mesh.n_cells() << "\">\n"
          << "      <Points>\n";
      std::vector<double> coordinates;
      coordinates.reserve(3 * mesh.points.size());
      for (const auto &p : mesh.points)
        for (unsigned int d = 0; d < 3; ++d)
          coordinates.push_back(p[d]);
      data.add_field({"Points", 3, coordinates, "", false});
      xml << "      </Points>\n"
          << "      <Cells>\n";
      std::vector<std::int64_t> connectivity(mesh.connectivity.begin(),
                                             mesh.connectivity.end());
      std::vector<std::int64_t> offsets(mesh.n_cells());
      for (std::size_t c = 0; c < offsets.size(); ++c)
        offsets[c] = (c + 1) * mesh.nodes_per_cell;
      data.add("Int64", "connectivity", 1, connectivity);
      data.add("Int64", "offsets", 1, offsets);
      data.add("UInt8",
               "types",
               1,
               std::vector<std::uint8_t>(mesh.n_cells(),
                                         vtk_cell_type(mesh.nodes_per_cell)));
      xml << "      </Cells>\n"
          << "      <PointData>\n";
      for (const auto &f : point_fields)
        {
          Assert(f.values.size() == f.n_components * mesh.points.size(),
                 ExcInternalError());
          data.add_field(f);
        }
      xml << "      </PointData>\n"
          << "      <CellData>\n";
      for (const auto &f : cell_fields)
        {
          Assert(f.values.size() == f.n_components * mesh.n_cells(),
                 ExcInternalError());
          data.add_field(f);
        }
      xml << "      </CellData>\n"
          << "    </Piece>\n"
          << "  </UnstructuredGrid>\n"
          << "  <AppendedData encoding=\"raw\">\n_" << data.appended
          << "\n  </AppendedData>\n"
          << "</VTKFile>\n";
      write_file_atomically(path, xml.str());
    }
  } // namespace Output
} // namespace TissueContact
