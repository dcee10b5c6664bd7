// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TWO_DOMAIN_CHOLESKY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TWO_DOMAIN_CHOLESKY_H

// Sparse Cholesky factorisation on two threads by one level of nested dissection: the
// unknowns are split into two domains D1, D2 that do not touch and a separator S,
//
//       [ A11   0   A1s ]
//   A = [  0   A22  A2s ]
//       [ As1  As2  Ass ],
//
// (the split: two_domain_ordering.h), and the two principal submatrices M_i = [Aii Ais; Asi Ass]
// are factored concurrently by CHOLMOD with S ordered last. The trailing block of each factor is the Cholesky factor of
// S_i = Ass - Asi Aii^-1 Ais, so the Schur complement of the whole matrix is
// S = S_1 + S_2 - Ass (dense, |S| x |S|, a few thousand at most on a mesh), factored with
// LAPACK. Solves run the two triangular solves of each M_i on its own thread.
//
// solve(b, held) and trailing_schur(t) treat the separator's last unknowns apart: the
// integer-grid map orders its small unknowns there (Integer_grid_map/map_factor.h).
//
// Why: CHOLMOD 3's numeric factorisation of a mesh Laplacian is sequential (its supernodes are
// too small for threaded BLAS to help), and the machines this package targets have 2 cores.

#include <CGAL/Surface_mesh_direction_fields/internal/cholmod_errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_domain_ordering.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_threads.h>

#include <cholmod.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <memory>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

// Dense BLAS/LAPACK kernels (the libraries CHOLMOD links). Declared under local names bound to
// the Fortran symbols so that they cannot clash with other declarations of dsyrk_ and friends.
#if defined(__GNUC__) && defined(__ELF__) && !defined(CGAL_SMDF_NO_DIRECT_BLAS)
#define CGAL_SMDF_DIRECT_BLAS 1
extern "C" {
void cgal_smdf_dsyrk(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha,
                     const double* a, const int* lda, const double* beta, double* c, const int* ldc) __asm__("dsyrk_");
void cgal_smdf_dpotrf(const char* uplo, const int* n, double* a, const int* lda, int* info) __asm__("dpotrf_");
void cgal_smdf_dlauum(const char* uplo, const int* n, double* a, const int* lda, int* info) __asm__("dlauum_");
void cgal_smdf_dtrmv(const char* uplo, const char* trans, const char* diag, const int* n, const double* a,
                     const int* lda, double* x, const int* incx) __asm__("dtrmv_");
void cgal_smdf_dtrsv(const char* uplo, const char* trans, const char* diag, const int* n, const double* a,
                     const int* lda, double* x, const int* incx) __asm__("dtrsv_");
}
#endif

#if defined(__unix__) || defined(__APPLE__)
#include <dlfcn.h>
#define CGAL_SMDF_HAS_DLSYM 1
#endif

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// CHOLMOD 3 (SuiteSparse 5) runs the assembly loops of large supernodes in OpenMP regions of a
// hard-coded 4 threads; next to our own factorisation threads that oversubscribed the 2 cores of
// the target machine (433k faces: 1.2 s instead of 0.25 s per half). While alive, this guard
// limits the OpenMP regions started by the calling thread to one thread, through the per-thread
// ICVs dyn-var and nthreads-var (with dynamic adjustment on, GCC's libgomp caps a region at
// nthreads-var threads; other OpenMP runtimes may ignore it, which only costs speed), and
// restores them on exit. The OpenMP runtime is looked up at run time:
// it is present only when CHOLMOD was built with OpenMP, and then nothing needs to be linked.
class Single_thread_openmp_scope
{
public:
  Single_thread_openmp_scope()
  {
    const Api& api = get_api();
    if(!api.ok) return;
    active_ = true;
    dynamic_ = api.get_dynamic();
    threads_ = api.get_max_threads();
    api.set_dynamic(1);
    api.set_num_threads(1);
  }
  ~Single_thread_openmp_scope()
  {
    if(!active_) return;
    const Api& api = get_api();
    api.set_dynamic(dynamic_);
    api.set_num_threads(threads_);
  }
  Single_thread_openmp_scope(const Single_thread_openmp_scope&) = delete;
  Single_thread_openmp_scope& operator=(const Single_thread_openmp_scope&) = delete;

private:
  struct Api
  {
    typedef void (*Setter)(int);
    typedef int (*Getter)();
    Setter set_dynamic = nullptr, set_num_threads = nullptr;
    Getter get_dynamic = nullptr, get_max_threads = nullptr;
    bool ok = false;
  };
  static const Api& get_api()
  {
    static const Api api = [] {
      Api a;
#ifdef CGAL_SMDF_HAS_DLSYM
      a.set_dynamic = reinterpret_cast<Api::Setter>(dlsym(RTLD_DEFAULT, "omp_set_dynamic"));
      a.set_num_threads = reinterpret_cast<Api::Setter>(dlsym(RTLD_DEFAULT, "omp_set_num_threads"));
      a.get_dynamic = reinterpret_cast<Api::Getter>(dlsym(RTLD_DEFAULT, "omp_get_dynamic"));
      a.get_max_threads = reinterpret_cast<Api::Getter>(dlsym(RTLD_DEFAULT, "omp_get_max_threads"));
      a.ok = a.set_dynamic && a.set_num_threads && a.get_dynamic && a.get_max_threads;
#endif
      return a;
    }();
    return api;
  }
  bool active_ = false;
  int dynamic_ = 0, threads_ = 1;
};

