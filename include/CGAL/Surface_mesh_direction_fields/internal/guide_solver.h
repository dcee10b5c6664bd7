// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_GUIDE_SOLVER_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_GUIDE_SOLVER_H

// Soft guide directions of a trivial connection (Trivial_connection::set_guide_directions()):
// lambda sum_i (c_i^T x - cbar_i)^2 added to the objective, c_i the tree path from a guide face
// to its partner. Solved as a KKT system through the factorisation of A W A^T and a rank-k
// Sherman-Morrison-Woodbury correction (k = number of guides).

#include <CGAL/Surface_mesh_direction_fields/internal/connection_system.h>
#include <CGAL/Surface_mesh_direction_fields/internal/field_propagation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename Solver>
class Guide_solver
{
public:
  // no guide path: the plain minimum-norm solve applies
  bool empty() const { return guide_paths_.empty(); }

  // Guide paths (tree paths from each guide face up to the nearest guide or constrained face),
  // their columns, and the Woodbury data Z = L^-1 U, G = S - U^T Z with U = A W C^T,
  // S = diag(1/lambda + c_i^T W c_i).
  template <typename TM>
  void prepare(const Mesh_arrays<TM>& m_, const Face_tree& tree, const Connection_system& sys, const Solver& chol_,
               const std::vector<int>& guide_faces_, const std::vector<int>& constrained_faces_, double guide_weight)
  {
    guide_weight_ = guide_weight;
    guide_paths_.clear();
    guide_partner_.clear();
    guide_columns_.clear();
    if(guide_faces_.empty()) return;
    std::vector<int> mark(m_.number_of_faces(), -1);   // >= 0 guide i, <= -2 constraint -(j + 2)
    for(std::size_t i = 0; i < guide_faces_.size(); ++i) mark[guide_faces_[i]] = int(i);
    for(std::size_t j = 0; j < constrained_faces_.size(); ++j) mark[constrained_faces_[j]] = -int(j) - 2;
    for(std::size_t i = 0; i < guide_faces_.size(); ++i) {
      int f = guide_faces_[i];
      std::vector<int> path;
      while(tree.parent_cross_[f] >= 0) {
        const int up = tree.parent_cross_[f] ^ 1;
        path.push_back(up);
        f = m_.face[up];
        if(mark[f] != -1) break;
      }
      if(mark[f] == -1 || path.empty()) continue;   // reached an unconstrained root
      std::map<int, double> cols;
      for(int h : path) cols[sys.col_of_edge_[h >> 1]] += (h & 1) ? -1. : 1.;
      std::vector<std::pair<Eigen::Index, double>> c;
      for(const auto& ce : cols) if(ce.second != 0) c.push_back(std::make_pair(Eigen::Index(ce.first), ce.second));
      guide_paths_.push_back(path);
      guide_partner_.push_back(std::make_pair(int(i), mark[f]));
      guide_columns_.push_back(c);
    }
    // Paths of guides in different subtrees may share the edges above their common ancestor,
    // so C W C^T is a small dense matrix.
    const Eigen::Index k = Eigen::Index(guide_paths_.size());
    Eigen::MatrixXd S = Eigen::MatrixXd::Identity(k, k) / guide_weight_;
    Eigen::MatrixXd U(sys.rows_, k);
    guide_WCt_.resize(sys.W_.size(), k);
    std::vector<Eigen::Triplet<double>> t;
    for(Eigen::Index i = 0; i < k; ++i)
      for(const auto& ce : guide_columns_[std::size_t(i)]) t.emplace_back(ce.first, i, sys.W_[ce.first] * ce.second);
    guide_WCt_.setFromTriplets(t.begin(), t.end());
    for(Eigen::Index i = 0; i < k; ++i) {
      const Eigen::VectorXd wc = guide_WCt_.col(i);
      for(Eigen::Index j = 0; j < k; ++j)
        for(const auto& ce : guide_columns_[std::size_t(j)]) S(j, i) += ce.second * wc[ce.first];
      U.col(i) = sys.A_ * wc;
    }
    guide_S_.compute(S);
    guide_Z_.resize(sys.rows_, k);
    for(Eigen::Index i = 0; i < k; ++i) guide_Z_.col(i) = chol_.solve(U.col(i));
    guide_G_.compute(S - U.transpose() * guide_Z_);
  }


