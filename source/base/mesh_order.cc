#include <tissue_contact/base/mesh_order.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace TissueContact
{
  void
  order_mesh_by_cuthill_mckee(Triangulation<3> &triangulation)
  {
    AssertThrow(triangulation.n_levels() == 1,
                ExcMessage("a refined mesh cannot be renumbered"));
    auto [vertices, cells, subcells] =
      GridTools::get_coarse_mesh_description(triangulation);
    // create_triangulation() takes used vertices only (the description
    // lists every vertex up to the highest one a cell uses)
    GridTools::delete_unused_vertices(vertices, cells, subcells);
    const unsigned int n_vertices = vertices.size();

    // the vertices' graph, and their Cuthill-McKee numbers: new_number[v]
    // is the new number of vertex v
    DynamicSparsityPattern graph(n_vertices);
    for (const auto &cell : cells)
      for (const unsigned int a : cell.vertices)
        for (const unsigned int b : cell.vertices)
          graph.add(a, b);
    std::vector<DynamicSparsityPattern::size_type> new_number(n_vertices);
    SparsityTools::reorder_Cuthill_McKee(graph, new_number);

    std::vector<Point<3>> new_vertices(n_vertices);
    for (unsigned int v = 0; v < n_vertices; ++v)
      new_vertices[new_number[v]] = vertices[v];
    const auto renumber = [&](std::vector<unsigned int> &list) {
      for (unsigned int &v : list)
        v = new_number[v];
    };
    for (auto &cell : cells)
      renumber(cell.vertices);
    for (auto &quad : subcells.boundary_quads)
      renumber(quad.vertices);
    for (auto &line : subcells.boundary_lines)
      renumber(line.vertices);

    // the cells by their lowest vertex
    std::vector<unsigned int> lowest(cells.size());
    for (unsigned int c = 0; c < cells.size(); ++c)
      lowest[c] =
        *std::min_element(cells[c].vertices.begin(), cells[c].vertices.end());
    std::vector<unsigned int> order(cells.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       return lowest[a] < lowest[b];
                     });
    std::vector<CellData<3>> new_cells;
    new_cells.reserve(cells.size());
    for (const unsigned int c : order)
      new_cells.push_back(cells[c]);

    triangulation.clear();
    triangulation.create_triangulation(new_vertices, new_cells, subcells);
  }
} // namespace TissueContact