// OpenBLAS's thread pool is process-wide and its size may not be changed here: another thread
// of the user's program could see it. With two pool threads, two concurrent callers queued for
// the pool and its threads spun on sched_yield (433k-face cone metric: 5.5 s instead of 3.2-4.6
// s, 4 s of system time). So the two halves run concurrently only when BLAS runs in its calling
// thread (a pool of one thread, or a BLAS without a pool); with a threaded pool they run one
// after the other and the pool parallelises their dense blocks. The size is only read, once per
// factorisation; BLAS libraries other than OpenBLAS count as one thread.
inline bool blas_runs_in_caller()
{
#ifdef CGAL_SMDF_HAS_DLSYM
  typedef int (*Getter)();
  static const Getter get = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  return !get || get() <= 1;
#else
  return true;
#endif
}

typedef Eigen::SparseMatrix<double, Eigen::ColMajor, int> Sparse_matrix_int;

// Column-major dense lower-triangular kernels on n x n arrays.
namespace dense {

typedef Eigen::Map<Eigen::MatrixXd> Matrix_map;
typedef Eigen::Map<const Eigen::MatrixXd> Const_matrix_map;

// lower(C) = L L^T, L lower triangular (its upper part must be zero). With R = J L J (J the
// reversal, R upper triangular), L L^T = J R R^T J: LAPACK's dlauum forms R R^T in s^3 / 3
// flops, a third of a general rank update.
inline void lower_times_transpose(int n, const double* L, double* C)
{
  if(n == 0) return;
#ifdef CGAL_SMDF_DIRECT_BLAS
  const std::size_t nn = std::size_t(n) * std::size_t(n);
  std::reverse_copy(L, L + nn, C);   // reversing the column-major array is J L J
  int info = 0;
  cgal_smdf_dlauum("U", &n, C, &n, &info);
  std::reverse(C, C + nn);
#else
  Matrix_map c(C, n, n);
  c.setZero();
  c.selfadjointView<Eigen::Lower>().rankUpdate(Const_matrix_map(L, n, n));
#endif
}

// Cholesky factor in place (lower); false if not positive definite
inline bool cholesky(int n, double* C)
{
  if(n == 0) return true;
#ifdef CGAL_SMDF_DIRECT_BLAS
  int info = 0;
  cgal_smdf_dpotrf("L", &n, C, &n, &info);
  return info == 0;
#else
  Matrix_map c(C, n, n);
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(c);
  return llt.info() == Eigen::Success;
#endif
}

// x = op(L) x, op(L) one of L, L^T, L^-1, L^-T
inline void triangular(int n, const double* L, double* x, bool transpose, bool inverse)
{
  if(n == 0) return;
#ifdef CGAL_SMDF_DIRECT_BLAS
  const int one = 1;
  (inverse ? cgal_smdf_dtrsv : cgal_smdf_dtrmv)("L", transpose ? "T" : "N", "N", &n, L, &n, x, &one);
#else
  Eigen::Map<Eigen::VectorXd> v(x, n);
  Const_matrix_map l(L, n, n);
  if(inverse && transpose) l.transpose().triangularView<Eigen::Upper>().solveInPlace(v);
  else if(inverse) l.triangularView<Eigen::Lower>().solveInPlace(v);
  else if(transpose) v = Eigen::VectorXd(l.transpose().triangularView<Eigen::Upper>() * v);
  else v = Eigen::VectorXd(l.triangularView<Eigen::Lower>() * v);
#endif
}

} // namespace dense