  // The x of the KKT system M x + A^T y = f, A x = g with M = W^-1 + lambda C^T C,
  // f = lambda C^T cbar, g = -b: x = M^-1 (f - A^T y), (A M^-1 A^T) y = A M^-1 f - g. One step of
  // iterative refinement recovers the digits that the Woodbury correction loses at large
  // weights. Returns the guide energy lambda sum_i (c_i^T x - cbar_i)^2.
  double solve(const Connection_system& sys, const Solver& chol_, const Eigen::VectorXd& b,
               const Eigen::VectorXd& cbar, Eigen::VectorXd& xc) const
  {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(sys.W_.size());
    for(std::size_t i = 0; i < guide_paths_.size(); ++i)
      for(const auto& ce : guide_columns_[i]) f[ce.first] += guide_weight_ * cbar[Eigen::Index(i)] * ce.second;
    Eigen::VectorXd y;
    kkt_solve(sys, chol_, f, -b, xc, y);
    const Eigen::VectorXd r1 = f - apply_M(sys, xc) - sys.A_.transpose() * y;
    const Eigen::VectorXd r2 = -b - sys.A_ * xc;
    Eigen::VectorXd dx, dy;
    kkt_solve(sys, chol_, r1, r2, dx, dy);
    xc += dx;
    double misfit = 0;
    for(std::size_t i = 0; i < guide_paths_.size(); ++i) {
      double cx = 0;
      for(const auto& ce : guide_columns_[i]) cx += ce.second * xc[ce.first];
      misfit += guide_weight_ * (cx - cbar[Eigen::Index(i)]) * (cx - cbar[Eigen::Index(i)]);
    }
    return misfit;
  }

  // Smallest rotation (mod 2pi/N) asked by each guide path.
  template <typename TM>
  Eigen::VectorXd rhs(const Mesh_arrays<TM>& m_, const std::vector<double>& guide_angles_,
                      const std::vector<double>& constraint_angles_, int N_) const
  {
    Eigen::VectorXd c(Eigen::Index(guide_paths_.size()));
    const double period = 2 * CGAL_PI / N_;
    for(std::size_t i = 0; i < guide_paths_.size(); ++i) {
      const double gm = guide_angles_[guide_partner_[i].first];
      const int p = guide_partner_[i].second;
      const double gn = p >= 0 ? guide_angles_[p] : constraint_angles_[-p - 2];
      c[Eigen::Index(i)] = std::remainder(gn - gm - transport_along(m_, guide_paths_[i]), period);
    }
    return c;
  }

private:
  void kkt_solve(const Connection_system& sys, const Solver& chol_, const Eigen::VectorXd& f, const Eigen::VectorXd& g,
                 Eigen::VectorXd& x, Eigen::VectorXd& y) const
  {
    const Eigen::VectorXd r = sys.A_ * apply_M_inverse(sys, f) - g;
    y = chol_.solve(r);
    y += guide_Z_ * guide_G_.solve(guide_Z_.transpose() * r);
    x = apply_M_inverse(sys, f - sys.A_.transpose() * y);
  }

  // M v = W^-1 v + lambda C^T C v
  Eigen::VectorXd apply_M(const Connection_system& sys, const Eigen::VectorXd& v) const
  {
    Eigen::VectorXd r = v.cwiseQuotient(sys.W_);
    for(const auto& cols : guide_columns_) {
      double cv = 0;
      for(const auto& ce : cols) cv += ce.second * v[ce.first];
      for(const auto& ce : cols) r[ce.first] += guide_weight_ * ce.second * cv;
    }
    return r;
  }

  // M^-1 v with M = W^-1 + lambda C^T C, by Woodbury: W v - W C^T S^-1 C W v.
  Eigen::VectorXd apply_M_inverse(const Connection_system& sys, const Eigen::VectorXd& v) const
  {
    Eigen::VectorXd r = sys.W_.cwiseProduct(v);
    if(guide_columns_.empty()) return r;
    const Eigen::VectorXd cwv = guide_WCt_.transpose() * v;
    return r - guide_WCt_ * guide_S_.solve(cwv);
  }


private:
  double guide_weight_ = 1;
  std::vector<std::vector<int>> guide_paths_;
  std::vector<std::pair<int, int>> guide_partner_;
  std::vector<std::vector<std::pair<Eigen::Index, double>>> guide_columns_;
  Eigen::SparseMatrix<double> guide_WCt_;          // W C^T
  Eigen::LDLT<Eigen::MatrixXd> guide_S_;           // S = I / lambda + C W C^T
  Eigen::MatrixXd guide_Z_;                        // L^-1 A W C^T
  Eigen::PartialPivLU<Eigen::MatrixXd> guide_G_;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_GUIDE_SOLVER_H
