// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SPARSE_SOLVERS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SPARSE_SOLVERS_H

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/CholmodSupport>

#include <SuiteSparseQR.hpp>

#include <CGAL/Surface_mesh_direction_fields/internal/two_domain_cholesky.h>

#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

typedef Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long> Sparse_matrix;

// Sparse Cholesky factorisation of a symmetric positive definite matrix kept for repeated
// solves. CHOLMOD and not SPQR: the normal-equation matrix of the trivial-connection system is a
// graph Laplacian plus a few sparse rows, and its Cholesky factor is an order of magnitude
// cheaper than a QR of the |V| x |E| constraint matrix. The symbolic analysis is reusable when
// only values change.
//
// From two_domain_min_rows rows on, the matrix is split by one level of nested dissection and
// factored on two threads (Two_domain_cholesky); measured here: trivial-connection setup 0.90 ->
// 0.55 s at 400k faces, 2.7 -> 2.2 s at 1M faces. Below, one thread: simplicial below 300k
// rows, supernodal above (simplicial factored 200k-row mesh Laplacians 1.5x faster, supernodal
// 800k rows 1.6x faster).
//
// Fill-reducing ordering: AMD (CHOLMOD's, or the caller's with PRESERVE_ORDERING when its
// rows are already in a fill-reducing order, see amd_ordering(); CHOLMOD then only postorders
// the elimination tree). METIS and NESDIS cut the flops at 1M faces from 5.9e9 to 3.0-3.2e9 but
// their analysis took 3.0-3.7 s, more than they save.
class Cholmod_factor
{
public:
  enum Ordering {
    CHOLMOD_ORDERING,   ///< AMD (or the two-domain split of large matrices)
    PRESERVE_ORDERING   ///< the rows are already in a fill-reducing order
  };

  // Matrices with at least this many rows are factored on two threads when a small separator
  // is found (Two_domain_cholesky). The tests lower it to run that path on small meshes.
#ifdef CGAL_SMDF_TWO_DOMAIN_MIN_ROWS
  static constexpr int two_domain_min_rows = CGAL_SMDF_TWO_DOMAIN_MIN_ROWS;
#else
  static constexpr int two_domain_min_rows = 100000;
#endif
  // Largest separator accepted: its dense Schur complement costs |S|^3 / 3 flops and 8 |S|^2 bytes.
  static constexpr int max_separator = 2500;

  Cholmod_factor() { solver_.reset(new Solver()); }

  // Analyses the pattern and factors; returns false (with a message) if not positive definite.
  // With PRESERVE_ORDERING, n1 > 0 and n2 > 0 say that the rows are ordered as two domains of
  // n1 and n2 rows that share no entry, followed by their separator. solve_often: the factor
  // will serve many solves and few or no refactor() calls (it may then be stored differently).
  bool factor(const Sparse_matrix_int& lower, std::string& message, Ordering ordering = CHOLMOD_ORDERING,
              int n1 = 0, int n2 = 0, bool solve_often = false)
  {
    two_domain_.reset();
    const int n = int(lower.rows());
    Two_domain_ordering split;
    if(ordering == PRESERVE_ORDERING && n1 > 0 && n2 > 0) {
      split.order.resize(std::size_t(n));
      for(int i = 0; i < n; ++i) split.order[i] = i;
      split.n1 = n1;
      split.n2 = n2;
    } else if(ordering == CHOLMOD_ORDERING && n >= two_domain_min_rows && lower.isCompressed()) {
      std::vector<int> adj_begin, adj;
      symmetric_adjacency(n, lower.outerIndexPtr(), lower.innerIndexPtr(), adj_begin, adj);
      split = two_domain_ordering(n, adj_begin, adj, 64, max_separator, false);
    }
    if(split.is_split() && n - split.n1 - split.n2 <= max_separator) {
      std::unique_ptr<Two_domain_cholesky> td(new Two_domain_cholesky());
      std::string why;
      if(td->factor(lower, split, why, solve_often)) {
        solver_.reset();
        two_domain_ = std::move(td);
        return true;
      }
      if(why.compare(0, 9, "internal:") != 0) { message = why; return false; }
    }
    solver_.reset(new Solver());
    solver_->setMode(lower.rows() < 300000 ? Eigen::CholmodSimplicialLLt : Eigen::CholmodSupernodalLLt);
    if(ordering == PRESERVE_ORDERING) {
      solver_->cholmod().nmethods = 1;
      solver_->cholmod().method[0].ordering = CHOLMOD_NATURAL;
      solver_->cholmod().postorder = 1;
    }
    solver_->analyzePattern(lower);
    return refactor(lower, message);
  }
  // Numeric factorisation with the previous analysis (same pattern).
  bool refactor(const Sparse_matrix_int& lower, std::string& message)
  {
    if(two_domain_) return two_domain_->refactor(lower, message);
    solver_->factorize(lower);
    if(solver_->info() != Eigen::Success) {
      message = "CHOLMOD could not factor the normal equations (matrix not positive definite)";
      return false;
    }
    return true;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const
  {
    return two_domain_ ? two_domain_->solve(b) : Eigen::VectorXd(solver_->solve(b));
  }
  // Rows of the separator when the last factorisation used two threads, -1 otherwise.
  int separator_size() const { return two_domain_ ? two_domain_->separator_size() : -1; }

private:
  typedef Eigen::CholmodDecomposition<Sparse_matrix_int, Eigen::Lower> Solver;
  std::unique_ptr<Solver> solver_;
  std::unique_ptr<Two_domain_cholesky> two_domain_;
};

// Minimum 2-norm solution of an underdetermined system M y = r by SuiteSparseQR
// (SuiteSparseQR_min2norm: QR of M^T). This is the reference path, used to validate the
// CHOLMOD normal-equation solve: Eigen's SPQR::solve is a basic, not a minimum-norm, solution
// for wide matrices.
inline bool spqr_minimum_norm(const Sparse_matrix& M, const Eigen::VectorXd& r, Eigen::VectorXd& y,
                              std::string& message)
{
  cholmod_common cc;
  cholmod_l_start(&cc);
  Sparse_matrix Mc = M;
  Mc.makeCompressed();
  cholmod_sparse A = Eigen::viewAsCholmod(Mc);
  cholmod_dense* B = cholmod_l_allocate_dense(r.size(), 1, r.size(), CHOLMOD_REAL, &cc);
  for(Eigen::Index i = 0; i < r.size(); ++i) static_cast<double*>(B->x)[i] = r[i];
  cholmod_dense* X = SuiteSparseQR_min2norm<double>(SPQR_ORDERING_DEFAULT, SPQR_DEFAULT_TOL, &A, B, &cc);
  bool ok = X != nullptr && cc.status == CHOLMOD_OK;
  if(ok) {
    y.resize(Eigen::Index(X->nrow));
    for(std::size_t i = 0; i < X->nrow; ++i) y[Eigen::Index(i)] = static_cast<double*>(X->x)[i];
  } else {
    message = "SuiteSparseQR minimum-norm solve failed (status " + std::to_string(cc.status) + ")";
  }
  if(X) cholmod_l_free_dense(&X, &cc);
  cholmod_l_free_dense(&B, &cc);
  cholmod_l_finish(&cc);
  return ok;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SPARSE_SOLVERS_H
