// The VTU files read back: a twisted block (P1 and P2, pressed onto a rigid
// plane for the contact fields) is run with Output/Double precision, then
// the last state's files are decoded here (XML header, zlib blocks) and
// compared with the solution itself:
//  - a connected mesh: as many points as vertices (P1) or vertices and
//    edges (P2), every point used, no cell of zero or negative volume in
//    VTK's node order, and each P2 edge node the midpoint of its edge's
//    vertices in VTK_QUADRATIC_TETRA's order;
//  - the displacement at every point equals the solution at its DoFs, the
//    cell stress tensor equals ElasticAssembler::cell_quantities() in VTK's
//    component order (xx yy zz xy yz xz), the surface file's contact
//    pressure equals StepResults' (all exactly: Float64);
//  - the Float32 file of the same state, and its size against Float64's.

#include "../tests.h"

#include <tissue_contact/simulation/static_simulation.h>
#include <tissue_contact/simulation/step_results.h>

#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

namespace
{
  std::string
  scene(const unsigned int degree, const bool float64)
  {
    return R"(
subsection Discretization
  set Polynomial degree = )" +
           std::to_string(degree) + R"(
end
subsection Mesh
  set Box upper corner = 1, 1, 0.5
  set Box subdivisions = 3, 3, 2
end
subsection Bodies
  subsection Body 0
    set Model  = neo-Hookean
    set Mu     = 100
    set Lambda = 100
  end
end
subsection Boundary conditions
  set Number of Dirichlet conditions = 1
  subsection Dirichlet 0
    set Boundary id     = 5
    set Translation     = 0, 0, -0.05
    set Rotation axis   = 0, 0, 1
    set Rotation center = 0.5, 0.5, 0.5
    set Rotation angle  = 20
  end
end
subsection Contact
  set Contact surfaces    = 4
  set Number of obstacles = 1
  subsection Obstacle 0
    set Type           = plane
    set Penalty factor = 1e3
  end
end
subsection Newton
  set Quasi-viscosity = true
end
subsection Output
  set Print timing     = false
  set Directory        = out
  set Base name        = )" +
           std::string(float64 ? "f64" : "f32") + R"(
  set Double precision = )" +
           (float64 ? "true" : "false") + R"(
