#include <tissue_contact/base/row_ranges.h>
#include <tissue_contact/base/timing.h>
#include <tissue_contact/contact/body_contact_assembler.h>
#include <tissue_contact/contact/contact_parameters.h>
#include <tissue_contact/contact/material_depth.h>
#include <tissue_contact/contact/penalty_energy.h>
#include <tissue_contact/contact/point_collocation.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/work_stream.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace TissueContact
{
  namespace Contact
  {
    BodyContactAssembler::BodyContactAssembler(
      const ContactSurface                                   &surface,
      const Triangulation<3>                                 &tria,
      const std::set<types::boundary_id>                     &contact_surfaces,
      const std::vector<BodyContact>                         &pairs,
      const std::map<types::material_id, types::material_id> &body_of)
      : surface(surface)
      , pairs(pairs)
    {
      // the one place area integration and point collocation differ
      for (const auto &p : pairs)
        methods.push_back(
          p.point_collocation ?
            Method{&collocation_energy<double>, &collocation_kernel} :
            Method{&penalty_energy_value, &penalty_kernel});
      if (pairs.empty())
        return;
      // material depth, and a tree over the tetrahedra of the volume bodies
      depth           = compute_material_depth(tria, contact_surfaces, body_of);
      const auto body = [&](const types::material_id m) {
        return body_of_material(body_of, m);
      };
      std::set<types::material_id>               volume_bodies;
      std::map<types::material_id, unsigned int> number;
      for (const auto &p : pairs)
        {
          volume_bodies.insert(p.volume_body);
          number.emplace(p.surface_body, number.size());
          number.emplace(p.volume_body, number.size());
        }
      n_pair_bodies = number.size();
      pairs_of.resize(n_pair_bodies * n_pair_bodies);
      for (unsigned int i = 0; i < pairs.size(); ++i)
        pairs_of[n_pair_bodies * number[pairs[i].surface_body] +
                 number[pairs[i].volume_body]]
          .push_back(i);
      for (const auto b : surface.triangle_body)
        triangle_body.push_back(number.count(b) > 0 ? number[b] :
                                                      n_pair_bodies);
      // the tree holds the tetrahedra with a vertex of positive depth: one
      // whose vertices all lie on contact surfaces (depth 0) has no material
      // depth to push with, so no pair with it has energy; in the thin
      // layers of the knee such tetrahedra were half the candidates
      // (doc/theory/05-contact.md, sec. 2.2). The rebuild distance is the
      // mean box diagonal of all the volume bodies' tetrahedra.
      double                      size    = 0.;
      unsigned int                n_boxes = 0;
      std::vector<BoundingBox<3>> boxes;
      for (const auto &cell : tria.active_cell_iterators())
        if (volume_bodies.count(body(cell->material_id())) > 0)
          {
            const std::array<unsigned int, 4> v{{cell->vertex_index(0),
                                                 cell->vertex_index(1),
                                                 cell->vertex_index(2),
                                                 cell->vertex_index(3)}};
            for (const unsigned int i : v)
              AssertThrow(std::isfinite(depth[i]),
                          ExcMessage("Contact: body with material id " +
                                     std::to_string(body(cell->material_id())) +
                                     " is the volume body of a pair but has "
                                     "no contact surface: its material depth "
                                     "is undefined"));
            const BoundingBox<3> box(
              std::array<Point<3>, 4>{{surface.X[v[0]],
                                       surface.X[v[1]],
                                       surface.X[v[2]],
                                       surface.X[v[3]]}});
            size += box.get_boundary_points().first.distance(
              box.get_boundary_points().second);
            ++n_boxes;
            if (std::none_of(v.begin(), v.end(), [&](const unsigned int i) {
                  return depth[i] > 0.;
                }))
              continue;
            tets.push_back(v);
            tet_body.push_back(number[body(cell->material_id())]);
            boxes.push_back(box);
          }
      tree             = std::make_unique<BoundingVolumeTree>(boxes);
      x_at_build       = surface.X;
      rebuild_distance = n_boxes == 0 ? 0. : size / n_boxes;
      candidate_margin = 0.1 * rebuild_distance;
      for (unsigned int t = 0; t < surface.triangles.size(); ++t)
        if (surface_of_a_pair(t))
          surface_triangles.push_back(t);
    }


    void
    BodyContactAssembler::update_candidates(
      const std::vector<Point<3>> &x) const
    {
      // the vertices that moved more than half the margin from their
      // reference positions (doc/theory/05-contact.md, sec. 2.1)
      std::vector<bool> moved;
      unsigned int      n_moved = 0;
      if (have_candidates)
        {
          const double limit = 0.25 * candidate_margin * candidate_margin;
          moved.resize(x.size());
          for (unsigned int v = 0; v < x.size(); ++v)
            if (x[v].distance_square(x_reference[v]) > limit)
              {
                moved[v] = true;
                ++n_moved;
              }
          if (n_moved == 0)
            return;
        }
      const auto scope     = time_section(timer, "contact: search");
      const auto has_moved = [&](const auto &vertices) {
        return std::any_of(vertices.begin(),
                           vertices.end(),
                           [&](const unsigned int v) { return moved[v]; });
      };
      // the tetrahedra with a moved vertex; with more than half of them
      // moved a new search costs less than the update
      std::vector<unsigned int> moved_tets;
      if (have_candidates)
        for (unsigned int k = 0; k < tets.size(); ++k)
          if (has_moved(tets[k]))
            moved_tets.push_back(k);
      const bool search_all =
        !have_candidates || 2 * moved_tets.size() > tets.size();
      if (search_all)
        x_reference = x;
      else
        for (unsigned int v = 0; v < x.size(); ++v)
          if (moved[v])
            x_reference[v] = x[v];
      refit(x_reference);
      // the moved tetrahedra in a tree of their own, for the triangles that
      // did not move: their other candidates stay what they were
      std::unique_ptr<BoundingVolumeTree> moved_tree;
      if (!search_all && !moved_tets.empty())
        {
          std::vector<BoundingBox<3>> boxes;
          for (const unsigned int k : moved_tets)
            boxes.push_back(tet_box(x_reference, k));
          moved_tree = std::make_unique<BoundingVolumeTree>(boxes);
        }
      std::vector<bool> tet_moved(search_all ? 0 : tets.size());
      if (!search_all)
        for (const unsigned int k : moved_tets)
          tet_moved[k] = true;
      // the new list written into the memory of the one before the current
      // one, reserved at the current one's size and an eighth more: on the
      // full knee's first 8 increments (some 300 000 candidates, 5 MB) a
      // list grown anew at every update, by the serial appends below, made
      // the updates about 15 % slower
      std::swap(previous_candidates, candidates);
      std::swap(previous_offsets, offsets);
      const std::vector<Candidate>    &old_candidates = previous_candidates;
      const std::vector<unsigned int> &old_offsets    = previous_offsets;
      candidates.clear();
      candidates.reserve(old_candidates.size() + old_candidates.size() / 8);
      offsets.assign(1, 0);
      offsets.reserve(old_offsets.size());
      // the triangles in parallel (the trees are only read), each list
      // sorted by tetrahedron and pair: the same list whichever way it was
      // found, so the sums over it are too
      per_surface_triangle(
        [&](const unsigned int i, std::vector<Candidate> &found) {
          found.clear();
          const unsigned int t    = surface_triangles[i];
          const auto         keep = [&](const unsigned int t,
                                const unsigned int k,
                                const BodyContact &p) {
            found.push_back({t,
                             k,
                             static_cast<unsigned int>(&p - pairs.data()),
                             shared_vertices(t, k)});
          };
          if (search_all || has_moved(surface.triangles[t]))
            for_each_candidate_of(t, x_reference, candidate_margin, keep);
          else
            {
              for (unsigned int c = old_offsets[i]; c < old_offsets[i + 1]; ++c)
                if (!tet_moved[old_candidates[c].k])
                  found.push_back(old_candidates[c]);
              if (!moved_tree)
                return;
              const std::size_t n_kept = found.size();
              for_each_candidate_in(*moved_tree,
                                    moved_tets,
                                    t,
                                    x_reference,
                                    candidate_margin,
                                    keep);
              if (found.size() == n_kept)
                return; // what is left of a sorted list is sorted
            }
          std::sort(found.begin(),
                    found.end(),
                    [](const Candidate &a, const Candidate &b) {
                      return a.k < b.k || (a.k == b.k && a.pair < b.pair);
                    });
        },
        [&](const std::vector<Candidate> &found) {
          candidates.insert(candidates.end(), found.begin(), found.end());
          offsets.push_back(candidates.size());
        },
        std::vector<Candidate>());
      have_candidates = true;
      have_survivors  = false;
    }


    BoundingBox<3>
    BodyContactAssembler::tet_box(const std::vector<Point<3>> &x,
                                  const unsigned int           k) const
    {
      const auto &t = tets[k];
      return BoundingBox<3>(
        std::array<Point<3>, 4>{{x[t[0]], x[t[1]], x[t[2]], x[t[3]]}});
    }


    BodyContactAssembler::SharedVertices
    BodyContactAssembler::shared_vertices(const unsigned int t,
                                          const unsigned int k) const
    {
      const auto    &kv = tets[k];
      SharedVertices shared;
      for (unsigned int a = 0; a < 3; ++a)
        shared[a] = static_cast<unsigned char>(
          std::find(kv.begin(), kv.end(), surface.triangles[t][a]) -
          kv.begin());
      return shared;
    }


    void
    BodyContactAssembler::refit(const std::vector<Point<3>> &x) const
    {
      std::vector<BoundingBox<3>> boxes;
      boxes.reserve(tets.size());
      for (unsigned int k = 0; k < tets.size(); ++k)
        boxes.push_back(tet_box(x, k));
      // a refitted tree stays exact but degrades when objects that were
      // neighbours drift apart: rebuild once a vertex has moved farther than
      // the mean tetrahedron size since the last build (a rebuild costs
      // about 25 refits, both far below one assembly)
      double moved = 0.;
      for (const auto &t : tets)
        for (const unsigned int v : t)
          moved = std::max(moved, x[v].distance_square(x_at_build[v]));
      if (std::sqrt(moved) > rebuild_distance)
        {
          tree       = std::make_unique<BoundingVolumeTree>(boxes);
          x_at_build = x;
          ++n_rebuilds;
        }
      else
        tree->refit(boxes);
    }


    bool
    BodyContactAssembler::surface_of_a_pair(const unsigned int t) const
    {
      for (const auto &p : pairs)
        if (p.surface_body == surface.triangle_body[t])
          return true;
      return false;
    }


    template <typename F>
    void
    BodyContactAssembler::for_each_candidate_of(const unsigned int           t,
                                                const std::vector<Point<3>> &x,
                                                const double margin,
                                                const F     &f) const
    {
      for_each_candidate_in(*tree, {}, t, x, margin, f);
    }


    template <typename F>
    void
    BodyContactAssembler::for_each_candidate_in(
      const BoundingVolumeTree        &in,
      const std::vector<unsigned int> &tet_of,
      const unsigned int               t,
      const std::vector<Point<3>>     &x,
      const double                     margin,
      const F                         &f) const
    {
      if (!surface_of_a_pair(t))
        return;
      const std::vector<unsigned int> *row =
        &pairs_of[n_pair_bodies * triangle_body[t]];
      const auto    &tv = surface.triangles[t];
      BoundingBox<3> box =
        BoundingBox<3>(std::array<Point<3>, 3>{{x[tv[0]], x[tv[1]], x[tv[2]]}});
      if (margin > 0.)
        box.extend(margin);
      in.for_each_overlap(box, [&](const unsigned int object) {
        const unsigned int k = tet_of.empty() ? object : tet_of[object];
        const std::vector<unsigned int> &matching = row[tet_body[k]];
        if (matching.empty())
          return;
        const auto &kv = tets[k];
        // a triangle that is a face of the tetrahedron
        unsigned int shared = 0;
        for (const unsigned int a : tv)
          shared += std::count(kv.begin(), kv.end(), a);
        if (shared == 3)
          return;
        for (const unsigned int p : matching)
          f(t, k, pairs[p]);
      });
    }


    bool
    BodyContactAssembler::begin_survivors(const std::vector<Point<3>> &x) const
    {
      if (have_survivors && x == x_at_survivors)
        return true;
      have_survivors   = false;
      have_with_energy = false;
      survivors.resize(surface_triangles.size());
      with_energy.resize(surface_triangles.size());
      make_frames(x);
      return false;
    }


    void
    BodyContactAssembler::make_frames(const std::vector<Point<3>> &x) const
    {
      frames.resize(tets.size());
      parallel::apply_to_subranges(
        0u,
        static_cast<unsigned int>(tets.size()),
        [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int k = begin; k < end; ++k)
            {
              const auto &kv = tets[k];
              frames[k]      = TetrahedronFrame(std::array<Point<3>, 4>{
                     {x[kv[0]], x[kv[1]], x[kv[2]], x[kv[3]]}});
            }
        },
        1024);
    }


    void
    BodyContactAssembler::end_survivors(const std::vector<Point<3>> &x) const
    {
      if (have_survivors)
        return;
      x_at_survivors = x;
      have_survivors = true;
    }


    template <typename F>
    void
    BodyContactAssembler::visit(const unsigned int           c,
                                const std::vector<Point<3>> &x,
                                const F                     &f) const
    {
      const Candidate &candidate = candidates[c];
      f(candidate.t,
        candidate.k,
        pairs[candidate.pair],
        pair_geometry(x, candidate.t, candidate.k));
    }


    template <typename F>
    void
    BodyContactAssembler::for_each_surviving_pair_of(
      const unsigned int           i,
      const std::vector<Point<3>> &x,
      const bool                   known,
      const F                     &f) const
    {
      std::vector<unsigned int> &found = survivors[i];
      if (known)
        {
          for (const unsigned int c : found)
            visit(c, x, f);
          return;
        }
      found.clear();
      const auto &tv = surface.triangles[surface_triangles[i]];
      const std::array<Point<3>, 3> tri{{x[tv[0]], x[tv[1]], x[tv[2]]}};
      const TriangleFrame           tri_frame(tri);
      for (unsigned int c = offsets[i]; c < offsets[i + 1]; ++c)
        {
          // the frame of a candidate a few ahead fetched now: the frames
          // are read in no order the processor foresees, and the tests are
          // short (doc/theory/05-contact.md, sec. 2.2)
          if (c + 6 < offsets.back())
            prefetch(frames[candidates[c + 6].k]);
          const Candidate &candidate = candidates[c];
          // cheap rejection before differentiating: zero energy near this
          // position has zero gradient and Hessian
          if (pair_rejected(
                candidate.shared, frames[candidate.k], tri_frame, tri))
            continue;
          found.push_back(c);
          f(candidate.t,
            candidate.k,
            pairs[candidate.pair],
            pair_geometry(x, candidate.t, candidate.k));
        }
    }


    template <typename F>
    void
    BodyContactAssembler::for_each_pair_with_energy(
      const unsigned int           i,
      const std::vector<Point<3>> &x,
      const bool                   known,
      const F                     &f) const
    {
      if (known && have_with_energy)
        {
          for (const unsigned int c : with_energy[i])
            visit(c, x, f);
          return;
        }
      with_energy[i].clear();
      unsigned int j = 0; // the survivor of the call: survivors[i][j]
      for_each_surviving_pair_of(
        i,
        x,
        known,
        [&](const unsigned int  t,
            const unsigned int  k,
            const BodyContact  &p,
            const PairGeometry &geometry) {
          const unsigned int c      = survivors[i][j++];
          const auto &[tet, tri, g] = geometry;
          if (!(method_of(p).energy(tet, tri, g, p.penalty) > 0.))
            return;
          with_energy[i].push_back(c);
          f(t, k, p, geometry);
        });
    }


    BodyContactAssembler::PairGeometry
    BodyContactAssembler::pair_geometry(const std::vector<Point<3>> &x,
                                        const unsigned int           t,
                                        const unsigned int           k) const
    {
      const auto &kv = tets[k];
      const auto &tv = surface.triangles[t];
      return {{x[kv[0]], x[kv[1]], x[kv[2]], x[kv[3]]},
              {x[tv[0]], x[tv[1]], x[tv[2]]},
              {depth[kv[0]], depth[kv[1]], depth[kv[2]], depth[kv[3]]}};
    }


    std::array<types::global_dof_index, 21>
    BodyContactAssembler::pair_dofs(const unsigned int t,
                                    const unsigned int k) const
    {
      std::array<types::global_dof_index, 21> dofs;
      for (unsigned int a = 0; a < 4; ++a)
        for (unsigned int c = 0; c < 3; ++c)
          dofs[3 * a + c] = surface.vertex_dofs[tets[k][a]][c];
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int c = 0; c < 3; ++c)
          dofs[12 + 3 * a + c] =
            surface.vertex_dofs[surface.triangles[t][a]][c];
      return dofs;
    }


    void
    BodyContactAssembler::assemble(const Vector<double> &u,
                                   Vector<double>       &R,
                                   SparseMatrix<double> *K) const
    {
      if (pairs.empty())
        return;
      evaluate_pairs(u, K != nullptr);
      const auto scope = time_section(timer, "contact: insertion");
      // the rows of R and K split among the threads, each row added by one
      // thread, the owner of its range, with the pairs' additions in the
      // list's order: every entry receives the same additions in the same
      // order as in a serial loop over the pairs (the same sums to the last
      // bit)
      std::vector<const PairResult *> list;
      for (const auto &results : pair_results)
        for (const PairResult &r : results)
          list.push_back(&r);
      std::vector<DistinctDofs> distinct(list.size());
      parallel::apply_to_subranges(
        std::size_t(0),
        list.size(),
        [&](const std::size_t begin, const std::size_t end) {
          for (std::size_t p = begin; p < end; ++p)
            distinct[p] = distinct_dofs(*list[p]);
        },
        256);
      // the rows' incidences, counted once: they split the rows among the
      // threads and place each row's pairs in its thread's list
      const std::vector<std::size_t> incidences =
        row_incidences(distinct, R.size());
      const unsigned int                         n_parts = n_row_ranges();
      const std::vector<types::global_dof_index> bounds =
        insertion_row_ranges(incidences, n_parts);
      parallel::apply_to_subranges(
        0u,
        n_parts,
        [&](const unsigned int part_begin, const unsigned int part_end) {
          for (unsigned int part = part_begin; part < part_end; ++part)
            add_rows(
              list, distinct, incidences, bounds[part], bounds[part + 1], R, K);
        },
        1);
      pair_results.clear();
    }


    std::vector<std::size_t>
    BodyContactAssembler::row_incidences(
      const std::vector<DistinctDofs> &distinct,
      const types::global_dof_index    n_rows)
    {
      std::vector<std::size_t> incidences(n_rows + 1, 0);
      for (const DistinctDofs &d : distinct)
        for (unsigned int s = 0; s < d.n; ++s)
          ++incidences[d.dofs[s] + 1];
      std::partial_sum(incidences.begin(),
                       incidences.end(),
                       incidences.begin());
      return incidences;
    }


    std::vector<types::global_dof_index>
    BodyContactAssembler::insertion_row_ranges(
      const std::vector<std::size_t> &incidences,
      const unsigned int              n_parts)
    {
      if (n_parts == 1)
        return {0, incidences.size() - 1};
      // a part's work is about the number of (pair, row) incidences in its
      // rows: ranges of equal row counts gave the first of two threads 60 %
      // of them on the full knee's first 8 increments (contact sits where
      // the numbering puts it) and two thirds of the insertion's time (the
      // whole flexion gained nothing measurable; doc/theory/05-contact.md
      // sec. 7)
      return TissueContact::balanced_row_ranges(incidences, n_parts);
    }


    BodyContactAssembler::DistinctDofs
    BodyContactAssembler::distinct_dofs(const PairResult &r) const
    {
      const auto                   dofs = pair_dofs(r.t, r.k);
      std::array<unsigned int, 21> order;
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
        return dofs[a] < dofs[b];
      });
      DistinctDofs d;
      for (const unsigned int i : order)
        {
          if (d.n == 0 || d.dofs[d.n - 1] != dofs[i])
            {
              d.first[d.n]  = i;
              d.dofs[d.n++] = dofs[i];
            }
          d.slot[i] = d.n - 1;
        }
      return d;
    }


    void
    BodyContactAssembler::add_rows(const std::vector<const PairResult *> &list,
                                   const std::vector<DistinctDofs> &distinct,
                                   const std::vector<std::size_t>  &incidences,
                                   const types::global_dof_index    lo,
                                   const types::global_dof_index    hi,
                                   Vector<double>                  &R,
                                   SparseMatrix<double>            *K) const
    {
      // the (pair, distinct DoF) incidences of each row of the range, in
      // the list's order: row r's from start[r - lo] on
      std::vector<unsigned int> start(hi - lo + 1);
      for (types::global_dof_index r = lo; r <= hi; ++r)
        start[r - lo] = incidences[r] - incidences[lo];
      std::vector<std::pair<unsigned int, unsigned int>> incidence(
        start.back());
      {
        std::vector<unsigned int> next(start.begin(), start.end() - 1);
        for (unsigned int p = 0; p < distinct.size(); ++p)
          for (unsigned int s = 0; s < distinct[p].n; ++s)
            {
              const types::global_dof_index row = distinct[p].dofs[s];
              if (row >= lo && row < hi)
                incidence[next[row - lo]++] = {p, s};
            }
      }
      // a column's place in the current row: valid where its stamp is the
      // row
      std::vector<types::global_dof_index> stamp;
      std::vector<unsigned int>            place;
      if (K != nullptr)
        {
          // (K may have more columns than R rows: a free rigid body's)
          stamp.assign(K->n(), numbers::invalid_dof_index);
          place.resize(K->n());
        }
      for (types::global_dof_index row = lo; row < hi; ++row)
        {
          const unsigned int first = start[row - lo],
                             last  = start[row - lo + 1];
          if (first == last)
            continue;
          // R: each pair's entries at this row, in their order among the 21
          for (unsigned int e = first; e < last; ++e)
            {
              const auto &[p, s]    = incidence[e];
              const DistinctDofs &d = distinct[p];
              if (d.n == 21)
                R[row] += list[p]->d.gradient[d.first[s]];
              else
                for (unsigned int i = 0; i < 21; ++i)
                  if (d.slot[i] == s)
                    R[row] += list[p]->d.gradient[i];
            }
          if (K == nullptr)
            continue;
          const SparsityPattern &pattern = K->get_sparsity_pattern();
          double                *values  = &K->diag_element(row);
          const unsigned int     length  = pattern.row_length(row);
          for (unsigned int q = 0; q < length; ++q)
            {
              const types::global_dof_index column =
                pattern.column_number(row, q);
              stamp[column] = row;
              place[column] = q;
            }
          const auto add = [&](const types::global_dof_index column,
                               const double                  value) {
            if (stamp[column] == row)
              values[place[column]] += value;
            else
              // only a zero may miss its place, as with add()
              AssertThrow(value == 0.,
                          ExcMessage("A contact pair's coupling (row " +
                                     std::to_string(row) + ", column " +
                                     std::to_string(column) +
                                     ") is not in the matrix's pattern."));
          };
          // K: each pair's row summed onto its distinct columns (in the
          // order of the 21 rows and columns, from zero), then added once
          // per column
          for (unsigned int e = first; e < last; ++e)
            {
#if defined(__GNUC__)
              // the next pair's row fetched ahead: the pairs' Hessians are
              // read in no order the processor foresees
              if (e + 1 < last)
                {
                  const auto &[pn, sn] = incidence[e + 1];
                  const char *h        = reinterpret_cast<const char *>(
                    list[pn]->d.hessian[distinct[pn].first[sn]].data());
                  for (unsigned int b = 0; b < 21 * sizeof(double); b += 64)
                    __builtin_prefetch(h + b);
                }
#endif
              const auto &[p, s]    = incidence[e];
              const DistinctDofs &d = distinct[p];
              const auto         &H = list[p]->d.hessian;
              if (d.n == 21)
                {
                  // each column once: its sum from zero is 0 + H_ij
                  const auto &row_of_H = H[d.first[s]];
                  for (unsigned int j = 0; j < 21; ++j)
                    add(d.dofs[d.slot[j]], 0. + row_of_H[j]);
                  continue;
                }
              std::array<double, 21> sum{};
              for (unsigned int i = 0; i < 21; ++i)
                if (d.slot[i] == s)
                  for (unsigned int j = 0; j < 21; ++j)
                    sum[d.slot[j]] += H[i][j];
              for (unsigned int c = 0; c < d.n; ++c)
                add(d.dofs[c], sum[c]);
            }
        }
    }


    void
    BodyContactAssembler::evaluate_pairs(const Vector<double> &u,
                                         const bool with_hessian) const
    {
      const std::vector<Point<3>> x = surface.positions(u);
      update_candidates(x);
      const auto scope = time_section(timer, "contact: kernels");
      const bool known = begin_survivors(x);
      // the pairs of each contact triangle are evaluated in parallel (the
      // list is only read, a triangle's survivors and results written by
      // its worker alone)
      pair_results.resize(surface_triangles.size());
      // the kernel writes into the work item's own scratch; a pair with
      // energy is copied to its triangle's list (the lists hold only such
      // pairs and are released after use: kept at their largest size, they
      // held 148 MiB more at the full knee's peak)
      per_surface_triangle(
        [&](const unsigned int i, PairKernel &scratch) {
          std::vector<PairResult> &results = pair_results[i];
          results.clear();
          const auto evaluate = [&](const unsigned int  t,
                                    const unsigned int  k,
                                    const BodyContact  &p,
                                    const PairGeometry &geometry) {
            const auto &[tet, tri, g] = geometry;
            if (method_of(p).kernel(
                  tet, tri, g, p.penalty, with_hessian, scratch))
              results.push_back(
                {t, k, static_cast<unsigned int>(&p - pairs.data()), scratch});
          };
          for_each_pair_with_energy(i, x, known, evaluate);
        },
        [](const PairKernel &) {},
        PairKernel());
      end_survivors(x);
      have_with_energy = true;
    }


    template <typename F>
    void
    BodyContactAssembler::for_each_pair_contact(const Vector<double> &u,
                                                const bool with_hessian,
                                                const F   &f) const
    {
      if (pairs.empty())
        return;
      evaluate_pairs(u, with_hessian);
      for (const auto &results : pair_results)
        for (const PairResult &r : results)
          f(r.t, r.k, r.pair, r.d);
      pair_results.clear();
    }


    void
    BodyContactAssembler::add_couplings(const Vector<double> &u,
                                        const double          margin,
                                        PatternRows          &rows,
                                        const bool where_missing) const
    {
      if (pairs.empty())
        return;
      const std::vector<Point<3>> x = surface.positions(u);
      refit(x);
      // where the rows hold the pattern the sparsity check found incomplete
      // at u, the triangles it found a coupling missing for and their
      // neighbours (sharing a vertex) are searched, the others' pairs with
      // energy being coupled already; the neighbours get the margin's
      // couplings too, as a contact zone spreads to them next (on the full
      // knee's first 8 increments 39 builds instead of 43 for the
      // triangles alone; doc/theory/05-contact.md, sec. 7)
      std::vector<unsigned char> search(surface_triangles.size(), 1);
      if (where_missing && missing_couplings.size() == search.size())
        {
          std::vector<unsigned char> near(surface.X.size(), 0);
          for (unsigned int i = 0; i < search.size(); ++i)
            if (missing_couplings[i])
              for (const unsigned int v :
                   surface.triangles[surface_triangles[i]])
                near[v] = 1;
          for (unsigned int i = 0; i < search.size(); ++i)
            {
              const auto &tv = surface.triangles[surface_triangles[i]];
              search[i]      = near[tv[0]] || near[tv[1]] || near[tv[2]];
            }
        }
      // the vertices' couplings first, then each vertex row expanded to its
      // 3 x 3 DoF blocks: a ninth of the insertions of adding each pair's
      // 21 x 21 DoFs (the pattern builds were 7 % of the knee-scale tube's
      // run that way). A pair couples its tetrahedron's 4 vertices and its
      // triangle's 3 with each other; the tetrahedron is a cell and the
      // triangle a face of one, so the finite element pattern holds their
      // couplings among themselves, and only those across are added: with
      // V the vertices of a triangle's pairs' tetrahedra, the triangle's
      // rows get V and the rows of V the triangle's vertices (on the full
      // knee this halved the insertions, the same pattern). The triangles'
      // searches in parallel, their vertices appended to the vertices'
      // lists in the triangles' order, each list sorted once at the end
      std::vector<std::vector<unsigned int>> across(surface.X.size());
      struct Across
      {
        std::array<unsigned int, 3> triangle;
        std::vector<unsigned int>   V; // sorted, unique
      };
      per_surface_triangle(
        [&](const unsigned int i, Across &found) {
          found.V.clear();
          found.triangle = surface.triangles[surface_triangles[i]];
          if (!search[i])
            return;
          const auto         &tv = found.triangle;
          const TriangleFrame tri_frame(
            std::array<Point<3>, 3>{{x[tv[0]], x[tv[1]], x[tv[2]]}});
          for_each_candidate_of(
            surface_triangles[i],
            x,
            margin,
            [&](const unsigned int t,
                const unsigned int k,
                const BodyContact &p) {
              if (may_gain_energy(x, t, k, p, margin, tri_frame))
                found.V.insert(found.V.end(), tets[k].begin(), tets[k].end());
            });
          std::sort(found.V.begin(), found.V.end());
          found.V.erase(std::unique(found.V.begin(), found.V.end()),
                        found.V.end());
        },
        [&](const Across &found) {
          if (found.V.empty())
            return;
          for (const unsigned int a : found.triangle)
            across[a].insert(across[a].end(), found.V.begin(), found.V.end());
          for (const unsigned int b : found.V)
            across[b].insert(across[b].end(),
                             found.triangle.begin(),
                             found.triangle.end());
        },
        Across());
      // each vertex's DoF rows are its own: the vertices in parallel
      parallel::apply_to_subranges(
        0u,
        static_cast<unsigned int>(across.size()),
        [&](const unsigned int begin, const unsigned int end) {
          std::vector<types::global_dof_index> columns;
          for (unsigned int a = begin; a < end; ++a)
            {
              auto &vertices = across[a];
              if (vertices.empty())
                continue;
              std::sort(vertices.begin(), vertices.end());
              vertices.erase(std::unique(vertices.begin(), vertices.end()),
                             vertices.end());
              columns.clear();
              for (const unsigned int b : vertices)
                for (const auto dof : surface.vertex_dofs[b])
                  columns.push_back(dof);
              std::sort(columns.begin(), columns.end());
              for (const auto row : surface.vertex_dofs[a])
                merge_columns(rows[row], columns);
            }
        },
        256);
    }


    bool
    BodyContactAssembler::may_gain_energy(const std::vector<Point<3>> &x,
                                          const unsigned int           t,
                                          const unsigned int           k,
                                          const BodyContact           &p,
                                          const double                 margin,
                                          const TriangleFrame &tri_frame) const
    {
      const PairGeometry geometry = pair_geometry(x, t, k);
      const auto &[tet, tri, g]   = geometry;
      // the triangle's outward normal points into the body it can press
      // into: material of positive depth in front of the triangle (or
      // within the margin behind it) can meet it within a step
      const Tensor<1, 3> normal = double(surface.outward[t]) * tri_frame.normal;
      const double       n      = tri_frame.n;
      if (!(n > 0.) || !std::isfinite(n))
        return true;
      for (unsigned int j = 0; j < 4; ++j)
        if (g[j] > 0. && normal * (tet[j] - tri[0]) / n > -margin)
          return true;
      // a pair pressed through, with energy now, keeps its couplings
      return !pair_rejected(shared_vertices(t, k), tet, tri_frame, tri) &&
             method_of(p).energy(tet, tri, g, p.penalty) > 0.;
    }


    bool
    BodyContactAssembler::has_couplings(const Vector<double>  &u,
                                        const SparsityPattern &pattern) const
    {
      if (pairs.empty())
        return true;
      const std::vector<Point<3>> x = surface.positions(u);
      update_candidates(x);
      const auto scope = time_section(timer, "contact: sparsity check");
      const bool known = begin_survivors(x);
      // only pairs the assembly will add (nonzero energy) need couplings;
      // add_couplings() adds whole 3 x 3 vertex blocks, so one entry per
      // vertex pair tells, and only the pairs across the tetrahedron and
      // the triangle can be missing. The triangles in parallel.
      bool all = true;
      struct Has
      {
        bool all = true;
      };
      missing_couplings.assign(surface_triangles.size(), 0);
      per_surface_triangle(
        [&](const unsigned int i, Has &c) {
          bool &has = c.all;
          has       = true;
          for_each_pair_with_energy(
            i,
            x,
            known,
            [&](const unsigned int t,
                const unsigned int k,
                const BodyContact &,
                const PairGeometry &) {
              // the couplings across (add_couplings()), in the
              // tetrahedron's rows: the pattern is symmetric (add_couplings()
              // couples both ways, and a pattern kept within an increment
              // keeps both), so their transposes are there too
              const auto dofs = pair_dofs(t, k);
              for (unsigned int a = 0; a < 4 && has; ++a)
                for (unsigned int b = 4; b < 7; ++b)
                  has = has && pattern.exists(dofs[3 * a], dofs[3 * b]);
            });
          // each triangle's flag written by its worker alone
          missing_couplings[i] = !has;
        },
        [&](const Has &c) { all = all && c.all; },
        Has());
      end_survivors(x);
      have_with_energy = true;
      return all;
    }


    double
    BodyContactAssembler::max_penetration(const Vector<double> &u) const
    {
      double d_max = 0.;
      for (const auto &[v, d] : penetrations(u))
        d_max = std::max(d_max, d);
      return d_max;
    }


    std::vector<std::pair<unsigned int, double>>
    BodyContactAssembler::penetrations(const Vector<double> &u) const
    {
      std::vector<double> per_pair;
      return penetrations(u, per_pair);
    }


    std::vector<double>
    BodyContactAssembler::pair_penetrations(const Vector<double> &u) const
    {
      std::vector<double> per_pair;
      penetrations(u, per_pair);
      return per_pair;
    }


    std::vector<std::pair<unsigned int, double>>
    BodyContactAssembler::penetrations(const Vector<double> &u,
                                       std::vector<double>  &per_pair) const
    {
      per_pair.assign(pairs.size(), 0.);
      if (pairs.empty())
        return {};
      const std::vector<Point<3>> x = surface.positions(u);
      update_candidates(x);
      // each vertex of a pair's surface body: its largest depth (a flag
      // and a value per vertex, read out in the vertices' order)
      std::vector<unsigned char> on_surface(x.size(), 0);
      std::vector<double>        depth_of(x.size(), 0.);
      for (unsigned int t = 0; t < surface.triangles.size(); ++t)
        if (surface_of_a_pair(t))
          for (const unsigned int v : surface.triangles[t])
            on_surface[v] = 1;
      for (unsigned int i = 0; i < surface_triangles.size(); ++i)
        for_each_listed_candidate_of(
          i,
          [&](const unsigned int t,
              const unsigned int k,
              const BodyContact &p) {
            const Point<3>    &x0 = x[tets[k][0]];
            const Tensor<1, 3> a = x[tets[k][1]] - x0, b = x[tets[k][2]] - x0,
                               c  = x[tets[k][3]] - x0;
            const Tensor<1, 3> bc = cross_product_3d(b, c);
            const double       V  = a * bc;
            if (!(std::abs(V) > 0.))
              return;
            for (const unsigned int v : surface.triangles[t])
              {
                // the barycentric coordinates of the vertex in the
                // tetrahedron; inside (to rounding) if none is negative
                const Tensor<1, 3>    r = x[v] - x0;
                std::array<double, 4> lambda;
                lambda[1] = r * bc / V;
                lambda[2] = a * cross_product_3d(r, c) / V;
                lambda[3] = a * cross_product_3d(b, r) / V;
                lambda[0] = 1. - lambda[1] - lambda[2] - lambda[3];
                if (*std::min_element(lambda.begin(), lambda.end()) < -1e-12)
                  continue;
                double g = 0.;
                for (unsigned int j = 0; j < 4; ++j)
                  g += std::max(lambda[j], 0.) * depth[tets[k][j]];
                depth_of[v]      = std::max(depth_of[v], g);
                on_surface[v]    = 1;
                double &pair_max = per_pair[&p - pairs.data()];
                pair_max         = std::max(pair_max, g);
              }
          });
      std::vector<std::pair<unsigned int, double>> result;
      for (unsigned int v = 0; v < x.size(); ++v)
        if (on_surface[v])
          result.emplace_back(v, depth_of[v]);
      return result;
    }


    std::vector<ContactResult>
    BodyContactAssembler::results(const Vector<double>      &u,
                                  std::vector<Tensor<1, 3>> &surface_force,
                                  std::vector<double>       &penetration) const
    {
      std::vector<ContactResult> result(pairs.size());
      if (pairs.empty())
        return result;
      const std::vector<Point<3>> x = surface.positions(u);
      for_each_pair_contact(u,
                            false,
                            [&](const unsigned int t,
                                const unsigned int k,
                                const unsigned int pair,
                                const PairKernel  &d) {
                              ContactResult &r = result[pair];
                              // the triangle's vertices follow the
                              // tetrahedron's among the 21 coordinates
                              for (unsigned int a = 0; a < 3; ++a)
                                for (unsigned int c = 0; c < 3; ++c)
                                  {
                                    const double f =
                                      -d.gradient[12 + 3 * a + c];
                                    r.force[c] += f;
                                    surface_force[surface.triangles[t][a]][c] +=
                                      f;
                                  }
                              const PairGeometry g = pair_geometry(x, t, k);
                              r.area += intersection_area(g.tet, g.tri);
                              r.energy += d.energy;
                            });
      std::vector<double> largest;
      for (const auto &[v, d] : penetrations(u, largest))
        penetration[v] = std::max(penetration[v], d);
      for (unsigned int p = 0; p < pairs.size(); ++p)
        result[p].max_penetration = largest[p];
      return result;
    }


    std::vector<double>
    BodyContactAssembler::energies(const Vector<double> &u) const
    {
      std::vector<double> W(pairs.size(), 0.);
      if (pairs.empty())
        return W;
      const std::vector<Point<3>> x = surface.positions(u);
      update_candidates(x);
      const auto scope = time_section(timer, "contact: energy");
      const bool known = begin_survivors(x);
      // each triangle's pair energies in parallel, added serially in the
      // list's order (the sums are those of a serial loop)
      using Energies = std::vector<std::pair<unsigned int, double>>;
      per_surface_triangle(
        [&](const unsigned int i, Energies &e) {
          e.clear();
          with_energy[i].clear();
          unsigned int j = 0; // the survivor of the call: survivors[i][j]
          for_each_surviving_pair_of(
            i,
            x,
            known,
            [&](const unsigned int,
                const unsigned int,
                const BodyContact  &p,
                const PairGeometry &geometry) {
              const auto &[tet, tri, g] = geometry;
              const double w = method_of(p).energy(tet, tri, g, p.penalty);
              e.emplace_back(&p - pairs.data(), w);
              if (w > 0.)
                with_energy[i].push_back(survivors[i][j]);
              ++j;
            });
        },
        [&](const Energies &e) {
          for (const auto &[p, w] : e)
            W[p] += w;
        },
        Energies());
      end_survivors(x);
      have_with_energy = true;
      return W;
    }
  } // namespace Contact
} // namespace TissueContact
