// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SPARSE_SOLVERS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_SPARSE_SOLVERS_H

#include <CGAL/Surface_mesh_direction_fields/internal/cholmod_errors.h>

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

// Minimum 2-norm solution of an underdetermined system M y = r by SuiteSparseQR
// (SuiteSparseQR_min2norm: QR of M^T). This is the reference path, used to validate the
// CHOLMOD normal-equation solve: Eigen's SPQR::solve is a basic, not a minimum-norm, solution
// for wide matrices.
inline bool spqr_minimum_norm(const Sparse_matrix& M, const Eigen::VectorXd& r, Eigen::VectorXd& y,
                              std::string& message)
{
  cholmod_common cc;
  cholmod_l_start(&cc);
  make_cholmod_quiet(cc);   // failures are the return value, nothing is printed
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
