// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_SMALL_CONDITIONS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_SMALL_CONDITIONS_H

// The linear conditions on the small unknowns of integer_grid_map() (integer_grid_map.h): the
// closings around the vertices, the boundary's lines, the gauge, then the roundings. They are
// kept as an orthonormal basis Q y = delta of their span (Gram-Schmidt): a condition in that span
// is implied by the others and not added again.

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

class Small_conditions
{
public:
  explicit Small_conditions(int ns)
    : ns_(ns), unexplained_(Eigen::VectorXd::Ones(ns)), penalty_(Eigen::MatrixXd::Zero(ns, ns))
  {}

  // row . y = value; false if implied by the others. Until penalty() is called, row row^T is
  // also added to the penalty R^T R (Integer_grid_map/map_factor.h; the value must then be 0).
  bool add(Eigen::VectorXd row, double value)
  {
    if(recording_) penalty_.selfadjointView<Eigen::Lower>().rankUpdate(row);
    for(std::size_t j = 0; j < q_.size(); ++j) {
      const double c = q_[j].dot(row);
      row -= c * q_[j];
      value -= c * delta_[j];
    }
    const double n = row.norm();
    if(n < 1e-9) return false;
    q_.push_back(row / n);
    delta_.push_back(value / n);
    unexplained_ -= q_.back().cwiseAbs2();
    return true;
  }
  // undoes the last add() calls, down to `count` conditions
  void drop_to(std::size_t count)
  {
    for(; q_.size() > count; q_.pop_back(), delta_.pop_back()) unexplained_ += q_.back().cwiseAbs2();
  }
  std::size_t size() const { return q_.size(); }
  // e_k lies in the span of the conditions (1 - |its projection|^2 below 1e-12)
  bool implied(int k) const { return unexplained_[k] < 1e-12; }

  // R^T R of the conditions added so far, symmetric; later conditions are not recorded
  const Eigen::MatrixXd& penalty()
  {
    if(recording_) penalty_.triangularView<Eigen::StrictlyUpper>() = penalty_.transpose();
    recording_ = false;
    return penalty_;
  }

  // the KKT matrix [S Q^T; Q 0] of minimising y^T S y - 2 rs^T y subject to Q y = delta, and its
  // right-hand side [rs; delta]
  Eigen::MatrixXd kkt(const Eigen::MatrixXd& S) const
  {
    const Eigen::Index mq = Eigen::Index(q_.size());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(ns_ + mq, ns_ + mq);
    K.topLeftCorner(ns_, ns_) = S;
    for(Eigen::Index i = 0; i < mq; ++i) {
      K.block(ns_ + i, 0, 1, ns_) = q_[std::size_t(i)].transpose();
      K.block(0, ns_ + i, ns_, 1) = q_[std::size_t(i)];
    }
    return K;
  }
  Eigen::VectorXd kkt_rhs(const Eigen::VectorXd& rs) const
  {
    Eigen::VectorXd rhs(ns_ + Eigen::Index(q_.size()));
    rhs.head(ns_) = rs;
    for(std::size_t i = 0; i < q_.size(); ++i) rhs[ns_ + Eigen::Index(i)] = delta_[i];
    return rhs;
  }

private:
  Eigen::Index ns_;
  std::vector<Eigen::VectorXd> q_;
  std::vector<double> delta_;
  Eigen::VectorXd unexplained_;   // per small unknown k: 1 - |projection of e_k on the span|^2
  Eigen::MatrixXd penalty_;
  bool recording_ = true;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_SMALL_CONDITIONS_H
