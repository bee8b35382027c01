#include <tissue_contact/base/discretization.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>

namespace TissueContact
{
  Discretization::Discretization(const Triangulation<3> &triangulation,
                                 const unsigned int      degree,
                                 const bool              reduced_quadrature,
                                 const bool              renumber)
    : degree(degree)
    , fe(FE_SimplexP<3>(degree), 3)
    , mapping(FE_SimplexP<3>(1))
    , quadrature(degree + 1)
    , stiffness_quadrature(
        degree == 1 ? 1 : (reduced_quadrature ? degree : degree + 1))
    , face_quadrature(degree + 1)
    , dof_handler(triangulation)
  {
    AssertThrow(degree == 1 || degree == 2,
                ExcMessage("Polynomial degree must be 1 (linear "
                           "tetrahedra) or 2 (quadratic tetrahedra), not " +
                           std::to_string(degree)));
    dof_handler.distribute_dofs(fe);
    if (!renumber || !renumber_by_points())
      make_sparsity_pattern();
  }


  void
  Discretization::make_sparsity_pattern()
  {
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    sparsity_pattern.copy_from(dsp);
  }


  bool
  Discretization::renumber_by_points()
  {
    const types::global_dof_index n = dof_handler.n_dofs();
    if (n % 3 != 0)
      return false;
    // each point's DoFs must be 3 g + c
    const auto at_point = support_point_dofs();
    for (types::global_dof_index i = 0; i < n; ++i)
      for (unsigned int c = 0; c < 3; ++c)
        if (at_point[i][c] != i - i % 3 + c)
          return false;
    // the points' graph: two points joined where a cell holds both
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    DynamicSparsityPattern               graph(n / 3);
    std::vector<types::global_dof_index> points;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        points.clear();
        for (unsigned int k = 0; k < dofs.size(); ++k)
          if (fe.system_to_component_index(k).first == 0)
            points.push_back(dofs[k] / 3);
        std::sort(points.begin(), points.end());
        for (const auto g : points)
          graph.add_entries(g, points.begin(), points.end(), true);
      }
    std::vector<DynamicSparsityPattern::size_type> new_point(n / 3);
    SparsityTools::reorder_Cuthill_McKee(graph, new_point);
    std::vector<types::global_dof_index> new_dof(n);
    for (types::global_dof_index i = 0; i < n; ++i)
      new_dof[i] = 3 * new_point[i / 3] + i % 3;
    dof_handler.renumber_dofs(new_dof);
    make_sparsity_pattern();
    points_renumbered = true;
    return true;
  }


  std::vector<Point<3>>
  Discretization::support_points() const
  {
    std::vector<Point<3>> points(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    return points;
  }


  std::vector<unsigned int>
  Discretization::dof_components() const
  {
    std::vector<unsigned int>            component(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int k = 0; k < dofs.size(); ++k)
          component[dofs[k]] = fe.system_to_component_index(k).first;
      }
    return component;
  }


  std::vector<std::array<types::global_dof_index, 3>>
  Discretization::support_point_dofs() const
  {
    std::vector<std::array<types::global_dof_index, 3>> result(n_dofs());
    std::vector<types::global_dof_index>   dofs(fe.n_dofs_per_cell());
    std::array<types::global_dof_index, 3> at_point;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        // the components of one support point are one base element's
        // shape function in each of the three copies
        for (unsigned int k = 0; k < dofs.size(); ++k)
          {
            const unsigned int base = fe.system_to_component_index(k).second;
            for (unsigned int j = 0; j < dofs.size(); ++j)
              if (fe.system_to_component_index(j).second == base)
                at_point[fe.system_to_component_index(j).first] = dofs[j];
            result[dofs[k]] = at_point;
          }
      }
    return result;
  }


  Point<3>
  Discretization::mean_support_point() const
  {
    Point<3> mean;
    for (const auto &x : support_points())
      mean += x / static_cast<double>(n_dofs());
    return mean;
  }


  std::vector<Vector<double>>
  Discretization::rigid_body_modes() const
  {
    const std::vector<Point<3>>     X    = support_points();
    const std::vector<unsigned int> c    = dof_components();
    const Point<3>                  mean = mean_support_point();
    std::vector<Vector<double>>     modes(6, Vector<double>(n_dofs()));
    for (types::global_dof_index i = 0; i < n_dofs(); ++i)
      {
        modes[c[i]][i]       = 1.;
        const Tensor<1, 3> r = X[i] - mean;
        for (unsigned int a = 0; a < 3; ++a)
          {
            Tensor<1, 3> e;
            e[a]            = 1.;
            modes[3 + a][i] = cross_product_3d(e, r)[c[i]];
          }
      }
    return modes;
  }
} // namespace TissueContact