end
)";
  }

  /** A VTU file of ours, decoded: every array by name. */
  struct Vtu
  {
    std::size_t                                n_points = 0, n_cells = 0;
    std::map<std::string, std::vector<double>> arrays;
    std::map<std::string, unsigned int>        components;
  };

  template <typename T>
  std::vector<double>
  decode(const std::string &data, const std::size_t offset)
  {
    std::uint64_t header[4];
    std::memcpy(header, data.data() + offset, sizeof(header));
    std::vector<T> raw(header[1] / sizeof(T));
    uLongf         size = header[1];
    AssertThrow(uncompress(reinterpret_cast<Bytef *>(raw.data()),
                           &size,
                           reinterpret_cast<const Bytef *>(data.data() +
                                                           offset + 32),
                           header[3]) == Z_OK,
                ExcMessage("a block does not decompress"));
    return std::vector<double>(raw.begin(), raw.end());
  }

  Vtu
  read_vtu(const std::string &file)
  {
    std::ifstream      in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    const std::string text   = s.str();
    const std::size_t start  = text.find("<AppendedData encoding=\"raw\">");
    const std::size_t base   = text.find('_', start) + 1;
    const std::string header = text.substr(0, start);
    Vtu               v;
    std::smatch       m;
    std::regex_search(header,
                      m,
                      std::regex("NumberOfPoints=\"([0-9]+)\" "
                                 "NumberOfCells=\"([0-9]+)\""));
    v.n_points = std::stoul(m[1]);
    v.n_cells  = std::stoul(m[2]);
    const std::regex array(
      "type=\"([A-Za-z0-9]+)\" Name=\"([^\"]+)\" NumberOfComponents=\"([0-9]+)\""
      "[^>]*offset=\"([0-9]+)\"");
    for (auto it = std::sregex_iterator(header.begin(), header.end(), array);
         it != std::sregex_iterator();
         ++it)
      {
        const std::string type = (*it)[1], name = (*it)[2];
        const std::size_t offset = base + std::stoul((*it)[4]);
        v.components[name]       = std::stoul((*it)[3]);
        if (type == "Float64")
          v.arrays[name] = decode<double>(text, offset);
        else if (type == "Float32")
          v.arrays[name] = decode<float>(text, offset);
        else if (type == "Int64")
          v.arrays[name] = decode<std::int64_t>(text, offset);
        else if (type == "Int32")
          v.arrays[name] = decode<std::int32_t>(text, offset);
        else
          v.arrays[name] = decode<std::uint8_t>(text, offset);
      }
    return v;
  }

  Point<3>
  point(const Vtu &v, const std::size_t p)
  {
    const auto &x = v.arrays.at("Points");
    return Point<3>(x[3 * p], x[3 * p + 1], x[3 * p + 2]);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  for (const unsigned int degree : {1u, 2u})
    {
      std::ostringstream screen;
      StaticSimulation   sim(
        Scene::SceneParameters::from_string(scene(degree, true)), screen);
      const auto        statistics = sim.run();
      const Problem    &problem    = sim.problem();
      const auto       &tria       = problem.get_scene().triangulation;
      const std::string last =
        "out/f64-" + Utilities::int_to_string(statistics.increments, 4) +
        ".vtu";
      const Vtu v = read_vtu(last);
      deallog << "P" << degree << ": " << statistics.increments
              << " increments; " << last << ": " << v.n_points << " points ("
              << tria.n_vertices() << " vertices, " << tria.n_raw_lines()
              << " edges), " << v.n_cells << " cells (" << tria.n_active_cells()
              << " tetrahedra)" << std::endl;

      // connectivity: points used, volumes, edge midpoints
      const unsigned int n_nodes = degree == 1 ? 4 : 10;
      const auto        &conn    = v.arrays.at("connectivity");
      std::vector<bool>  used(v.n_points, false);
      unsigned int       non_positive   = 0;
      double             midpoint_error = 0.;
      const unsigned int edges[6][2]    = {
           {0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
      for (std::size_t c = 0; c < v.n_cells; ++c)
        {
          std::array<Point<3>, 10> x;
          for (unsigned int k = 0; k < n_nodes; ++k)
            {
              used[conn[n_nodes * c + k]] = true;
              x[k]                        = point(v, conn[n_nodes * c + k]);
            }
          non_positive +=
            (x[1] - x[0]) * cross_product_3d(x[2] - x[0], x[3] - x[0]) <= 0.;
          if (degree == 2)
            for (unsigned int e = 0; e < 6; ++e)
              midpoint_error = std::max(
                midpoint_error,
                (x[4 + e] - 0.5 * (x[edges[e][0]] + x[edges[e][1]])).norm());
        }
      deallog << "  unused points "
              << std::count(used.begin(), used.end(), false)
              << ", cells of non-positive volume " << non_positive
              << ", largest edge-node distance from its edge's midpoint "
              << error_bound(midpoint_error, -14) << std::endl;

      // the displacement: at each point, the solution at the DoFs there
      const Vector<double> u = problem.displacement(sim.solution());
      const auto           X = problem.discretization().support_points();
      const auto point_dofs  = problem.discretization().support_point_dofs();
      std::map<std::array<double, 3>, std::array<types::global_dof_index, 3>>
        dofs_at;
      for (types::global_dof_index i = 0; i < X.size(); ++i)
        dofs_at[{{X[i][0], X[i][1], X[i][2]}}] = point_dofs[i];
      double      u_error = 0.;
      const auto &U       = v.arrays.at("displacement");
      for (std::size_t p = 0; p < v.n_points; ++p)
        {
          const Point<3> y = point(v, p);
          const auto     d = dofs_at.at({{y[0], y[1], y[2]}});
          for (unsigned int c = 0; c < 3; ++c)
            u_error = std::max(u_error, std::abs(U[3 * p + c] - u[d[c]]));
        }
      // the stress tensor, per cell in VTK's component order
      const auto         q = problem.elastic_assembler().cell_quantities(u);
      const auto        &S = v.arrays.at("cauchy_stress");
      const unsigned int ours[6] = {0, 1, 2, 5, 3, 4};
      double             s_error = 0., s_max = 0.;
      for (std::size_t c = 0; c < v.n_cells; ++c)
        for (unsigned int k = 0; k < 6; ++k)
          {
            s_error =
              std::max(s_error,
                       std::abs(S[6 * c + k] - q.cauchy_stress[ours[k]][c]));
            s_max = std::max(s_max, std::abs(q.cauchy_stress[ours[k]][c]));
          }
      // the surface file's contact pressure
      const Vtu surface =
        read_vtu("out/f64-surface-" +
                 Utilities::int_to_string(statistics.increments, 4) + ".vtu");
      const StepResults r(problem, sim.solution(), 1.);
      double            p_total = 0., p_file = 0.;
      for (const double p : r.contact.pressure)
        p_total += p;
      for (const double p : surface.arrays.at("contact_pressure"))
        p_file += p;
      deallog << "  displacement: largest difference "
              << error_bound(u_error, -14) << "; stress ("
              << v.components.at("cauchy_stress")
              << " components): largest difference "
              << error_bound(s_error, -14) << " of " << std::setprecision(3)
              << s_max << std::setprecision(6)
              << "; surface file: " << surface.n_cells << " triangles, sum of "
              << "contact pressures " << std::setprecision(10) << p_file
              << ", in the results " << p_total << std::setprecision(6)
              << std::endl;

      if (degree == 1)
        {
          StaticSimulation f32(
            Scene::SceneParameters::from_string(scene(degree, false)), screen);
          f32.run();
          const std::string last32 =
            "out/f32-" + Utilities::int_to_string(statistics.increments, 4) +
            ".vtu";
          const Vtu w = read_vtu(last32);
          double    e = 0.;
          for (std::size_t i = 0; i < U.size(); ++i)
            e = std::max(e, std::abs(w.arrays.at("displacement")[i] - U[i]));
          deallog << "  Float32: displacement within "
                  << error_bound(e / 0.05, -7) << " of the largest, file size "
                  << std::setprecision(2)
                  << double(std::filesystem::file_size(last32)) /
                       std::filesystem::file_size(last)
                  << std::setprecision(6) << " of Float64's" << std::endl;
        }
    }
}
