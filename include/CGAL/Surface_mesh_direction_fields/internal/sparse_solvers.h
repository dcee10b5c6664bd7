// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SPARSE_SOLVERS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SPARSE_SOLVERS_H

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/CholmodSupport>

#include <SuiteSparseQR.hpp>

#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

typedef Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long> Sparse_matrix;
typedef Eigen::SparseMatrix<double, Eigen::ColMajor, int> Sparse_matrix_int;

// Sparse Cholesky factorisation of a symmetric positive definite matrix kept for repeated
// solves. CHOLMOD and not SPQR: the normal-equation matrix of the trivial-connection system is a
// graph Laplacian plus a few sparse rows, and its Cholesky factor is an order of magnitude
// cheaper than a QR of the |V| x |E| constraint matrix. Simplicial below 300k rows, supernodal
// above: measured here on mesh Laplacians with AMD ordering, simplicial factored 200k rows 1.5x
// faster, supernodal (BLAS-3) 800k rows 1.6x faster (and at 500k rows, 1M faces: 3.1 s vs
// 2.3 s); two BLAS threads did not speed up the supernodal factorisation (2.3 s -> 2.2-2.6 s:
// the supernodes of a 2D mesh are small, and a third of the time is first-touch page faults
// of the factor). The symbolic analysis is reusable when only values change.
//
// Fill-reducing ordering: CHOLMOD's default (AMD here; it tries METIS only when AMD's fill is
// poor), unless the caller passes PRESERVE_ORDERING because its rows are already in a
// fill-reducing order (see amd_ordering()); CHOLMOD then only postorders the elimination tree.
// Measured at 1M faces (500k rows): AMD 0.8 s analysis, 2.3e7 nonzeros in L, 5.9e9 flops;
// METIS and NESDIS cut the flops to 3.0-3.2e9 but their analysis took 3.0-3.7 s, more than
// they save in the 2.0-2.3 s numeric factorisation.
class Cholmod_factor
{
public:
  enum Ordering {
    CHOLMOD_ORDERING,   ///< CHOLMOD chooses (AMD, METIS as a fallback)
    PRESERVE_ORDERING   ///< the rows are already in a fill-reducing order
  };

  Cholmod_factor() { solver_.reset(new Solver()); }

  // Analyses the pattern and factors; returns false (with a message) if not positive definite.
  bool factor(const Sparse_matrix_int& lower, std::string& message, Ordering ordering = CHOLMOD_ORDERING)
  {
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
    solver_->factorize(lower);
    if(solver_->info() != Eigen::Success) {
      message = "CHOLMOD could not factor the normal equations (matrix not positive definite)";
      return false;
    }
    return true;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return solver_->solve(b); }

private:
  typedef Eigen::CholmodDecomposition<Sparse_matrix_int, Eigen::Lower> Solver;
  std::unique_ptr<Solver> solver_;
};

// AMD fill-reducing ordering of the symmetric pattern with n nodes whose strictly lower
// triangle is given in compressed columns (col_begin of size n + 1, sorted rows without
// duplicates): order[k] is the node eliminated k-th. Empty if CHOLMOD fails. Used to order the
// vertex rows of a mesh Laplacian before the rest of the system exists (it only needs the
// connectivity), so that the ordering can run concurrently with the assembly.
inline std::vector<int> amd_ordering(int n, std::vector<int>& col_begin, std::vector<int>& rows)
{
  std::vector<int> order(std::size_t(n), 0);
  if(n == 0) return order;
  cholmod_common cc;
  cholmod_start(&cc);
  cholmod_sparse A;
  A.nrow = A.ncol = std::size_t(n);
  A.nzmax = rows.size();
  A.p = col_begin.data();
  A.i = rows.data();
  A.nz = nullptr;
  A.x = A.z = nullptr;
  A.stype = -1;
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_PATTERN;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  const bool ok = cholmod_amd(&A, nullptr, 0, order.data(), &cc) && cc.status == CHOLMOD_OK;
  cholmod_finish(&cc);
  if(!ok) order.clear();
  return order;
}

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
