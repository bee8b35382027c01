#include <tissue_contact/solvers/cholesky_factorization.h>

#include <cholmod.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace TissueContact
{
  namespace Solvers
  {
    struct CholeskyFactorization::Implementation
    {
      cholmod_common common;
      /** the upper triangle of the last tangent, stored column by column
       * as its lower triangle (K symmetric: column i of the lower triangle
       * is row i of the upper one) */
      cholmod_sparse *A = nullptr;
      cholmod_factor *L = nullptr;
      /** whether L holds the factor of the last tangent */
      bool factorized = false;
      /** whether the last tangent passed the symmetry check */
      bool         symmetric  = false;
      unsigned int n_analyses = 0;

      Implementation()
      {
        cholmod_l_start(&common);
        // failures are reported by factorize()'s result, not printed
        common.print = 0;
        // the simplicial factorization where the flops per entry of the
        // factor are below 150, the supernodal one (dense blocks in BLAS)
        // above: CHOLMOD's default switch, 40, made a 375-unknown tangent's
        // factorization four times slower than the simplicial one
        // (doc/theory/04-solver.md sec. 4.5.3)
        common.supernodal_switch = 150.;
      }

      ~Implementation()
      {
        cholmod_l_free_factor(&L, &common);
        cholmod_l_free_sparse(&A, &common);
        cholmod_l_finish(&common);
      }
    };


    bool
    is_symmetric(const SparseMatrix<double> &K)
    {
      Vector<double> v(K.m()), Kv(K.m()), KTv(K.m());
      std::uint64_t  state = 0x9e3779b97f4a7c15ull;
      for (double &vi : v)
        {
          state = state * 6364136223846793005ull + 1442695040888963407ull;
          vi    = static_cast<double>(state >> 11) * 0x1.0p-52 - 1.;
        }
      K.vmult(Kv, v);
      K.Tvmult(KTv, v);
      const double scale = Kv.l2_norm() + KTv.l2_norm();
      Kv -= KTv;
      return Kv.l2_norm() <= 1e-12 * scale;
    }


    CholeskyFactorization::CholeskyFactorization()
      : implementation(std::make_unique<Implementation>())
    {}


    CholeskyFactorization::~CholeskyFactorization() = default;


    bool
    CholeskyFactorization::factorize(const SparseMatrix<double> &K)
    {
      Implementation &impl = *implementation;
      cholmod_common &c    = impl.common;
      impl.factorized      = false;
      AssertThrow(K.m() == K.n(), ExcNotQuadratic());
      impl.symmetric = is_symmetric(K);
      if (!impl.symmetric)
        return false;

      // the upper triangle: deal.II stores a square matrix's diagonal
      // first and the other columns in order, so the columns >= i of row i
      // are its first entry and its tail
      const SparsityPattern        &sp = K.get_sparsity_pattern();
      const std::size_t             n  = K.m();
      std::vector<SuiteSparse_long> p(n + 1, 0);
      std::vector<unsigned int>     tail(n);
      for (std::size_t i = 0; i < n; ++i)
        {
          const unsigned int length = sp.row_length(i);
          AssertThrow(length > 0 && sp.column_number(i, 0) == i,
                      ExcMessage("Cholesky: row " + std::to_string(i) +
                                 " of the tangent has no diagonal entry"));
          unsigned int k = length;
          while (k > 1 && sp.column_number(i, k - 1) > i)
            --k;
          tail[i]  = k;
          p[i + 1] = p[i] + 1 + (length - k);
        }
      std::vector<SuiteSparse_long> rows(p[n]);
      for (std::size_t i = 0; i < n; ++i)
        {
          SuiteSparse_long k = p[i];
          rows[k++]          = i;
          for (unsigned int e = tail[i]; e < sp.row_length(i); ++e)
            rows[k++] = sp.column_number(i, e);
        }

      // a new analysis where the pattern is not the last one's
      const bool same_pattern =
        impl.A != nullptr && impl.L != nullptr && impl.A->nrow == n &&
        impl.A->nzmax == rows.size() &&
        std::equal(p.begin(),
                   p.end(),
                   static_cast<SuiteSparse_long *>(impl.A->p)) &&
        std::equal(rows.begin(),
                   rows.end(),
                   static_cast<SuiteSparse_long *>(impl.A->i));
      if (!same_pattern)
        {
          cholmod_l_free_factor(&impl.L, &c);
          cholmod_l_free_sparse(&impl.A, &c);
          // stype -1: the lower triangle of a symmetric matrix
          impl.A = cholmod_l_allocate_sparse(n,
                                             n,
                                             rows.size(),
                                             /*sorted*/ 1,
                                             /*packed*/ 1,
                                             -1,
                                             CHOLMOD_REAL,
                                             &c);
          AssertThrow(impl.A != nullptr,
                      ExcMessage("Cholesky: out of memory for the tangent's "
                                 "copy; use Direct solver = UMFPACK or Type = "
                                 "GMRES+AMG"));
          std::copy(p.begin(),
                    p.end(),
                    static_cast<SuiteSparse_long *>(impl.A->p));
          std::copy(rows.begin(),
                    rows.end(),
                    static_cast<SuiteSparse_long *>(impl.A->i));
          impl.L = cholmod_l_analyze(impl.A, &c);
          AssertThrow(impl.L != nullptr && c.status == CHOLMOD_OK,
                      ExcMessage("Cholesky: the symbolic analysis failed ("
                                 "CHOLMOD status " +
                                 std::to_string(c.status) +
                                 "); use Direct solver = UMFPACK"));
          ++impl.n_analyses;
        }
      double *x = static_cast<double *>(impl.A->x);
      for (std::size_t i = 0; i < n; ++i)
        {
          const double *v = &K(i, i);
          *x++            = v[0];
          x               = std::copy(v + tail[i], v + sp.row_length(i), x);
        }

      cholmod_l_factorize(impl.A, impl.L, &c);
      AssertThrow(c.status != CHOLMOD_OUT_OF_MEMORY,
                  ExcMessage("Cholesky: out of memory for the factor; use "
                             "Type = GMRES+AMG"));
      impl.factorized = c.status == CHOLMOD_OK && impl.L->minor == n;
      // the supernodal factorization is L L^T and stops at the first pivot
      // that is not positive; the simplicial one is L D L^T and stops only
      // at a zero pivot, so an indefinite K passes with negative entries in
      // D, which holds K's inertia (Sylvester): refused here
      if (impl.factorized && !impl.L->is_super && !impl.L->is_ll)
        {
          const auto *const Lp =
            static_cast<const SuiteSparse_long *>(impl.L->p);
          const auto *const Lx = static_cast<const double *>(impl.L->x);
          for (std::size_t j = 0; j < n && impl.factorized; ++j)
            impl.factorized = Lx[Lp[j]] > 0.;
        }
      return impl.factorized;
    }


    void
    CholeskyFactorization::solve(Vector<double>       &x,
                                 const Vector<double> &b) const
    {
      const Implementation &impl = *implementation;
      Assert(impl.factorized, ExcMessage("no factor to solve with"));
      cholmod_common &c = const_cast<cholmod_common &>(impl.common);
      cholmod_dense   rhs;
      rhs.nrow                = b.size();
      rhs.ncol                = 1;
      rhs.nzmax               = b.size();
      rhs.d                   = b.size();
      rhs.x                   = const_cast<double *>(b.begin());
      rhs.z                   = nullptr;
      rhs.xtype               = CHOLMOD_REAL;
      rhs.dtype               = CHOLMOD_DOUBLE;
      cholmod_dense *solution = cholmod_l_solve(CHOLMOD_A, impl.L, &rhs, &c);
      AssertThrow(solution != nullptr,
                  ExcMessage("Cholesky: out of memory for the solve"));
      const double *s = static_cast<const double *>(solution->x);
      std::copy(s, s + b.size(), x.begin());
      cholmod_l_free_dense(&solution, &c);
    }


    bool
    CholeskyFactorization::was_symmetric() const
    {
      return implementation->symmetric;
    }


    unsigned int
    CholeskyFactorization::n_analyses() const
    {
      return implementation->n_analyses;
    }
  } // namespace Solvers
} // namespace TissueContact
