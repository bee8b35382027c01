#pragma once

#include <tissue_contact/contact/bounding_volume_tree.h>
#include <tissue_contact/contact/contact_interaction.h>
#include <tissue_contact/contact/contact_parameters.h>
#include <tissue_contact/contact/contact_surface.h>
#include <tissue_contact/contact/pair_rejection.h>
#include <tissue_contact/contact/penalty_kernel.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace TissueContact
{
  namespace Contact
  {
    /**
     * Contact between bodies, and of a body with itself, by material depth
     * (doc/theory/05-contact.md, secs. 1-5 and 7): for every declared pair,
     * the contact triangles of the surface body against the tetrahedra of
     * the volume body, found by a bounding-volume tree over the tetrahedra
     * (refitted, rebuilt after large motion); each intersecting
     * (triangle, tetrahedron) pair adds the penalty
     * @f$\frac{\varepsilon_p}{2}\int g_h^2\,da@f$ with its exact gradient
     * and Hessian (penalty_kernel()), or the point-collocation baseline
     * (collocation_kernel()), chosen once per pair. Pairs are evaluated in
     * parallel and summed in a fixed order (reproducible).
     *
     * The candidate pairs (boxes overlapping) are kept in a list found with
     * a margin @f$m@f$ at each vertex's reference position and shared by
     * every call (residual and tangent, the sparsity check, the line
     * search's energies, the penetrations): boxes that overlap at positions
     * within @f$m/2@f$ of the references overlapped, enlarged by @f$m@f$, at
     * the references, so the list holds every pair a search would find (a
     * Verlet list). A vertex that moves farther gets a new reference, and
     * only the pairs it belongs to are searched again. The extra pairs do
     * not intersect and add nothing.
     */
    class BodyContactAssembler : public ContactInteraction
    {
    public:
      /** @p triangulation: the mesh of @p surface (its cells give the
       * tetrahedra and the material depth). */
      BodyContactAssembler(
        const ContactSurface               &surface,
        const Triangulation<3>             &triangulation,
        const std::set<types::boundary_id> &contact_surfaces,
        const std::vector<BodyContact>     &pairs,
        const std::map<types::material_id, types::material_id> &body_of = {});

      void
      assemble(const Vector<double> &u,
               Vector<double>       &R,
               SparseMatrix<double> *K) const override;

      /** One energy per pair, in the declared order. */
      std::vector<double>
      energies(const Vector<double> &u) const override;

      /** The DoF couplings of every (triangle, tetrahedron) candidate at
       * @p u whose boxes overlap after the triangle's box is enlarged by
       * @p margin and that may gain energy there (may_gain_energy()). With
       * @p where_missing, only the candidates of the triangles that the
       * last has_couplings() found with a coupling missing, and of the
       * triangles that share a vertex with one of them: the other
       * triangles' pairs with energy are coupled in @p rows already
       * (doc/theory/05-contact.md, sec. 7). */
      void
      add_couplings(const Vector<double> &u,
                    const double          margin,
                    PatternRows          &rows,
                    const bool            where_missing = false) const override;

      /** Per declared pair: the force on its surface body (the triangle
       * vertices' share of @f$-\partial W/\partial x@f$), the area of its
       * triangles inside the volume body (the intersection polygons of the
       * pairs with energy), its largest penetration (pair_penetrations())
       * and its energy. */
      std::vector<ContactResult>
      results(const Vector<double>      &u,
              std::vector<Tensor<1, 3>> &surface_force,
              std::vector<double>       &penetration) const override;

      /** Whether @p pattern holds the couplings of every pair with nonzero
       * energy at @p u; which triangles lack some is kept for
       * add_couplings(). */
      bool
      has_couplings(const Vector<double>  &u,
                    const SparsityPattern &pattern) const override;

      /** How often the tree was rebuilt (a vertex moved farther than the
       * mean tetrahedron size since the last build). */
      unsigned int
      n_tree_rebuilds() const
      {
        return n_rebuilds;
      }

      /** Material depth at every vertex. */
      const std::vector<double> &
      vertex_depth() const
      {
        return depth;
      }

      /** Largest material depth reached by a vertex of a contact triangle
       * inside a tetrahedron of a paired body (the penetration). */
      double
      max_penetration(const Vector<double> &u) const;

      /** For every vertex of a contact triangle of a paired surface body:
       * (its vertex index, the material depth it reaches inside a paired
       * body, zero if none). With the area-integrated penalty the contact
       * pressure at a surface point is @f$\varepsilon_p@f$ times this depth
       * (per direction of a pair). */
      std::vector<std::pair<unsigned int, double>>
      penetrations(const Vector<double> &u) const;

      /** The largest penetration of each declared pair (in the order of
       * the pairs), as penetrations() measures it. */
      std::vector<double>
      pair_penetrations(const Vector<double> &u) const;

    private:
      /** penetrations(), and the largest of each pair in @p per_pair. */
      std::vector<std::pair<unsigned int, double>>
      penetrations(const Vector<double> &u,
                   std::vector<double>  &per_pair) const;

      /** Area integration or point collocation: the energy and the kernel
       * of one pair, chosen once when the pair is declared. */
      struct Method
      {
        double (*energy)(const std::array<Point<3>, 4> &,
                         const std::array<Point<3>, 3> &,
                         const std::array<double, 4> &,
                         const double);
        bool (*kernel)(const std::array<Point<3>, 4> &,
                       const std::array<Point<3>, 3> &,
                       const std::array<double, 4> &,
                       const double,
                       const bool,
                       PairKernel &);
      };

      const ContactSurface                    &surface;
      std::vector<BodyContact>                 pairs;
      std::vector<Method>                      methods; // per pair
      std::vector<double>                      depth;   // per vertex
      std::vector<std::array<unsigned int, 4>> tets; // of depth > 0 somewhere
      /** The bodies of the pairs numbered 0, 1, ...: the number of each
       * tetrahedron's and each triangle's body (n_pair_bodies for a
       * triangle of a body in no pair), and the pairs of each
       * (surface body, volume body) in pairs_of[n_pair_bodies * s + v], in
       * the declared order (the broad phase's lookup). */
      unsigned int                                n_pair_bodies = 0;
      std::vector<unsigned int>                   tet_body;
      std::vector<unsigned int>                   triangle_body;
      std::vector<std::vector<unsigned int>>      pairs_of;
      mutable std::unique_ptr<BoundingVolumeTree> tree; // over tets
      mutable unsigned int                        n_rebuilds = 0;
      mutable std::vector<Point<3>> x_at_build; // positions at the build
      double rebuild_distance = 0.;             // mean tetrahedron box diagonal

      /** The method of pair @p p (an element of pairs). */
      const Method &
      method_of(const BodyContact &p) const
      {
        return methods[&p - pairs.data()];
      }

      /** Refit the tree to the positions @p x of the vertices. */
      void
      refit(const std::vector<Point<3>> &x) const;

      /** A (triangle, tetrahedron) pair whose boxes overlap, and the index
       * of its body pair in pairs. */
      /** For each vertex of a triangle, its index among the vertices of a
       * tetrahedron, 4 if it is none of them. */
      using SharedVertices = std::array<unsigned char, 3>;
      /** The vertices triangle t shares with tetrahedron k. */
      SharedVertices
      shared_vertices(const unsigned int t, const unsigned int k) const;
      struct Candidate
      {
        unsigned int   t, k, pair;
        SharedVertices shared; // shared_vertices(t, k)
      };
      /** The candidate list: the candidates of surface_triangles[i] are
       * candidates[offsets[i]] .. candidates[offsets[i + 1] - 1], sorted
       * by tetrahedron and pair (the order of the sums). */
      mutable std::vector<Candidate>    candidates;
      mutable std::vector<unsigned int> offsets;
      /** The list before the last update (read while the new one is
       * made), kept with its memory for the next update to write into. */
      mutable std::vector<Candidate>    previous_candidates;
      mutable std::vector<unsigned int> previous_offsets;
      /** Each vertex's position when the pairs it belongs to were last
       * searched for: the list holds every pair whose boxes at these
       * positions overlap once the triangle's is enlarged by the margin. */
      mutable std::vector<Point<3>> x_reference;
      mutable bool                  have_candidates = false;
      /** The candidates that passed pair_rejected() in the last evaluation
       * that tested them all: survivors[i] indexes those of
       * surface_triangles[i] in the list, in the list's order, at the
       * positions x_at_survivors. The residual and tangent and the sparsity
       * check that follow a line search's energy at the same positions visit
       * only these (doc/theory/05-contact.md, sec. 2.1). */
      mutable std::vector<std::vector<unsigned int>> survivors;
      mutable std::vector<Point<3>>                  x_at_survivors;
      mutable bool                                   have_survivors = false;
      /** Each tetrahedron's box and barycentric frame at x_at_survivors,
       * made by begin_survivors() for the pass that tests all candidates
       * (pair_rejected()). */
      mutable std::vector<TetrahedronFrame> frames;
      /** Of the survivors of surface_triangles[i], those with energy at
       * x_at_survivors (indices into the list), recorded by every pass over
       * the survivors: the pairs the assembly adds and the sparsity check
       * must find coupled. A pass that follows at the same positions (the
       * residual and tangent and the sparsity check after the line
       * search's accepted energy) visits only these, without computing
       * their energies again (doc/theory/05-contact.md, sec. 2.1). */
      mutable std::vector<std::vector<unsigned int>> with_energy;
      mutable bool                                   have_with_energy = false;
      /** Whether surface_triangles[i] had a pair with energy whose
       * couplings the pattern lacked, as the last has_couplings() found. */
      mutable std::vector<unsigned char> missing_couplings;
      /** The triangles of the surface bodies of the pairs. */
      std::vector<unsigned int> surface_triangles;
      /** The list's margin m: a tenth of the mean tetrahedron box
       * diagonal. */
      double candidate_margin = 0.;

      /** Make the candidate list valid for the positions @p x: the
       * vertices that moved more than half the margin from their reference
       * positions get new ones, and the pairs of their triangles and
       * tetrahedra are searched for again (all pairs, if more than half
       * the tetrahedra moved). */
      void
      update_candidates(const std::vector<Point<3>> &x) const;

      /** The bounding box of tetrahedron k at the positions @p x. */
      BoundingBox<3>
      tet_box(const std::vector<Point<3>> &x, const unsigned int k) const;

      /** WorkStream over the surface triangles: @p worker(i, copy) for
       * surface_triangles[i] in parallel, @p copier(copy) serially in the
       * triangles' order (sums are those of a serial loop); @p sample is
       * the initial copy data. Chunks of 32 triangles, four per thread in
       * flight: most triangles have few candidates, and with chunks of 8
       * and one per thread in flight the coarse knee's residual + tangent
       * took 14-25 % longer on two threads than now, its energies 11-15 %
       * (doc/theory/05-contact.md, sec. 7). */
      template <typename Worker, typename Copier, typename Copy>
      void
      per_surface_triangle(const Worker &worker,
                           const Copier &copier,
                           const Copy   &sample) const
      {
        struct Scratch
        {};
        WorkStream::run(
          surface_triangles.cbegin(),
          surface_triangles.cend(),
          [&](const std::vector<unsigned int>::const_iterator &it,
              Scratch &,
              Copy &copy) {
            worker(static_cast<unsigned int>(it - surface_triangles.cbegin()),
                   copy);
          },
          copier,
          Scratch(),
          sample,
          4 * MultithreadInfo::n_threads(),
          32);
      }

      /** Call @p f(t, k, pair, geometry) for candidates[c] at the
       * positions @p x. */
      template <typename F>
      void
      visit(const unsigned int           c,
            const std::vector<Point<3>> &x,
            const F                     &f) const;

      /** Call @p f(t, k, pair, geometry) for every candidate of
       * surface_triangles[i] in the list that pair_rejected() does not reject
       * at the positions @p x, in the list's order: only the recorded
       * survivors if @p known (they were found at these positions), else
       * all candidates, recording the survivors. For a pass over all
       * triangles at the positions of the last update_candidates(), begun
       * with begin_survivors() and ended with end_survivors(). */
      template <typename F>
      void
      for_each_surviving_pair_of(const unsigned int           i,
                                 const std::vector<Point<3>> &x,
                                 const bool                   known,
                                 const F                     &f) const;

      /** Whether the survivors are those of the positions @p x; if not,
       * they are invalidated, to be recorded anew by the pass that
       * follows (the return value false tells it to record). */
      bool
      begin_survivors(const std::vector<Point<3>> &x) const;

      /** Call @p f(t, k, pair, geometry) for every survivor of
       * surface_triangles[i] at the positions @p x (@p known as for
       * for_each_surviving_pair_of()) whose energy is positive: those in
       * with_energy if they are known at these positions, else each
       * survivor's energy decides and with_energy[i] is recorded anew (the
       * caller sets have_with_energy after the pass). */
      template <typename F>
      void
      for_each_pair_with_energy(const unsigned int           i,
                                const std::vector<Point<3>> &x,
                                const bool                   known,
                                const F                     &f) const;

      /** The survivors recorded by a pass at the positions @p x are
       * valid. */
      void
      end_survivors(const std::vector<Point<3>> &x) const;

      /** Call @p f(t, k, pair) for every candidate of surface_triangles[i]
       * in the list. */
      template <typename F>
      void
      for_each_listed_candidate_of(const unsigned int i, const F &f) const
      {
        for (unsigned int c = offsets[i]; c < offsets[i + 1]; ++c)
          f(candidates[c].t, candidates[c].k, pairs[candidates[c].pair]);
      }

      /** Call @p f(t, k, pair) for every candidate pair of triangle @p t
       * and a tetrahedron k of a body pair (boxes overlapping after
       * enlarging the triangle's by @p margin), triangles that are faces of
       * the tetrahedron excluded. */
      template <typename F>
      void
      for_each_candidate_of(const unsigned int           t,
                            const std::vector<Point<3>> &x,
                            const double                 margin,
                            const F                     &f) const;

      /** for_each_candidate_of() among the tetrahedra of the tree @p in,
       * whose object i is tetrahedron tet_of[i] (or i, if @p tet_of is
       * empty). */
      template <typename F>
      void
      for_each_candidate_in(const BoundingVolumeTree        &in,
                            const std::vector<unsigned int> &tet_of,
                            const unsigned int               t,
                            const std::vector<Point<3>>     &x,
                            const double                     margin,
                            const F                         &f) const;
      /** Whether triangle @p t belongs to the surface body of a pair. */
      bool
      surface_of_a_pair(const unsigned int t) const;
      /** The positions and depths of triangle t and tetrahedron k. */
      struct PairGeometry
      {
        std::array<Point<3>, 4> tet;
        std::array<Point<3>, 3> tri;
        std::array<double, 4>   g;
      };
      PairGeometry
      pair_geometry(const std::vector<Point<3>> &x,
                    const unsigned int           t,
                    const unsigned int           k) const;

      /** Each tetrahedron's rejection frame at the positions @p x, into
       * frames, in parallel. */
      void
      make_frames(const std::vector<Point<3>> &x) const;

      /** Whether the candidate pair (triangle t, tetrahedron k) at the
       * positions @p x is coupled in the matrix pattern: it has energy now,
       * or a vertex of the tetrahedron with positive depth lies in front of
       * the triangle (on its outward side) or less than @p margin behind
       * its plane (doc/theory/05-contact.md, sec. 7). The tetrahedra under
       * a surface triangle's neighbours, whose positive depth lies behind
       * it, are left out: they would widen the pattern of every contact
       * surface by its neighbourhood without ever touching it. Whatever
       * this leaves out and later gains energy is caught by
       * has_couplings(), which has the pattern rebuilt. @p tri_frame is the
       * triangle's at @p x. */
      bool
      may_gain_energy(const std::vector<Point<3>> &x,
                      const unsigned int           t,
                      const unsigned int           k,
                      const BodyContact           &p,
                      const double                 margin,
                      const TriangleFrame         &tri_frame) const;

      std::array<types::global_dof_index, 21>
      pair_dofs(const unsigned int t, const unsigned int k) const;

      /** A pair with energy: triangle t, tetrahedron k, the index of its
       * body pair in pairs, and its energy and derivatives. */
      struct PairResult
      {
        unsigned int t = 0, k = 0, pair = 0;
        PairKernel   d;
      };
      /** The pairs with energy of surface_triangles[i], in the list's
       * order, from evaluate_pairs() until they are added. */
      mutable std::vector<std::vector<PairResult>> pair_results;

      /** A pair's 21 DoFs (pair_dofs()): the distinct ones, ascending,
       * the place of each of the 21 among them, and the first of the 21 at
       * each place (a vertex shared by the triangle and the tetrahedron
       * appears twice among the 21; with none shared, @p n = 21 and each
       * place has one of them). */
      struct DistinctDofs
      {
        std::array<types::global_dof_index, 21> dofs;
        std::array<unsigned char, 21>           slot, first;
        unsigned int                            n = 0;
      };

      /** The (pair, row) incidences of the pairs' @p distinct DoFs
       * counted per row and summed: entry r is the number of incidences in
       * the rows before r (@p n_rows + 1 entries). */
      static std::vector<std::size_t>
      row_incidences(const std::vector<DistinctDofs> &distinct,
                     const types::global_dof_index    n_rows);

      /** Boundaries 0 = b_0 <= ... <= b_n of @p n_parts ranges of the rows
       * of @p incidences (row_incidences()) with about equal shares of
       * them: part p adds the rows b_p ... b_{p+1} - 1. */
      static std::vector<types::global_dof_index>
      insertion_row_ranges(const std::vector<std::size_t> &incidences,
                           const unsigned int              n_parts);

      /** The distinct DoFs of pair @p r. */
      DistinctDofs
      distinct_dofs(const PairResult &r) const;

      /** Add the gradients and (if @p K) Hessians of the pairs @p list to
       * the rows lo .. hi - 1 of @p R and @p K, row by row: each row's
       * entries found once, then every pair's additions to it in the
       * list's order; @p incidences: row_incidences(). */
      void
      add_rows(const std::vector<const PairResult *> &list,
               const std::vector<DistinctDofs>       &distinct,
               const std::vector<std::size_t>        &incidences,
               const types::global_dof_index          lo,
               const types::global_dof_index          hi,
               Vector<double>                        &R,
               SparseMatrix<double>                  *K) const;

      /** Fill pair_results at @p u: the triangles in parallel. */
      void
      evaluate_pairs(const Vector<double> &u, const bool with_hessian) const;

      /** Call @p f(t, k, pair, derivatives) for every intersecting pair of
       * a contact triangle t and a tetrahedron k with nonzero energy, pair
       * the index of its body pair in pairs, in the list's order. */
      template <typename F>
      void
      for_each_pair_contact(const Vector<double> &u,
                            const bool            with_hessian,
                            const F              &f) const;
    };
  } // namespace Contact
} // namespace TissueContact
