// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_CHOLMOD_CHOLESKY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_CHOLMOD_CHOLESKY_H

#include <CGAL/Surface_mesh_direction_fields/internal/two_domain_cholesky.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsSolvers
/// What a caller knows about a matrix it hands to `SparseCholeskySolver::factor()`. Solvers
/// may use or ignore it; `Cholmod_cholesky` uses all of it.
struct Cholesky_hints
{
  /// the rows are already in a fill-reducing order (keep it instead of computing one)
  bool preordered = false;
  /// with `preordered`: the rows are two domains of `domain_rows[0]` and `domain_rows[1]` rows
  /// that share no entry, followed by their separator (0, 0: no such split)
  int domain_rows[2] = {0, 0};
  /// the factor will serve many solves and few or no refactorisations
  bool many_solves = false;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsSolvers
/// The default model of `SparseCholeskySolver`: CHOLMOD's sparse Cholesky factorisation
/// (SuiteSparse), factored on two threads for large matrices. Used by `Trivial_connection` and
/// `compute_cone_metric()` unless another solver is given.
///
/// From 30,000 rows on, the matrix is split by one level of nested dissection into two
/// domains and a separator, the two halves are factored concurrently and the dense Schur
/// complement of the separator is factored with LAPACK. While the halves run, the OpenMP regions
/// CHOLMOD starts from the factoring threads are limited to one thread (a per-thread setting,
/// restored afterwards). Nothing process-wide is changed: when OpenBLAS runs a thread pool of
/// more than one thread, the halves are factored one after the other and the pool works on
/// their dense blocks. See `enable_cholmod_huge_pages()` for an opt-in memory setting.
/// \cgalModels `SparseCholeskySolver`
//
// CHOLMOD and not SPQR: the normal-equation matrix of the trivial-connection system is a
// graph Laplacian plus a few sparse rows, and its Cholesky factor is an order of magnitude
// cheaper than a QR of the |V| x |E| constraint matrix. The symbolic analysis is reusable when
// only values change.
//
// From two_domain_min_rows rows on, the matrix is split by one level of nested dissection and
// factored on two threads (Two_domain_cholesky); measured here: trivial-connection setup 0.90 ->
// 0.55 s at 400k faces, 2.7 -> 2.2 s at 1M faces; from 30,000 rows rather than 100,000 since
// 2026-12-06: smdf remesh of a 114k-face mesh (57k rows), placement 1.5 -> 1.05 s, cross field
// 0.5 -> 0.26 s (OpenBLAS on one thread; with two, 1.5 -> 1.46 and 0.5 -> 0.41 s). Below, one thread: simplicial below 300k
// rows, supernodal above (simplicial factored 200k-row mesh Laplacians 1.5x faster, supernodal
// 800k rows 1.6x faster).
//
// Fill-reducing ordering: AMD (CHOLMOD's, or the caller's with Cholesky_hints::preordered when its
// rows are already in a fill-reducing order, see amd_ordering(); CHOLMOD then only postorders
// the elimination tree). METIS and NESDIS cut the flops at 1M faces from 5.9e9 to 3.0-3.2e9 but
// their analysis took 3.0-3.7 s, more than they save.
class Cholmod_cholesky
{
public:
  /// The matrix type: the lower triangle of a symmetric positive definite matrix.
  typedef Eigen::SparseMatrix<double, Eigen::ColMajor, int> Matrix;

  // Matrices with at least this many rows are factored on two threads when a small separator
  // is found (Two_domain_cholesky). The tests lower it to run that path on small meshes.
#ifdef CGAL_SMDF_TWO_DOMAIN_MIN_ROWS
  static constexpr int two_domain_min_rows = CGAL_SMDF_TWO_DOMAIN_MIN_ROWS;
#else
  static constexpr int two_domain_min_rows = 30000;
#endif
  // Largest separator accepted: its dense Schur complement costs |S|^3 / 3 flops and 8 |S|^2 bytes.
  static constexpr int max_separator = 2500;

