// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_EIGEN_SPARSE_CHOLESKY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_EIGEN_SPARSE_CHOLESKY_H

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <string>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsSolvers
/// A model of `SparseCholeskySolver` on one of Eigen's sparse direct solvers (no SuiteSparse
/// needed for the solves; one thread, several times slower than `Cholmod_cholesky` on large
/// meshes).
/// \tparam EigenSolver an Eigen sparse solver of `Eigen::SparseMatrix<double, Eigen::ColMajor, int>`
///         that reads the lower triangle, e.g. `Eigen::SimplicialLDLT<Matrix, Eigen::Lower>`
///         (the default) or `Eigen::SimplicialLLT<Matrix, Eigen::Lower>`
/// \cgalModels `SparseCholeskySolver`
template <typename EigenSolver =
              Eigen::SimplicialLDLT<Eigen::SparseMatrix<double, Eigen::ColMajor, int>, Eigen::Lower>>
class Eigen_sparse_cholesky
{
public:
  /// The matrix type: the lower triangle of a symmetric positive definite matrix.
  typedef Eigen::SparseMatrix<double, Eigen::ColMajor, int> Matrix;

  Eigen_sparse_cholesky() = default;
  /// Copies the settings, not the factorisation.
  Eigen_sparse_cholesky(const Eigen_sparse_cholesky&) {}
  Eigen_sparse_cholesky& operator=(const Eigen_sparse_cholesky&) { solver_ = EigenSolver(); return *this; }

  /// The Eigen solver, e.g. to set its options before the first factorisation.
  EigenSolver& solver() { return solver_; }

  /// Analyses the pattern and factors; `false` with a message if Eigen reports a failure.
  bool factor(const Matrix& lower, std::string& message)
  {
    solver_.analyzePattern(lower);
    return refactor(lower, message);
  }

  /// Numeric factorisation of a matrix with the pattern of the last `factor()`.
  bool refactor(const Matrix& lower, std::string& message)
  {
    solver_.factorize(lower);
    if(solver_.info() != Eigen::Success) {
      message = "Eigen's sparse Cholesky could not factor the matrix (not positive definite)";
      return false;
    }
    return true;
  }

  /// Solves \f$A x = b\f$ with the last factorisation.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return solver_.solve(b); }

private:
  EigenSolver solver_;
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_EIGEN_SPARSE_CHOLESKY_H
