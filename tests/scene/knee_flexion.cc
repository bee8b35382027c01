// The knee of prm/knee_flexion.prm on the coarse mesh of meshes/knee.geo
// (h 0.06: 4 739 tetrahedra, 1 559 vertices) flexed to 90 degrees in
// 30 increments of 3 degrees: femur fixed, tibia rotated, the patella a free
// rigid body held by its ligament and tendon, the skin-fat layer sliding
// over everything and folding onto itself behind the knee. The log prints
// the angle reached, whether the cut-backs and Newton iterations stay within
// bounds (the counts go to the console: they vary with the rounding), whether
// the largest penetration stays below 10 % of the local element size, and the
// patella's motion: it must travel down and around the condyles (its center
// moves backwards and down, it turns with the tibia). Then, at the final
// state, the contact assembler's reuse of the pairs that passed the
// rejection tests (doc/theory/05-contact.md, sec. 2.1): the residual and
// tangent after an energy at slightly different positions, and again at
// the same positions (from the reused pairs), equal bit for bit those of a
// pass over all candidates right after a new search; so do the energy at
// the nearby positions, and its second evaluation. Last, a tangent on the
// finite element pattern alone, without the contact couplings: the
// assembly refuses it with a message naming the coupling it misses (a
// release build of SparseMatrix::add() would have added the value to
// another entry of the row). And the pattern a Newton iteration within an
// increment builds where the linear solves see only the nonzeros
// (NonlinearProblem::update_sparsity_pattern() with keep_couplings): it
// holds the couplings of the pattern it replaced and those it was missing
// (searched for only near them), the tangent assembled on it has the same
// nonzeros to the bit as on a pattern built anew, and a call without
// keep_couplings makes the next build start anew.

#include "scenes.h"

#include <tissue_contact/base/nonzero_copy.h>
#include <tissue_contact/contact/contact_assembler.h>

#include <sstream>

