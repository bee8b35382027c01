#include <tissue_contact/base/row_ranges.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>

namespace TissueContact
{
  unsigned int
  n_row_ranges()
  {
    return std::max(1u, std::min(MultithreadInfo::n_threads(), 64u));
  }


  std::vector<types::global_dof_index>
  balanced_row_ranges(const std::vector<std::size_t> &work,
                      const unsigned int              n_parts)
  {
    const types::global_dof_index        n_rows = work.size() - 1;
    std::vector<types::global_dof_index> bounds(n_parts + 1, n_rows);
    bounds[0]               = 0;
    const std::size_t total = work.back();
    for (unsigned int part = 1; part < n_parts; ++part)
      bounds[part] = static_cast<types::global_dof_index>(
        std::lower_bound(work.begin(),
                         work.end(),
                         (total * part + n_parts - 1) / n_parts) -
        work.begin());
    return bounds;
  }
} // namespace TissueContact
