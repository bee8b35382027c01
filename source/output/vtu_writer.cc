#include <tissue_contact/output/vtu_writer.h>

#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace TissueContact
{
  namespace Output
  {
    VtuSeriesWriter::VtuSeriesWriter(const Discretization &disc,
                                     const std::string    &directory,
                                     const std::string    &base_name,
                                     const Options        &options)
      : disc(disc)
      , directory(directory)
      , base_name(base_name)
      , options(options)
    {
      const auto        &tria     = disc.dof_handler.get_triangulation();
      const auto        &fe       = disc.fe;
      const unsigned int n_v      = tria.n_vertices();
      const bool         p2       = disc.degree == 2;
      volume.nodes_per_cell       = p2 ? 10 : 4;
      const unsigned int n_points = n_v + (p2 ? tria.n_raw_lines() : 0);
      volume.points.resize(n_points);
      point_dofs.resize(n_points);
      point_vertices.resize(n_points);
      for (unsigned int v = 0; v < n_v; ++v)
        {
          volume.points[v]  = tria.get_vertices()[v];
          point_vertices[v] = {{v, v}};
        }
      // VTK_QUADRATIC_TETRA's edge nodes: (0,1), (1,2), (0,2), (0,3),
      // (1,3), (2,3)
      const unsigned int vtk_edges[6][2] = {
        {0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          // the point of each base shape function of this cell
          std::array<unsigned int, 10> point_of_base;
          for (unsigned int b = 0; b < 4; ++b)
            point_of_base[b] = cell->vertex_index(b);
          if (p2)
            for (unsigned int e = 0; e < 6; ++e)
              {
                const unsigned int p = n_v + cell->line(e)->index();
                point_of_base[4 + e] = p;
                point_vertices[p]    = {{cell->line(e)->vertex_index(0),
                                         cell->line(e)->vertex_index(1)}};
                volume.points[p]     = cell->line(e)->center();
              }
          for (unsigned int k = 0; k < dofs.size(); ++k)
            {
              const auto [c, b]               = fe.system_to_component_index(k);
              point_dofs[point_of_base[b]][c] = dofs[k];
            }
          for (unsigned int b = 0; b < 4; ++b)
            volume.connectivity.push_back(point_of_base[b]);
          if (p2)
            for (const auto &edge : vtk_edges)
              for (unsigned int e = 0; e < 6; ++e)
                {
                  const unsigned int a = cell->line(e)->vertex_index(0),
                                     b = cell->line(e)->vertex_index(1);
                  const unsigned int x = cell->vertex_index(edge[0]),
                                     y = cell->vertex_index(edge[1]);
                  if ((a == x && b == y) || (a == y && b == x))
                    volume.connectivity.push_back(point_of_base[4 + e]);
                }
        }
      AssertThrow(volume.connectivity.size() ==
                    tria.n_active_cells() * volume.nodes_per_cell,
                  ExcInternalError());
    }


    void
    VtuSeriesWriter::set_surface(
      const std::vector<std::array<unsigned int, 3>> &triangles,
      const std::vector<types::material_id>          &body)
    {
      std::map<unsigned int, unsigned int> point_of;
      surface                = VtuMesh();
      surface.nodes_per_cell = 3;
      surface_vertices.clear();
      for (const auto &t : triangles)
        for (const unsigned int v : t)
          {
            const auto [it, added] =
              point_of.emplace(v, surface_vertices.size());
            if (added)
              {
                surface_vertices.push_back(v);
                surface.points.push_back(volume.points[v]);
              }
            surface.connectivity.push_back(it->second);
          }
      surface_body.assign(body.begin(), body.end());
    }


    std::string
    VtuSeriesWriter::pvd_file() const
    {
      return directory + "/" + base_name + ".pvd";
    }


    std::string
    VtuSeriesWriter::units(const std::string &quantity) const
    {
      if (quantity == "length")
        return options.length_unit;
      if (quantity == "stress")
        return options.stress_unit;
      return "";
    }


    VtuSeriesWriter::~VtuSeriesWriter()
    {
      try
        {
          finish();
        }
      catch (const std::exception &e)
        {
          std::cerr << "error: the last result files were not written: "
                    << e.what() << std::endl;
        }
    }


    void
    VtuSeriesWriter::finish() const
    {
      if (pending.valid())
        pending.get();
    }


    void
    VtuSeriesWriter::then(
      std::function<void(const Records &, const Records &)> task)
    {
      pending = std::async(std::launch::async,
                           [this,
                            previous = std::move(pending),
                            task     = std::move(task)]() mutable {
                             if (previous.valid())
                               previous.get();
                             task(records, surface_records);
                           });
    }


    std::string
    VtuSeriesWriter::write(const Elasticity::ElasticAssembler &assembler,
                           const Vector<double>               &u,
                           const double                        time,
                           const std::vector<VertexField>     &vertex_fields)
    {
      finish();
      std::ostringstream number;
      number << std::setw(4) << std::setfill('0') << records.size();

      // point data: the displacement and the vertex fields (at a P2 edge
      // point the mean of its two vertices', the fields being linear)
      const std::size_t     n_points = volume.points.size();
      std::vector<VtuField> point_fields;
      VtuField displacement{"displacement", 3, {}, units("length"), false};
      displacement.values.resize(3 * n_points);
      for (std::size_t p = 0; p < n_points; ++p)
        for (unsigned int c = 0; c < 3; ++c)
          displacement.values[3 * p + c] = u[point_dofs[p][c]];
      point_fields.push_back(displacement);
      for (const auto &f : vertex_fields)
        {
          VtuField field{f.name, f.n_components, {}, units(f.quantity), false};
          field.values.resize(f.n_components * n_points);
          for (std::size_t p = 0; p < n_points; ++p)
            for (unsigned int c = 0; c < f.n_components; ++c)
              field.values[f.n_components * p + c] =
                0.5 * (f.values[f.n_components * point_vertices[p][0] + c] +
                       f.values[f.n_components * point_vertices[p][1] + c]);
          point_fields.push_back(field);
        }

      // cell data
      const Elasticity::CellQuantities q       = assembler.cell_quantities(u);
      const std::size_t                n_cells = volume.n_cells();
      VtuField material_id{"material_id", 1, {}, "", true};
      for (const auto &cell : disc.dof_handler.active_cell_iterators())
        material_id.values.push_back(cell->material_id());
      VtuField stress{"cauchy_stress", 6, {}, units("stress"), false};
      stress.values.resize(6 * n_cells);
      // ours: xx yy zz yz xz xy; VTK's symmetric tensor: xx yy zz xy yz xz
      const unsigned int from[6] = {0, 1, 2, 5, 3, 4};
      for (std::size_t k = 0; k < n_cells; ++k)
        for (unsigned int c = 0; c < 6; ++c)
          stress.values[6 * k + c] = q.cauchy_stress[from[c]][k];
      const auto scalar = [](const std::string    &name,
                             const Vector<double> &v,
                             const std::string    &unit) {
        return VtuField{
          name, 1, std::vector<double>(v.begin(), v.end()), unit, false};
      };
      std::vector<VtuField> cell_fields = {material_id,
                                           scalar("J", q.J, ""),
                                           stress,
                                           scalar("von_mises",
                                                  q.von_mises,
                                                  units("stress")),
                                           scalar("strain_energy_density",
                                                  q.strain_energy_density,
                                                  units("stress"))};

      const std::string     name = base_name + "-" + number.str() + ".vtu";
      std::vector<VtuField> surface_fields;
      if (!surface_vertices.empty())
        for (const auto &f : point_fields)
          {
            VtuField s{f.name, f.n_components, {}, f.units, false};
            for (const unsigned int v : surface_vertices)
              for (unsigned int c = 0; c < f.n_components; ++c)
                s.values.push_back(f.values[f.n_components * v + c]);
            surface_fields.push_back(s);
          }

      // compressing and writing: the meshes are fixed after construction,
      // the fields are moved into the task, the records are only touched
      // by it until finish()
      pending = std::async(
        std::launch::async,
        [this,
         time,
         name,
         number         = number.str(),
         point_fields   = std::move(point_fields),
         cell_fields    = std::move(cell_fields),
         surface_fields = std::move(surface_fields)]() {
          write_vtu(directory + "/" + name,
                    volume,
                    point_fields,
                    cell_fields,
                    time,
                    options.double_precision);
          if (!surface_vertices.empty())
            {
              const std::string surface_name =
                base_name + "-surface-" + number + ".vtu";
              write_vtu(directory + "/" + surface_name,
                        surface,
                        surface_fields,
                        {VtuField{"body", 1, surface_body, "", true}},
                        time,
                        options.double_precision);
              surface_records.emplace_back(time, surface_name);
              write_pvd(directory + "/" + base_name + "-surface.pvd",
                        surface_records);
            }
          // the series lists a state only once its files are complete
          records.emplace_back(time, name);
          write_pvd(pvd_file(), records);
        });
      return directory + "/" + name;
    }
  } // namespace Output
} // namespace TissueContact