using namespace dealii;
using namespace TissueContact;
using namespace TissueContactTests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const double      angle = 90.;
  const std::string prm   = project_prm(
    "knee_flexion.prm",
    {{"-setnumber h 0.0125 -setnumber n_2pi 8",
        "-setnumber h 0.06 -setnumber n_2pi 5 -setnumber pat_refine 2"},
       {"Rotation angle  = -150", "Rotation angle  = -90"},
       {"increment = 0.02", "increment = 0.0333333333333"}});
  std::ostringstream log;
  StaticSimulation   sim(Scene::SceneParameters::from_string(prm), log);
  SolveStatistics    statistics;
  if (!SceneTests::solve_or_log(sim, statistics, "the flexion"))
    return 0;
  const Problem     &problem     = sim.problem();
  const auto        &u           = sim.solution();
  const auto        &rigid       = *problem.free_rigid_bodies();
  const Tensor<1, 3> t           = rigid.translation(u, 0);
  const Tensor<1, 3> theta       = rigid.rotation_vector(u, 0);
  const double       penetration = problem.max_relative_penetration(u);

  deallog << "mesh: " << problem.get_scene().triangulation.n_active_cells()
          << " tetrahedra, " << problem.n_dofs() << " unknowns, "
          << problem.contact_assembler()->n_triangles() << " contact triangles"
          << std::endl;
  SceneTests::log_effort(statistics,
                         "flexed to " + std::to_string(int(angle)) + " degrees",
                         15,
                         2000);
  SceneTests::log_penetration(penetration);
  deallog << "patella: center moved by " << std::fixed << std::setprecision(1)
          << 1000. * t << " mm (|t| = " << 1000. * t.norm()
          << " mm), turned by " << theta.norm() * 180. / M_PI
          << " degrees about " << std::setprecision(2) << theta / theta.norm()
          << std::endl;

  const auto          &contact = *problem.contact_assembler();
  const Vector<double> x       = problem.displacement(u);
  const auto           n       = x.size();
  // the finite element pattern and the couplings across pairs, as the
  // program builds it: a pair also adds within its tetrahedron and triangle
  PatternRows rows = rows_of(problem.discretization().sparsity_pattern);
  AssertThrow(rows.size() == n, ExcInternalError());
  contact.add_couplings(x, 0.01, rows);
  SparsityPattern pattern;
  to_pattern(rows, pattern);
  // far away (every coordinate moved by 1 m: a new search), then back: a pass
  // over all candidates
  Vector<double> far(x);
  far.add(1.);
  contact.energy(far);
  SparseMatrix<double> K_ref(pattern), K(pattern);
  Vector<double>       R_ref(n), R(n);
  contact.assemble(x, R_ref, &K_ref);
  // positions moved by at most 0.35 mm at random, well within half the
  // candidate list's margin (no new search), whose energy finds other
  // pairs past the rejection tests; its second evaluation reuses them
  Vector<double> near(x);
  for (auto &v : near)
    v += 2e-4 * random_value(-1., 1.);
  const double E_near = contact.energy(near);
  bool         equal  = contact.energy(near) == E_near;
  // the energy nearby after a new search (20 mm away and back: the tree is
  // refitted, not rebuilt, so the candidates keep their order)
  Vector<double> shifted(x);
  shifted.add(0.0115);
  contact.energy(shifted);
  equal = equal && contact.energy(near) == E_near;
  for (unsigned int pass = 0; pass < 2; ++pass)
    {
      R = 0.;
      K = 0.;
      contact.assemble(x, R, &K);
      R -= R_ref;
      K.add(-1., K_ref);
      equal = equal && R.linfty_norm() == 0. && K.frobenius_norm() == 0.;
    }
  deallog << "final state: the contact energy nearby twice, then the "
             "residual and tangent twice, against passes after a new "
             "search: equal bit for bit "
          << equal << std::endl;

  SparseMatrix<double> K_fe(problem.discretization().sparsity_pattern);
  std::string          message;
  try
    {
      contact.assemble(x, R, &K_fe);
    }
  catch (const ExceptionBase &e)
    {
      // deal.II wraps the message's lines: one space for each gap
      std::istringstream words(e.what());
      for (std::string word; words >> word;)
        message += word + " ";
    }
  deallog << "a tangent on the finite element pattern alone: refused, the "
             "missing coupling named: "
          << (message.find("A contact pair's coupling (row ") !=
                std::string::npos &&
              message.find(") is not in the matrix's pattern. ") !=
                std::string::npos)
          << std::endl;

  // the couplings at the end, beyond it and halfway (the displacement
  // times 1.2 and 0.5: configurations, not equilibria), each pattern copied
  // as it is built
  Problem       &p = sim.problem();
  Vector<double> beyond(u), half(u);
  beyond *= 1.2;
  half *= 0.5;
  const auto update = [&](const Vector<double> &v, const bool keep) {
    const bool built = p.update_sparsity_pattern(v, keep);
    auto       copy  = std::make_unique<SparsityPattern>();
    copy->copy_from(p.sparsity_pattern());
    return std::make_pair(built, std::move(copy));
  };
  // a holds every entry of b
  const auto holds = [](const SparsityPattern &a, const SparsityPattern &b) {
    for (auto e = b.begin(); e != b.end(); ++e)
      if (!a.exists(e->row(), e->column()))
        return false;
    return true;
  };
  const auto same = [&](const SparsityPattern &a, const SparsityPattern &b) {
    return a.n_nonzero_elements() == b.n_nonzero_elements() && holds(a, b);
  };
  // the residual and the tangent's nonzeros at the end state on the
  // problem's current pattern
  const auto tangent = [&](Vector<double>       &R,
                           SparsityPattern      &nonzero_pattern,
                           SparseMatrix<double> &nonzeros) {
    SparseMatrix<double> K(p.sparsity_pattern());
    R.reinit(p.n_dofs());
    p.assemble(u, 1., R, &K);
    copy_nonzeros(K, nonzero_pattern, nonzeros);
  };
  const auto [built_over, over] = update(beyond, false);
  const auto [built_end, end]   = update(u, false);
  Vector<double>       R_end, R_kept;
  SparsityPattern      nz_end, nz_kept;
  SparseMatrix<double> K_end, K_kept;
  tangent(R_end, nz_end, K_end);
  const auto [built_kept, kept] = update(beyond, true);
  tangent(R_kept, nz_kept, K_kept);
  // the kept build searched only near the couplings found missing: it
  // holds every coupling beyond (a second call builds nothing), and none
  // that neither the end's pattern nor one built anew beyond holds
  const bool built_kept_again = update(beyond, true).first;
  bool       from_either      = true;
  for (auto e = kept->begin(); from_either && e != kept->end(); ++e)
    from_either =
      end->exists(e->row(), e->column()) || over->exists(e->row(), e->column());
  // a search from every triangle would have joined both
  std::size_t n_union = end->n_nonzero_elements();
  for (auto e = over->begin(); e != over->end(); ++e)
    n_union += !end->exists(e->row(), e->column());
  bool equal_tangents = same(nz_end, nz_kept) && R_kept == R_end;
  for (auto e = K_end.begin(); equal_tangents && e != K_end.end(); ++e)
    equal_tangents = K_kept.el(e->row(), e->column()) == e->value();
  // no coupling missing at the end state: no build, but the next starts
  // anew; a pattern built anew halfway by another route to compare with
  const bool built_again               = update(u, false).first;
  const auto [built_half, half_kept]   = update(half, true);
  const auto [built_over2, over2]      = update(beyond, false);
  const auto [built_fresh, half_fresh] = update(half, false);
  deallog << "patterns built beyond the end state, at it, beyond it keeping "
             "the couplings: "
          << built_over << built_end << built_kept
          << "; it holds the end's, more entries than it: "
          << (holds(*kept, *end) &&
              kept->n_nonzero_elements() > end->n_nonzero_elements())
          << ", every coupling beyond (no second build: " << !built_kept_again
          << "), none that neither the end's nor the one built anew beyond "
             "holds: "
          << from_either << ", fewer than both together: "
          << (kept->n_nonzero_elements() < n_union)
          << "; the residual and the tangent's nonzeros at the end state on "
             "it and on the end's pattern equal bit for bit: "
          << equal_tangents << std::endl;
  deallog << "after a call without keeping (no build: " << !built_again
          << "), a build halfway asked to keep the couplings starts anew: "
          << (built_half && built_over2 && built_fresh &&
              same(*half_kept, *half_fresh) && same(*over2, *over))
          << std::endl;
}