  Cholmod_cholesky() { reset_solver(); }
  /// Copies the settings, not the factorisation: the copy must be factored before it solves.
  Cholmod_cholesky(const Cholmod_cholesky&) : Cholmod_cholesky() {}
  Cholmod_cholesky& operator=(const Cholmod_cholesky&) { reset_solver(); two_domain_.reset(); return *this; }

  /// Analyses the pattern of `lower` (AMD ordering, or the two-domain split of large
  /// matrices) and factors it. Returns `false`, with a message, if the matrix is not positive
  /// definite.
  bool factor(const Matrix& lower, std::string& message) { return factor(lower, Cholesky_hints(), message); }

  /// As `factor(lower, message)`, with what the caller knows about the matrix (see `Cholesky_hints`).
  bool factor(const Matrix& lower, const Cholesky_hints& hints, std::string& message)
  {
    two_domain_.reset();
    const int n = int(lower.rows());
    internal::Two_domain_ordering split;
    if(hints.preordered && hints.domain_rows[0] > 0 && hints.domain_rows[1] > 0) {
      split.order.resize(std::size_t(n));
      for(int i = 0; i < n; ++i) split.order[i] = i;
      split.n1 = hints.domain_rows[0];
      split.n2 = hints.domain_rows[1];
    } else if(!hints.preordered && n >= two_domain_min_rows && lower.isCompressed()) {
      std::vector<int> adj_begin, adj;
      internal::symmetric_adjacency(n, lower.outerIndexPtr(), lower.innerIndexPtr(), adj_begin, adj);
      split = internal::two_domain_ordering(n, adj_begin, adj, 64, max_separator, false);
    }
    if(split.is_split() && n - split.n1 - split.n2 <= max_separator) {
      std::unique_ptr<internal::Two_domain_cholesky> td(new internal::Two_domain_cholesky());
      std::string why;
      if(td->factor(lower, split, why, hints.many_solves)) {
        solver_.reset();
        two_domain_ = std::move(td);
        return true;
      }
      if(why.compare(0, 9, "internal:") != 0) { message = why; return false; }
    }
    reset_solver();
    solver_->setMode(lower.rows() < 300000 ? Eigen::CholmodSimplicialLLt : Eigen::CholmodSupernodalLLt);
    if(hints.preordered) {
      solver_->cholmod().nmethods = 1;
      solver_->cholmod().method[0].ordering = CHOLMOD_NATURAL;
      solver_->cholmod().postorder = 1;
    }
    solver_->analyzePattern(lower);
    return refactor(lower, message);
  }
  /// Numeric factorisation of a matrix with the pattern of the last `factor()`.
  bool refactor(const Matrix& lower, std::string& message)
  {
    if(two_domain_) return two_domain_->refactor(lower, message);
    solver_->factorize(lower);
    if(solver_->info() != Eigen::Success) {
      message = "CHOLMOD could not factor the normal equations (matrix not positive definite)" + internal::take_cholmod_error();
      return false;
    }
    return true;
  }
  /// Solves \f$A x = b\f$ with the last factorisation.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const
  {
    return two_domain_ ? two_domain_->solve(b) : Eigen::VectorXd(solver_->solve(b));
  }
  /// Rows of the separator when the last factorisation used two threads, -1 otherwise.
  int separator_size() const { return two_domain_ ? two_domain_->separator_size() : -1; }

private:
  typedef Eigen::CholmodDecomposition<Matrix, Eigen::Lower> Solver;
  // A library does not print: CHOLMOD's messages are silenced, its failures are the return values.
  void reset_solver()
  {
    solver_.reset(new Solver());
    internal::make_cholmod_quiet(solver_->cholmod());
  }
  std::unique_ptr<Solver> solver_;
  std::unique_ptr<internal::Two_domain_cholesky> two_domain_;
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_CHOLMOD_CHOLESKY_H
