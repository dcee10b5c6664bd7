// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LATTICE_MINIMUM_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LATTICE_MINIMUM_H

// Minimum of a positive definite quadratic form over the integer lattice:
//   min over s in Z^k of q(s) = (s - c)^T G (s - c),
// the closest-vector problem in the metric G. Used to choose the smoothest generator turning
// numbers of a trivial connection (the energy is a quadratic form in them).

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Lattice_minimum
{
  Eigen::VectorXd s;      // the minimiser found (integer entries)
  double value = 0;       // q(s)
  bool exact = false;     // true: the global minimum (enumeration completed)
  bool positive_definite = true;
};

inline double quadratic_value(const Eigen::MatrixXd& G, const Eigen::VectorXd& c, const Eigen::VectorXd& s)
{
  const Eigen::VectorXd d = s - c;
  return d.dot(G * d);
}

// Rounds c and improves it by single-coordinate steps of +-1 until none helps (a local minimum
// of q on the lattice, never worse than rounding).
inline Eigen::VectorXd descend_from_rounding(const Eigen::MatrixXd& G, const Eigen::VectorXd& c)
{
  Eigen::VectorXd s = c.array().round().matrix();
  Eigen::VectorXd g = 2 * G * (s - c);   // gradient of q at s
  for(bool improved = true; improved;) {
    improved = false;
    for(Eigen::Index i = 0; i < s.size(); ++i)
      for(double step : {1., -1.}) {
        const double delta = step * g[i] + G(i, i);   // q(s + step e_i) - q(s)
        if(delta < -1e-12 * (1 + std::abs(G(i, i)))) {
          s[i] += step;
          g += 2 * step * G.col(i);
          improved = true;
        }
      }
  }
  return s;
}

// Exact enumeration (Schnorr-Euchner on the Cholesky factor G = R^T R) for k <= exact_limit
// and at most max_nodes visited nodes; otherwise, or if the node budget runs out, the local
// minimum of descend_from_rounding() (exact = false).
inline Lattice_minimum lattice_minimum(const Eigen::MatrixXd& G, const Eigen::VectorXd& c,
                                       int exact_limit = 12, long max_nodes = 2000000)
{
  Lattice_minimum r;
  const int k = int(c.size());
  r.s = Eigen::VectorXd::Zero(k);
  if(k == 0) { r.exact = true; return r; }
  Eigen::LLT<Eigen::MatrixXd> llt(G);
  if(llt.info() != Eigen::Success) { r.positive_definite = false; return r; }
  r.s = descend_from_rounding(G, c);
  r.value = quadratic_value(G, c, r.s);
  if(k > exact_limit) return r;
  const Eigen::MatrixXd R = llt.matrixU();
  // q(s) = sum_i (R_ii (s_i - c_i) + sum_{j>i} R_ij (s_j - c_j))^2, enumerated from i = k-1 down
  const std::size_t kk = std::size_t(k);
  std::vector<double> center(kk), partial(kk + 1, 0.), s(kk), step(kk);
  double best = r.value * (1 + 1e-12) + 1e-300;
  long nodes = 0;
  bool complete = true;
  auto set_center = [&](int i) {
    double t = 0;
    for(int j = i + 1; j < k; ++j) t += R(i, j) * (s[std::size_t(j)] - c[j]);
    center[std::size_t(i)] = c[i] - t / R(i, i);
    s[std::size_t(i)] = std::round(center[std::size_t(i)]);
    step[std::size_t(i)] = 0;
  };
  int i = k - 1;
  set_center(i);
  while(true) {
    const double d = R(i, i) * (s[std::size_t(i)] - center[std::size_t(i)]);
    const double v = partial[std::size_t(i) + 1] + d * d;
    if(++nodes > max_nodes) { complete = false; break; }
    if(v < best) {
      if(i == 0) {
        best = v;
        for(int j = 0; j < k; ++j) r.s[j] = s[std::size_t(j)];
      } else {
        partial[std::size_t(i)] = v;
        --i;
        set_center(i);
        continue;
      }
    } else {
      if(i == k - 1) break;
      ++i;
    }
    // next candidate at level i, zig-zagging around the center (Schnorr-Euchner)
    const double base = std::round(center[std::size_t(i)]);
    const double up = center[std::size_t(i)] >= base ? 1 : -1;
    double& t = step[std::size_t(i)];
    t = t > 0 ? -t : -t + 1;   // 0, 1, -1, 2, -2, ...
    s[std::size_t(i)] = base + up * t;
    // a level whose offset grew past the bound in both directions is finished by the test above
  }
  r.value = quadratic_value(G, c, r.s);
  r.exact = complete;
  return r;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LATTICE_MINIMUM_H
