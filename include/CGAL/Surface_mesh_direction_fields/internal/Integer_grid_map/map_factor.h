// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_MAP_FACTOR_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_MAP_FACTOR_H

// The factorisation behind integer_grid_map() (integer_grid_map.h). Its normal equations
//
//   A = [ Hbb    Hbs ]   b: one or two real unknowns per vertex (thousands to millions)
//       [ Hbs^T  Hss ]   s: the small unknowns (two per singularity, seam arc, boundary line)
//
// are factored as one sparse matrix with the small unknowns ordered last (the vertex block split
// by one level of nested dissection and factored on two threads, Two_domain_cholesky). The
// trailing block L3 of the factor gives the Schur complement S = Hss - Hbs^T Hbb^-1 Hbs = L3 L3^T,
// and its leading block solves Hbb alone (the small unknowns held at 0).
//
// Why: the Schur complement by one back-substitution of Hbb per small unknown took 60 % of the
// map's time (114k faces, 404 small unknowns: 2.4 s); ordered last, the small unknowns only fill
// the factor along the elimination tree's paths from the seams' vertices to the root.
//
// A must be positive definite, and the energy alone is not in the small unknowns (a translation
// of everything, a line's unused imaginary part): the caller adds w R^T R to Hss, R the rows of
// the linear conditions the small unknowns must meet. That leaves the energy unchanged on the
// conditions' solutions, and A is positive definite exactly when the conditioned problem has one
// solution. The caller subtracts w R^T R from the Schur complement again.

#include <CGAL/Surface_mesh_direction_fields/internal/two_domain_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_domain_ordering.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

class Map_factor
{
public:
  typedef Sparse_matrix_int Matrix;

  // lower: the lower triangle of A (compressed columns), the nb vertex unknowns first. Later
  // calls with the same pattern (the stiffening rounds) reuse the ordering and the analysis.
  bool factor(const Matrix& lower, int nb, std::string& message)
  {
    nb_ = nb;
    ns_ = int(lower.rows()) - nb;
    if(nb == 0) {   // no vertex unknown: S = Hss
      schur_ = Eigen::MatrixXd(Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>());
      return true;
    }
    if(factored_ && lower.nonZeros() == nonzeros_ && lower.rows() == rows_) return llt_->refactor(lower, message);
    // the vertex block's ordering (its own graph: through a small unknown, every vertex of a
    // seam would look adjacent to every other), the small unknowns appended to the separator
    std::vector<int> adj_begin, adj;
    {
      const Matrix hbb = lower.topLeftCorner(nb, nb);
      symmetric_adjacency(nb, hbb.outerIndexPtr(), hbb.innerIndexPtr(), adj_begin, adj);
    }
    Two_domain_ordering order = two_domain_ordering(nb, adj_begin, adj, 64, 2500, true);
    split_ = order.is_split();
    if(!split_) { order.n1 = nb; order.n2 = 0; }
    for(int k = nb; k < nb + ns_; ++k) order.order.push_back(k);
    llt_.reset(new Two_domain_cholesky());
    if(!llt_->factor(lower, order, message)) { factored_ = false; return false; }
    factored_ = true;
    rows_ = lower.rows();
    nonzeros_ = lower.nonZeros();
    return true;
  }

  // the vertex block was split in two domains (factored on two threads)
  bool split() const { return split_; }

  // S = Hss - Hbs^T Hbb^-1 Hbs of the last factor() (with the caller's w R^T R)
  Eigen::MatrixXd schur() const { return nb_ == 0 ? schur_ : llt_->trailing_schur(ns_); }

  // Hbb^-1 r
  Eigen::VectorXd solve_vertices(const Eigen::VectorXd& r) const
  {
    if(nb_ == 0) return Eigen::VectorXd();
    Eigen::VectorXd b = Eigen::VectorXd::Zero(nb_ + ns_);
    b.head(nb_) = r;
    return llt_->solve(b, ns_).head(nb_);
  }

private:
  std::unique_ptr<Two_domain_cholesky> llt_;
  bool factored_ = false, split_ = false;
  int nb_ = 0, ns_ = 0;
  Eigen::Index rows_ = 0, nonzeros_ = 0;
  Eigen::MatrixXd schur_;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_MAP_FACTOR_H