class Two_domain_cholesky
{
public:
  Two_domain_cholesky() = default;
  Two_domain_cholesky(const Two_domain_cholesky&) = delete;
  Two_domain_cholesky& operator=(const Two_domain_cholesky&) = delete;

  int separator_size() const { return s_; }

  // Analyses and factors `lower` (lower triangle with the diagonal of an SPD matrix) in the
  // given split ordering. False with a message if the split is invalid (an entry couples the
  // two domains) or the matrix is not positive definite. solve_often: many solves will follow
  // and few or no refactor() calls.
  bool factor(const Sparse_matrix_int& lower, const Two_domain_ordering& ord, std::string& message,
              bool solve_often = false)
  {
    half_[0].solve_often = half_[1].solve_often = solve_often;
    n_ = int(lower.rows());
    n1_ = ord.n1;
    n2_ = ord.n2;
    s_ = n_ - n1_ - n2_;
    std::vector<int> pos(std::size_t(n_), 0);   // input index -> position in the ordering
    for(int k = 0; k < n_; ++k) pos[ord.order[k]] = k;
    half_[0].rows.assign(ord.order.begin(), ord.order.begin() + n1_);
    half_[1].rows.assign(ord.order.begin() + n1_, ord.order.begin() + n1_ + n2_);
    sep_rows_.assign(ord.order.begin() + n1_ + n2_, ord.order.end());
    if(!build_halves(lower, pos, message)) return false;
    for(Half& h : half_) h.analysed = false;
    return refactor(lower, message);
  }

  // Numeric factorisation of a matrix with the pattern of the last factor().
  bool refactor(const Sparse_matrix_int& lower, std::string& message)
  {
    if(!lower.isCompressed() || std::size_t(lower.nonZeros()) != half_[0].dest.size()) {
      message = "internal: refactor() with a different pattern";
      return false;
    }
    const double* value = lower.valuePtr();
    const std::size_t nnz = std::size_t(lower.nonZeros());
    for(int i = 0; i < 2; ++i) {
      Half& h = half_[i];
      std::fill(h.x.begin(), h.x.end(), 0.);
      for(std::size_t k = 0; k < nnz; ++k) if(h.dest[k] >= 0) h.x[std::size_t(h.dest[k])] += value[k];
    }
    std::vector<double> ass(std::size_t(s_) * std::size_t(s_), 0.);
    for(const auto& d : sep_dest_) ass[std::size_t(d.second)] += value[d.first];
    std::string m0, m1;
    concurrent_ = blas_runs_in_caller();
    run_on_two_threads([&](int i) { (i == 0 ? m0 : m1) = half_[i].factor_and_schur(s_); }, concurrent_);
    if(!m0.empty() || !m1.empty()) { message = m0.empty() ? m1 : m0; return false; }
    // S = S_1 + S_2 - Ass (lower triangles), then its Cholesky factor
    schur_.resize(ass.size());
    for(int c = 0; c < s_; ++c)
      for(int r = c; r < s_; ++r) {
        const std::size_t k = std::size_t(c) * std::size_t(s_) + std::size_t(r);
        schur_[k] = half_[0].schur[k] + half_[1].schur[k] - ass[k];
      }
    for(int c = 0; c < s_; ++c)
      for(int r = 0; r < c; ++r) schur_[std::size_t(c) * std::size_t(s_) + std::size_t(r)] = 0;
    for(Half& h : half_) std::vector<double>().swap(h.schur);
    if(!dense::cholesky(s_, schur_.data())) {
      message = "CHOLMOD could not factor the normal equations (matrix not positive definite)";
      return false;
    }
    return true;
  }

