// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MAP_VERTEX_FACTOR_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MAP_VERTEX_FACTOR_H

// The sparse factorisation behind integer_grid_map() (integer_grid_map.h).

#include <CGAL/Surface_mesh_direction_fields/internal/cholmod_errors.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The vertex block of the map's system, factored again after every stiffening round with the
// same pattern: supernodal (its fill is that of a two-component Laplacian with seams, where
// CHOLMOD's BLAS kernels beat the simplicial ones several times), the analysis done once, and
// solves by blocks of columns (the Schur complement's back-substitutions).
class Map_vertex_factor
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;

  bool factor(const Matrix& lower, std::string& message)
  {
    const bool same = analyzed_ && lower.rows() == rows_ && lower.nonZeros() == nonzeros_ &&
                      std::equal(lower.outerIndexPtr(), lower.outerIndexPtr() + lower.outerSize() + 1, outer_.begin()) &&
                      std::equal(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros(), inner_.begin());
    if(!same) {
      llt_.reset(new Solver());
      make_cholmod_quiet(llt_->cholmod());
      llt_->analyzePattern(lower);
      analyzed_ = true;
      rows_ = lower.rows();
      nonzeros_ = lower.nonZeros();
      outer_.assign(lower.outerIndexPtr(), lower.outerIndexPtr() + lower.outerSize() + 1);
      inner_.assign(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros());
    }
    llt_->factorize(lower);
    if(llt_->info() != Eigen::Success) {
      message = "CHOLMOD could not factor the map's system (not positive definite)" + take_cholmod_error();
      return false;
    }
    return true;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const { return llt_->solve(b); }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const { return llt_->solve(b); }

private:
  typedef Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> Solver;
  std::unique_ptr<Solver> llt_;
  bool analyzed_ = false;
  Eigen::Index rows_ = 0, nonzeros_ = 0;
  std::vector<Matrix::StorageIndex> outer_, inner_;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MAP_VERTEX_FACTOR_H