  // Solves A x = b; with held > 0, the last `held` unknowns of the separator (in the ordering's
  // order) are held at 0 and left out: x solves the leading principal block A_11 x_1 = b_1 of the
  // other unknowns. With L = [L1 0; L2 L3] and L1 L1^T = A_11, zeroing the held part between the
  // forward and the backward solve gives x_1 = L1^-T L1^-1 b_1 and x_2 = 0.
  Eigen::VectorXd solve(const Eigen::VectorXd& b, int held = 0) const
  {
    Eigen::VectorXd x(n_);
    if(n_ == 0) return x;
    std::vector<double> sep(static_cast<std::size_t>(s_));
    for(int k = 0; k < s_; ++k) sep[std::size_t(k)] = b[sep_rows_[std::size_t(k)]];
    // forward: L_i [z_i; w_i] = [b_i; 0], and Asi Aii^-1 bi = -Lss_i w_i
    std::vector<double> c[2];
    auto forward = [&](int i) {
      const Half& h = half_[i];
      std::vector<double>& z = h.work;
      z.assign(std::size_t(h.n), 0.);
      for(int k = 0; k < h.nd; ++k) z[std::size_t(k)] = b[h.rows[std::size_t(k)]];
      h.solve(CHOLMOD_L, z);
      c[i].assign(z.begin() + h.nd, z.end());
      dense::triangular(s_, h.lss.data(), c[i].data(), false, false);
    };
    // back: L_i^T [x_i; y] = [z_i; Lss_i^T xs] gives y = xs and x_i = Lii^-T (z_i - Ls_i^T xs)
    auto back = [&](int i, const std::vector<double>& xs) {
      const Half& h = half_[i];
      std::vector<double>& z = h.work;
      std::copy(xs.begin(), xs.end(), z.begin() + h.nd);
      dense::triangular(s_, h.lss.data(), z.data() + h.nd, true, false);
      h.solve(CHOLMOD_Lt, z);
      for(int k = 0; k < h.nd; ++k) x[h.rows[std::size_t(k)]] = z[std::size_t(k)];
    };
    run_on_two_threads(forward, concurrent_);
    for(int k = 0; k < s_; ++k) sep[std::size_t(k)] += c[0][std::size_t(k)] + c[1][std::size_t(k)];
    dense::triangular(s_, schur_.data(), sep.data(), false, true);
    std::fill(sep.end() - (std::min)(held, s_), sep.end(), 0.);
    dense::triangular(s_, schur_.data(), sep.data(), true, true);
    run_on_two_threads([&](int i) { back(i, sep); }, concurrent_);
    for(int k = 0; k < s_; ++k) x[sep_rows_[std::size_t(k)]] = sep[std::size_t(k)];
    return x;
  }

  // The Schur complement of A onto the last t unknowns of the separator, A_22 - A_21 A_11^-1 A_12
  // (t x t, in the ordering's order): L3 L3^T, L3 the trailing block of the factor.
  Eigen::MatrixXd trailing_schur(int t) const
  {
    t = (std::min)(t, s_);
    const std::size_t s = std::size_t(s_), o = std::size_t(s_ - t);
    Eigen::MatrixXd l3 = Eigen::MatrixXd::Zero(t, t);
    for(int c = 0; c < t; ++c)
      for(int r = c; r < t; ++r) l3(r, c) = schur_[(o + std::size_t(c)) * s + o + std::size_t(r)];
    Eigen::MatrixXd result = Eigen::MatrixXd::Zero(t, t);
    result.selfadjointView<Eigen::Lower>().rankUpdate(l3);
    return Eigen::MatrixXd(result.selfadjointView<Eigen::Lower>());
  }

private:
  // M_i = [Aii Ais; Asi Ass] in compressed lower columns, factored by CHOLMOD in natural order
  // (the domain's AMD order, separator last) so that the last s columns of L are Lss_i.
  struct Half
  {
    cholmod_common cc;
    cholmod_factor* factor = nullptr;
    int nd = 0, n = 0;               // domain size, domain + separator
    std::vector<int> p, i;           // pattern of M_i
    std::vector<double> x;
    std::vector<long long> dest;     // per nonzero of the input: position in x, or -1
    std::vector<double> lss, schur;  // s x s column-major: Lss_i and Lss_i Lss_i^T
    std::vector<int> rows;           // input row of each domain unknown, in elimination order
    bool analysed = false;
    bool solve_often = false;        // convert the factor to simplicial form for the solves
    // solve workspace (a solve is not reentrant, as with CHOLMOD itself)
    mutable std::vector<double> work;
    mutable cholmod_dense *X = nullptr, *Y = nullptr, *E = nullptr;

    Half()
    {
      cholmod_start(&cc);
      make_cholmod_quiet(cc);   // failures are reported by factor(), nothing is printed
      cc.nmethods = 1;
      cc.method[0].ordering = CHOLMOD_NATURAL;
      cc.postorder = 0;
      // supernodal always: the trailing separator block is dense and goes through BLAS
      cc.supernodal = CHOLMOD_SUPERNODAL;
      cc.final_ll = 1;
    }
    ~Half()
    {
      cholmod_dense** ws[3] = {&X, &Y, &E};
      for(cholmod_dense** w : ws) if(*w) cholmod_free_dense(w, &cc);
      if(factor) cholmod_free_factor(&factor, &cc);
      cholmod_finish(&cc);
    }
    cholmod_sparse view() { return lower_triangle_view(n, p.data(), i.data(), x.size(), x.data()); }
    // empty string on success
    std::string factor_and_schur(int s)
    {
      if(n == 0) { lss.clear(); schur.clear(); return std::string(); }   // an empty half (a split of one domain)
      Single_thread_openmp_scope one_openmp_thread;
      cholmod_sparse A = view();
      if(!analysed) {
        if(factor) cholmod_free_factor(&factor, &cc);
        factor = cholmod_analyze(&A, &cc);
        if(!factor) return "internal: CHOLMOD analysis failed (status " + std::to_string(cc.status) + ")";
        const int* perm = static_cast<const int*>(factor->Perm);
        for(int k = 0; k < n; ++k)
          if(perm[k] != k) return "internal: CHOLMOD did not keep the two-domain ordering";
        analysed = true;
      }
      if(!cholmod_factorize(&A, factor, &cc) || cc.status != CHOLMOD_OK || factor->minor < factor->n)
        return "CHOLMOD could not factor the normal equations (matrix not positive definite)" + take_cholmod_error();
      extract_lss(s);
      schur.assign(lss.size(), 0.);
      dense::lower_times_transpose(s, lss.data(), schur.data());
      if(solve_often) {
        // simplicial triangular solves are faster than supernodal ones on the small supernodes
        // of a mesh (400k faces: 27 vs 34 ms per solve); refactor() then analyses again
        if(cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, factor, &cc)) analysed = false;
      }
      return std::string();
    }
    void extract_lss(int s)
    {
      lss.assign(std::size_t(s) * std::size_t(s), 0.);
      const double* fx = static_cast<const double*>(factor->x);
      if(factor->is_super) {
        const int* super = static_cast<const int*>(factor->super);
        const int* pi = static_cast<const int*>(factor->pi);
        const int* px = static_cast<const int*>(factor->px);
        const int* rows = static_cast<const int*>(factor->s);
        for(std::size_t k = 0; k < factor->nsuper; ++k) {
          const int c0 = super[k], c1 = super[k + 1];
          if(c1 <= nd) continue;
          const int nsrow = pi[k + 1] - pi[k];
          for(int c = (std::max)(c0, nd); c < c1; ++c)
            for(int t = c - c0; t < nsrow; ++t)
              lss[std::size_t(c - nd) * std::size_t(s) + std::size_t(rows[pi[k] + t] - nd)] =
                  fx[std::size_t(px[k]) + std::size_t(t) + std::size_t(c - c0) * std::size_t(nsrow)];
        }
      } else {
        const int* fp = static_cast<const int*>(factor->p);
        const int* fi = static_cast<const int*>(factor->i);
        const int* fnz = static_cast<const int*>(factor->nz);
        for(int c = nd; c < n; ++c)
          for(int q = fp[c]; q < fp[c] + fnz[c]; ++q)
            lss[std::size_t(c - nd) * std::size_t(s) + std::size_t(fi[q] - nd)] = fx[q];
      }
    }
    // y = L^-1 y or L^-T y (sys CHOLMOD_L / CHOLMOD_Lt)
    void solve(int sys, std::vector<double>& y) const
    {
      if(n == 0) return;
      cholmod_common& c = const_cast<cholmod_common&>(cc);
      cholmod_dense B;
      B.nrow = std::size_t(n);
      B.ncol = 1;
      B.nzmax = std::size_t(n);
      B.d = std::size_t(n);
      B.x = y.data();
      B.z = nullptr;
      B.xtype = CHOLMOD_REAL;
      B.dtype = CHOLMOD_DOUBLE;
      // cholmod_solve2 keeps its result and workspace between calls (no allocation per solve)
      if(cholmod_solve2(sys, factor, &B, nullptr, &X, nullptr, &Y, &E, &c)) {
        const double* xx = static_cast<const double*>(X->x);
        std::copy(xx, xx + n, y.begin());
      } else {
        std::fill(y.begin(), y.end(), std::numeric_limits<double>::quiet_NaN());
      }
    }
  };

  int n_ = 0, n1_ = 0, n2_ = 0, s_ = 0;
  bool concurrent_ = true;   // the halves on two threads (see blas_runs_in_caller())
  std::vector<int> sep_rows_;                          // input row of each separator unknown
  Half half_[2];
  std::vector<std::pair<std::size_t, long long>> sep_dest_;   // nonzero -> entry of dense Ass
  std::vector<double> schur_;                          // Cholesky factor of S (lower)

  bool build_halves(const Sparse_matrix_int& lower, const std::vector<int>& pos, std::string& message)
  {
    const int ns = n1_ + n2_;
    const std::size_t nnz = std::size_t(lower.nonZeros());
    half_[0].nd = n1_; half_[0].n = n1_ + s_;
    half_[1].nd = n2_; half_[1].n = n2_ + s_;
    sep_dest_.clear();
    // local (row, column) of an entry in half `i`, or false if it does not belong to it
    struct Local { int half, row, col; };
    auto locate = [&](int a, int b, Local out[2], int& count) {
      const int r = (std::max)(a, b), c = (std::min)(a, b);
      count = 0;
      if(c < n1_) {
        if(r >= n1_ && r < ns) return false;
        out[count++] = Local{0, r < n1_ ? r : r - n2_, c};
      } else if(c < ns) {
        out[count++] = Local{1, r - n1_, c - n1_};
      } else {
        out[count++] = Local{0, r - n2_, c - n2_};
        out[count++] = Local{1, r - n1_, c - n1_};
      }
      return true;
    };
    for(Half& h : half_) {
      h.p.assign(std::size_t(h.n) + 1, 0);
      h.dest.assign(nnz, -1);
    }
    const int* outer = lower.outerIndexPtr();
    const int* inner = lower.innerIndexPtr();
    if(!lower.isCompressed()) { message = "internal: uncompressed matrix"; return false; }
    Local loc[2];
    int count = 0;
    for(int j = 0; j < n_; ++j)
      for(int k = outer[j]; k < outer[j + 1]; ++k) {
        if(inner[k] < j) continue;   // the strict upper triangle is ignored, as by CHOLMOD
        if(!locate(pos[inner[k]], pos[j], loc, count)) {
          message = "internal: the two domains of the ordering are coupled";
          return false;
        }
        for(int t = 0; t < count; ++t) ++half_[loc[t].half].p[std::size_t(loc[t].col) + 1];
      }
    for(Half& h : half_) {
      for(int c = 0; c < h.n; ++c) h.p[c + 1] += h.p[c];
      h.i.assign(std::size_t(h.p[h.n]), 0);
      h.x.assign(std::size_t(h.p[h.n]), 0.);
    }
    std::vector<int> fill[2] = {std::vector<int>(half_[0].p.begin(), half_[0].p.end() - 1),
                                std::vector<int>(half_[1].p.begin(), half_[1].p.end() - 1)};
    for(int j = 0; j < n_; ++j)
      for(int k = outer[j]; k < outer[j + 1]; ++k) {
        if(inner[k] < j) continue;
        locate(pos[inner[k]], pos[j], loc, count);
        for(int t = 0; t < count; ++t) {
          Half& h = half_[loc[t].half];
          const int q = fill[loc[t].half][std::size_t(loc[t].col)]++;
          h.i[std::size_t(q)] = loc[t].row;
          h.dest[std::size_t(k)] = q;
        }
        if(count == 2) {
          const int r = (std::max)(pos[inner[k]], pos[j]) - ns, c = (std::min)(pos[inner[k]], pos[j]) - ns;
          sep_dest_.emplace_back(std::size_t(k), (long long)c * s_ + r);
        }
      }
    // sort the rows of each column (CHOLMOD wants them sorted), carrying the input positions
    for(Half& h : half_) {
      std::vector<long long> src_of(h.i.size(), -1);
      for(std::size_t k = 0; k < nnz; ++k) if(h.dest[k] >= 0) src_of[std::size_t(h.dest[k])] = (long long)k;
      std::vector<std::pair<int, long long>> column;
      for(int c = 0; c < h.n; ++c) {
        column.clear();
        for(int q = h.p[c]; q < h.p[c + 1]; ++q) column.emplace_back(h.i[q], src_of[q]);
        std::sort(column.begin(), column.end());
        for(int q = h.p[c]; q < h.p[c + 1]; ++q) {
          const auto& e = column[std::size_t(q - h.p[c])];
          h.i[q] = e.first;
          h.dest[std::size_t(e.second)] = q;
        }
      }
    }
    return true;
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TWO_DOMAIN_CHOLESKY_H
